#include "reconstruction/laplacian_reconstruction.h"

#include "mesh/cotangent_laplacian.h"
#include "evaluation/gaussian_noise.h"

#include <Eigen/CholmodSupport>

#include <chrono>

namespace hht {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

bool reconstruct_positions(const Positions& positions, const Faces& faces, const MeanCurvature& curvature,
                           const Eigen::VectorXd& signal, const ReconstructionOptions& options,
                           Positions& result, ReconstructionReport& report, std::string& error) {
  const Eigen::Index n = positions.rows();
  if (signal.size() != n || curvature.signal.size() != n) {
    error = "the signal has " + std::to_string(signal.size()) + " values for " + std::to_string(n) + " vertices";
    return false;
  }
  if (!signal.allFinite()) {
    error = "the filtered signal has NaN or infinite values";
    return false;
  }
  const double scale = mean_edge_length(positions, faces);
  if (!(scale > 0)) {
    error = "the mesh has no edge of positive length";
    return false;
  }
  const Eigen::RowVector3d centre = positions.colwise().mean();
  const Positions v = (positions.rowwise() - centre) / scale;  // unit mean edge length

  // Target Laplacian, in the scaled units (L V and G scale like 1/length).
  Positions target(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::RowVector3d normal = curvature.normals.row(i);
    target.row(i) = options.target == ReconstructionTarget::KeepTangential
                        ? Eigen::RowVector3d(curvature.laplacian.row(i) + (signal[i] - curvature.signal[i]) * normal)
                        : Eigen::RowVector3d(signal[i] * normal);
  }
  target *= scale;

  const Sparse c = cotangent_matrix(faces, corner_cotangents(v, faces), static_cast<int>(n));
  // Areas in scaled units, floored so that vertices of no or degenerate faces stay solvable.
  Eigen::VectorXd area = curvature.areas / (scale * scale);
  const double floor = 1e-8 * std::max(area.mean(), 1e-300);
  for (Eigen::Index i = 0; i < n; ++i) area[i] = std::max(area[i], floor);
  const Eigen::VectorXd inv_area2 = area.cwiseInverse().cwiseAbs2();
  const double lambda2 = options.lambda * options.lambda;

  // b = L^T T + lambda^2 V = C M^-1 T + lambda^2 V
  const Positions b = c * (area.cwiseInverse().asDiagonal() * target) + lambda2 * v;
  auto apply_a = [&](const Positions& x) -> Positions {
    return c * (inv_area2.asDiagonal() * (c * x)) + lambda2 * x;
  };

  Positions x = v;
  auto t0 = Clock::now();
  if (options.direct) {
    const Sparse a = Sparse(c * inv_area2.asDiagonal() * c) + lambda2 * Sparse(Eigen::VectorXd::Ones(n).asDiagonal());
    Eigen::CholmodDecomposition<Sparse> solver;
    solver.compute(a);
    if (solver.info() != Eigen::Success) {
      error = "the Cholesky factorisation of the normal equations failed (degenerate mesh?)";
      return false;
    }
    report.factor_seconds = since(t0);
    t0 = Clock::now();
    x = solver.solve(b);
    report.solve_seconds = since(t0);
    report.iterations = 0;
    report.relative_residual = (b - apply_a(x)).norm() / std::max(b.norm(), 1e-300);
  } else {
    const Sparse k = c + options.lambda * Sparse(area.asDiagonal());
    Eigen::CholmodDecomposition<Sparse> factor;
    factor.compute(k);
    if (factor.info() != Eigen::Success) {
      error = "the Cholesky factorisation of the preconditioner failed (degenerate mesh?)";
      return false;
    }
    report.factor_seconds = since(t0);
    t0 = Clock::now();
    auto precondition = [&](const Positions& r) -> Positions {
      const Positions y = factor.solve(r);
      return factor.solve(Positions(area.cwiseAbs2().asDiagonal() * y));
    };
    // Three independent conjugate-gradient runs, one per coordinate, advanced together.
    Positions r = b - apply_a(x);
    Positions z = precondition(r);
    Positions p = z;
    Eigen::RowVector3d rz = (r.array() * z.array()).colwise().sum();
    const Eigen::RowVector3d b_norm = b.colwise().norm().cwiseMax(1e-300);
    int it = 0;
    double worst = (r.colwise().norm().array() / b_norm.array()).maxCoeff();
    while (worst > options.tolerance && it < options.max_iterations) {
      const Positions ap = apply_a(p);
      const Eigen::RowVector3d pap = (p.array() * ap.array()).colwise().sum();
      Eigen::RowVector3d alpha;
      for (int j = 0; j < 3; ++j) alpha[j] = pap[j] > 0 ? rz[j] / pap[j] : 0.0;
      x += p * alpha.asDiagonal();
      r -= ap * alpha.asDiagonal();
      z = precondition(r);
      const Eigen::RowVector3d rz_next = (r.array() * z.array()).colwise().sum();
      Eigen::RowVector3d beta;
      for (int j = 0; j < 3; ++j) beta[j] = rz[j] > 0 ? rz_next[j] / rz[j] : 0.0;
      p = z + p * beta.asDiagonal();
      rz = rz_next;
      ++it;
      worst = (r.colwise().norm().array() / b_norm.array()).maxCoeff();
    }
    report.iterations = it;
    report.relative_residual = worst;
    report.solve_seconds = since(t0);
    if (worst > options.tolerance) {
      error = "conjugate gradients stopped at relative residual " + std::to_string(worst) + " after " +
              std::to_string(it) + " iterations";
      return false;
    }
  }
  result = (x * scale).rowwise() + centre;
  if (!result.allFinite()) {
    error = "the solve produced non-finite positions";
    return false;
  }
  return true;
}

}  // namespace hht
