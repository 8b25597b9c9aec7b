// The least-squares low-pass of the adaptive smoothing: X minimising
//   ||L^2 X||^2 + g mu^2 ||L X||^2 + mu^4 ||X - V||^2,
// L the uniform Laplacian, i.e. ((L^2)^T L^2 + g mu^2 L^T L + mu^4 I) X = mu^4 V. Per eigenmode k
// of L it keeps mu^4 / (mu^4 + g mu^2 k^2 + k^4): with g = 0 a second-order Butterworth response,
// with g = 1 a gentler roll-off that mixes in the first-order filter (the adaptive smoothing's,
// docs/quality.md item 9). Solved by preconditioned conjugate gradients, matrix-free: L = D^-1 K
// with K the graph Laplacian, so each product is four sweeps over the adjacency and nothing is
// factored or stored beyond a few vectors (a factor of the 4-ring matrix fills in badly on large
// meshes). Plain conjugate gradients need O(1 / mu^2) products, since the system's condition
// number is about 16 / mu^4. The preconditioner uses that A is nearly a polynomial in the
// normalised Laplacian S = D^-1/2 K D^-1/2 (eigenvalues in [0, 2]): with every valence d,
// D^-1/2 A D^-1/2 = p(S) / d, p(s) = s^4 + g mu^2 s^2 + mu^4, and otherwise it lies within
// d_max / d_min of that. So M^-1 = D^-1/2 d q(S) D^-1/2, q a polynomial with q p close to 1 on
// [0, 2] (degree 7 at mu 0.2), applied in one sweep per degree; the iterations no longer grow
// with 1 / mu^2 (docs/benchmarks.md: 357 to 13 at mu 0.2 on 416k vertices).
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
// further off than that 2-norm. Starts from V. progress(fraction done) is called every
// iteration. False if the iteration cap (500) is reached first.
bool biharmonic_low_pass(const VertexAdjacency& adjacency, const Positions& v, double mu, double first_order,
                         double max_error, Positions& x, BiharmonicLowPassReport& report,
                         const std::function<void(double)>& progress = {});

}  // namespace hht
