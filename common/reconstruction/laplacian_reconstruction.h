// Positions rebuilt from a modified curvature signal (the paper's eq. 9-11):
//   min ||L V~ - T||^2 + lambda^2 ||V~ - V||^2,   L = M^-1 C, the curvature signal's (mean_curvature.h),
// with T the target Laplacian. The paper's literal target is T_i = G~_i n_i; but L V has a
// tangential part on any irregular mesh, so that target moves vertices even when G~ == G.
// KeepTangential uses T_i = (L V)_i + (G~_i - G_i) n_i: only the normal component changes, and
// G~ == G gives V back exactly (docs/benchmarks.md measures both).
//
// Scale: the problem is solved with positions divided by the mean edge length, so lambda is
// relative to it and a scaled copy of a mesh gives the scaled result.
//
// Solver: the normal equations A x = b, A = C M^-2 C + lambda^2 I (a 2-ring pattern, slow to
// factor), by conjugate gradients started from V, preconditioned with K^-1 M^2 K^-1 where
// K = C + lambda M (1-ring, factored once by CHOLMOD): K M^-2 K ~ A up to O(lambda) terms.
#pragma once

#include <functional>

#include "mesh/mean_curvature.h"

#include <string>

namespace hht {

enum class ReconstructionTarget { NormalOnly, KeepTangential };

// A face with an angle under this is degenerate for the cotangent Laplacian (named in the
// message when the solve fails).
constexpr double kNeedleAngleDegrees = 0.01;

struct ReconstructionOptions {
  double lambda = 0.01;  // weight of the original positions, relative to the mean edge length
  ReconstructionTarget target = ReconstructionTarget::KeepTangential;
  // CG stops once no vertex can be further than this, relative to the bounding-box diagonal,
  // from the exact solution: A >= lambda^2 I, so ||x - x*||_2 <= ||b - A x||_2 / lambda^2.
  double max_error = 1e-5;
  int max_iterations = 500;
  bool direct = false;  // factor A itself (exact, slow at scale; for checking the iterative solve)
};

struct ReconstructionReport {
  int iterations = 0;
  double error_bound = 0;  // the bound above at the stop, relative to the bounding-box diagonal
  double factor_seconds = 0;
  double solve_seconds = 0;
};

// `curvature` is mean_curvature() of (positions, faces); `signal` is the modified G~ (one
// value per vertex). Fails with a message when the factorisation fails or CG does not reach
// max_error; `result` is then unspecified.
// progress(fraction done) follows the factorisation and the iterations.
bool reconstruct_positions(const Positions& positions, const Faces& faces, const MeanCurvature& curvature,
                           const Eigen::VectorXd& signal, const ReconstructionOptions& options,
                           Positions& result, ReconstructionReport& report, std::string& error,
                           const std::function<void(double)>& progress = {});

}  // namespace hht
