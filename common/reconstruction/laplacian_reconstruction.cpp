#include "reconstruction/laplacian_reconstruction.h"

#include "mesh/intrinsic_delaunay.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/mesh_checks.h"

#include <Eigen/CholmodSupport>

#include <chrono>
#include <cmath>
#include <sstream>

namespace hht {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

bool reconstruct_positions(const Positions& positions, const Faces& faces, const MeanCurvature& curvature,
                           const Eigen::VectorXd& signal, const ReconstructionOptions& options,
                           Positions& result, ReconstructionReport& report, std::string& error,
                           const std::function<void(double)>& progress) {
  auto step = [&](double done) {
    if (progress) progress(done);
  };
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

  // The signal's L (cotangents do not scale).
  const Sparse c = cotangent_matrix(cotangent_laplacian(positions, faces, curvature.triangles), static_cast<int>(n));
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

  // Proven bound on the position error (scaled units), and the stop in those units.
  const double diagonal = bounding_box_diagonal(v);
  auto error_bound = [&](const Positions& residual) { return residual.norm() / lambda2; };
  const double max_error = options.max_error * diagonal;

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
    report.error_bound = error_bound(b - apply_a(x)) / diagonal;
  } else {
    const Sparse k = c + options.lambda * Sparse(area.asDiagonal());
    Eigen::CholmodDecomposition<Sparse> factor;
    factor.compute(k);
    if (factor.info() != Eigen::Success) {
      error = "the Cholesky factorisation of the preconditioner failed (degenerate mesh?)";
      return false;
    }
    report.factor_seconds = since(t0);
    step(0.3);
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
    int it = 0;
    double bound = error_bound(r);
    const double start = std::max(bound, max_error);
    while (bound > max_error && it < options.max_iterations) {
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
      bound = error_bound(r);
      step(0.3 + 0.7 * std::log(start / std::max(bound, max_error)) / std::log(start / max_error));
    }
    report.iterations = it;
    report.error_bound = bound / diagonal;
    report.solve_seconds = since(t0);
    if (bound > max_error) {
      error = "conjugate gradients stopped with a possible position error of " + std::to_string(bound / diagonal) +
              " of the diagonal after " + std::to_string(it) + " iterations";
      // The usual cause: needles, whose cotangent weights dwarf every other and leave the system
      // near singular. A user can remove them; say so.
      const Eigen::Index needles = (corner_cotangents(v, faces).array() > 1 / std::tan(kNeedleAngleDegrees * M_PI / 180)).rowwise().any().count();
      if (needles > 0) {
        std::ostringstream hint;
        hint << "; the mesh has " << needles << " degenerate faces (an angle under " << kNeedleAngleDegrees
             << " degrees: no area, as triangulated polygons often leave), where the cotangent Laplacian is undefined: "
                "remove them first (Filters > Cleaning and Repairing > Remove Zero Area Faces, Remove T-Vertices)";
        error += hint.str();
      }
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
