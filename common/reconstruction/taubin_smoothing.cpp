#include "reconstruction/taubin_smoothing.h"

#include "mesh/uniform_laplacian.h"

namespace hht {

Positions taubin_smoothing(const VertexAdjacency& adjacency, const Positions& positions, int steps, double lambda,
                           double mu) {
  // L p = D^-1 K p, applied from the adjacency (no matrix: millions of vertices).
  Positions p = positions, kp;
  auto move = [&](double weight) {
    apply_graph_laplacian(adjacency, p, kp);
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      if (const int valence = adjacency.valence(static_cast<int>(i))) p.row(i) -= weight / valence * kp.row(i);
  };
  for (int s = 0; s < steps; ++s) {
    move(lambda);
    move(mu);
  }
  return p;
}

}  // namespace hht
