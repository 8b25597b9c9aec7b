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

double squared_laplacian_row_gain(const VertexAdjacency& adjacency, int i, std::vector<double>& scratch,
                                  std::vector<int>& touched) {
  // (I - W)^2 = I - 2 W + W^2, row i.
  auto add = [&](int l, double c) {
    if (scratch[l] == 0) touched.push_back(l);
    scratch[l] += c;
  };
  const double ki = adjacency.valence(i);
  add(i, 1);
  for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) {
    add(*j, -2 / ki);
    const double kj = adjacency.valence(*j);
    for (const int* m = adjacency.begin(*j); m != adjacency.end(*j); ++m) add(*m, 1 / (ki * kj));
  }
  double gain = 0;
  for (const int l : touched) {
    gain += scratch[l] * scratch[l];
    scratch[l] = 0;
  }
  touched.clear();
  return gain;
}

}  // namespace hht
