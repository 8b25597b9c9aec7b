#include "reconstruction/taubin_smoothing.h"

#include "mesh/uniform_laplacian.h"

namespace hht {

Positions taubin_smoothing(const VertexAdjacency& adjacency, const Positions& positions, int steps, double lambda,
                           double mu) {
  const Eigen::SparseMatrix<double> l = uniform_laplacian(adjacency);
  Positions p = positions;
  for (int s = 0; s < steps; ++s) {
    p -= lambda * Positions(l * p);
    p -= mu * Positions(l * p);
  }
  return p;
}

}  // namespace hht
