#include "mesh/uniform_laplacian.h"

#include "util/parallel_for.h"

namespace hht {

Eigen::SparseMatrix<double> uniform_laplacian(const VertexAdjacency& adjacency) {
  const int n = adjacency.vertices();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(adjacency.neighbours.size() + n);
  for (int i = 0; i < n; ++i) {
    if (adjacency.valence(i) == 0) continue;
    entries.emplace_back(i, i, 1.0);
    const double w = -1.0 / static_cast<double>(adjacency.valence(i));
    for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) entries.emplace_back(i, *j, w);
  }
  Eigen::SparseMatrix<double> l(n, n);
  l.setFromTriplets(entries.begin(), entries.end());
  return l;
}

void apply_graph_laplacian(const VertexAdjacency& adjacency, const Positions& y, Positions& out) {
  out.resize(y.rows(), 3);
  parallel_for(0, adjacency.vertices(), [&](int first, int last) {
    for (int i = first; i < last; ++i) {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) sum += y.row(*j);
      out.row(i) = adjacency.valence(i) * y.row(i) - sum;
    }
  });
}

}  // namespace hht
