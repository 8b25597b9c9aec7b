// The least-squares low-pass of the adaptive smoothing: X minimising
//   ||L^2 X||^2 + g mu^2 ||L X||^2 + mu^4 ||X - V||^2,
// L the uniform Laplacian, i.e. ((L^2)^T L^2 + g mu^2 L^T L + mu^4 I) X = mu^4 V. Per eigenmode k
// of L it keeps mu^4 / (mu^4 + g mu^2 k^2 + k^4): with g = 0 a second-order Butterworth response,
// with g = 1 a gentler roll-off that mixes in the first-order filter (the adaptive smoothing's,
// docs/quality.md item 9). Solved by conjugate gradients
// (a Jacobi preconditioner saved no iteration on cow, bull, femur, man or armadillo: the
// diagonal varies little), matrix-free: L = D^-1 K with K the graph Laplacian, so each product is
// four sweeps over the adjacency and nothing is factored or stored beyond a few vectors (a factor
// of the 4-ring matrix fills in badly on large meshes).
#pragma once

#include "mesh/vertex_adjacency.h"

#include <functional>

namespace hht {

struct BiharmonicLowPassReport {
  int iterations = 0;
  double error_bound = 0;  // proven bound on the largest position error at the stop (below)
};

// first_order: g above (>= 0). Stops once ||X_k - X||_2 <= max_error, X the exact solution: since
// the system matrix is at least mu^4 I, ||X_k - X||_2 <= ||residual||_2 / mu^4, and no vertex is
// further off than that 2-norm. Starts from V. progress(fraction done) is called every few
// iterations. False if the iteration cap is reached first.
bool biharmonic_low_pass(const VertexAdjacency& adjacency, const Positions& v, double mu, double first_order,
                         double max_error, Positions& x, BiharmonicLowPassReport& report,
                         const std::function<void(double)>& progress = {});

}  // namespace hht
