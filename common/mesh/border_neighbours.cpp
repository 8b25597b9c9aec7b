#include "mesh/border_neighbours.h"

#include <algorithm>
#include <utility>

namespace hht {

BorderNeighbours border_neighbours(const Faces& faces, const VertexAdjacency& adjacency) {
  // Only the edges between two border vertices can be border edges: few on most meshes, so this
  // costs little memory beside the smoothing's on a large one.
  const int vertex_count = adjacency.vertices();
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      if (a != b && adjacency.boundary[a] && adjacency.boundary[b]) edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  BorderNeighbours out(vertex_count, {-1, -1});
  std::vector<int> count(vertex_count, 0);
  auto add = [&](int i, int j) {
    if (count[i] < 2) out[i][count[i]] = j;
    ++count[i];
  };
  for (size_t e = 0; e < edges.size();) {
    size_t same = e;
    while (same < edges.size() && edges[same] == edges[e]) ++same;
    if (same - e == 1) {
      add(edges[e].first, edges[e].second);
      add(edges[e].second, edges[e].first);
    }
    e = same;
  }
  for (int i = 0; i < vertex_count; ++i)
    if (count[i] != 2) out[i] = {-1, -1};
  return out;
}

BorderNeighbours border_neighbours_among(const BorderNeighbours& border, const std::vector<int>& kept) {
  std::vector<int> new_index(border.size(), -1);
  for (size_t k = 0; k < kept.size(); ++k) new_index[kept[k]] = static_cast<int>(k);
  BorderNeighbours out(kept.size(), {-1, -1});
  for (size_t k = 0; k < kept.size(); ++k) {
    const auto [a, b] = border[kept[k]];
    if (a >= 0 && new_index[a] >= 0 && new_index[b] >= 0) out[k] = {new_index[a], new_index[b]};
  }
  return out;
}

int clamp_moves_across_borders(const Positions& from, const Positions& unit_normals, const BorderNeighbours& border,
                               Positions& x, double limit) {
  int clamped = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const auto [a, b] = border[i];
    if (a < 0) continue;
    const Eigen::RowVector3d normal = unit_normals.row(i);
    Eigen::RowVector3d along = from.row(a) - from.row(b);
    along -= along.dot(normal) * normal;
    const double length = along.norm();
    if (!(length > 0)) continue;
    const Eigen::RowVector3d across = normal.cross(along / length);
    if (!(across.squaredNorm() > 0.5)) continue;  // no normal there
    const double move = (x.row(i) - from.row(i)).dot(across);
    x.row(i) -= (move - std::clamp(move, -limit, limit)) * across;
    ++clamped;
  }
  return clamped;
}

}  // namespace hht
