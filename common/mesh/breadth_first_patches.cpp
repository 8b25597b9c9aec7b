#include "mesh/breadth_first_patches.h"

#include <algorithm>
#include <cstdint>

namespace hht {

namespace {

std::vector<int> index_of(int vertex_count, const std::vector<int>& kept) {
  std::vector<int> index(vertex_count, -1);
  for (size_t i = 0; i < kept.size(); ++i) index[kept[i]] = static_cast<int>(i);
  return index;
}

}  // namespace

std::vector<int> breadth_first_patches(const VertexAdjacency& adjacency, int budget, int patches) {
  const int n = adjacency.vertices();
  std::vector<unsigned char> taken(n, 0);
  std::vector<int> kept;
  if (n == 0 || patches < 1) return kept;
  const size_t per_patch = static_cast<size_t>(std::max(1, budget / patches));
  for (int p = 0; p < patches; ++p) {
    const int seed = static_cast<int>((static_cast<int64_t>(n) * p) / patches);
    if (taken[seed]) continue;
    const size_t start = kept.size();
    taken[seed] = 1;
    kept.push_back(seed);
    for (size_t head = start; head < kept.size() && kept.size() - start < per_patch; ++head)
      for (const int* j = adjacency.begin(kept[head]); j != adjacency.end(kept[head]); ++j)
        if (!taken[*j] && kept.size() - start < per_patch) {
          taken[*j] = 1;
          kept.push_back(*j);
        }
  }
  return kept;
}

VertexAdjacency adjacency_among(const VertexAdjacency& adjacency, const std::vector<int>& kept) {
  const std::vector<int> index = index_of(adjacency.vertices(), kept);
  VertexAdjacency out;
  out.offsets.assign(kept.size() + 1, 0);
  out.boundary.assign(kept.size(), 0);
  for (size_t i = 0; i < kept.size(); ++i) {
    for (const int* j = adjacency.begin(kept[i]); j != adjacency.end(kept[i]); ++j)
      if (index[*j] >= 0) out.neighbours.push_back(index[*j]);
    std::sort(out.neighbours.begin() + out.offsets[i], out.neighbours.end());
    out.offsets[i + 1] = static_cast<int>(out.neighbours.size());
  }
  return out;
}

Faces faces_among(const Faces& faces, int vertex_count, const std::vector<int>& kept) {
  const std::vector<int> index = index_of(vertex_count, kept);
  std::vector<Eigen::Index> inside;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    if (index[faces(f, 0)] >= 0 && index[faces(f, 1)] >= 0 && index[faces(f, 2)] >= 0) inside.push_back(f);
  Faces out(static_cast<Eigen::Index>(inside.size()), 3);
  for (size_t r = 0; r < inside.size(); ++r)
    for (int k = 0; k < 3; ++k) out(static_cast<Eigen::Index>(r), k) = index[faces(inside[r], k)];
  return out;
}

Positions rows_at(const Positions& all, const std::vector<int>& kept) {
  Positions out(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t i = 0; i < kept.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = all.row(kept[i]);
  return out;
}

}  // namespace hht
