#include "mesh/uniform_laplacian.h"

#include <algorithm>

namespace hht {

std::vector<std::vector<int>> vertex_neighbours(const Faces& faces, int vertex_count) {
  std::vector<std::vector<int>> out(vertex_count);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      out[a].push_back(b);
      out[b].push_back(a);
    }
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

Eigen::SparseMatrix<double> uniform_laplacian(const std::vector<std::vector<int>>& neighbours) {
  const int n = static_cast<int>(neighbours.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    if (neighbours[i].empty()) continue;
    entries.emplace_back(i, i, 1.0);
    const double w = -1.0 / static_cast<double>(neighbours[i].size());
    for (int j : neighbours[i]) entries.emplace_back(i, j, w);
  }
  Eigen::SparseMatrix<double> l(n, n);
  l.setFromTriplets(entries.begin(), entries.end());
  return l;
}

}  // namespace hht
