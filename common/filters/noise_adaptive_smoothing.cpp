#include "filters/noise_adaptive_smoothing.h"

#include "evaluation/gaussian_noise.h"
#include "mesh/mesh_checks.h"
#include "mesh/uniform_laplacian.h"
#include "mesh/vertex_normals.h"


#include <algorithm>
#include <cmath>

namespace hht {

namespace {

Positions face_normals(const Positions& p, const Faces& faces) {
  Positions out(faces.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::RowVector3d a = p.row(faces(f, 0));
    const Eigen::RowVector3d c = (p.row(faces(f, 1)) - a).cross(p.row(faces(f, 2)) - a);
    const double length = c.norm();
    out.row(f) = length > 0 ? Eigen::RowVector3d(c / length) : Eigen::RowVector3d::Zero();
  }
  return out;
}

// Faces pointing away from the surface around them (their normal against the mean of their
// vertices' normals) are folds, left where a sliver's vertices slid past each other: their
// vertices are moved to their one-ring centroids until none is left (a few passes at most).
int unfold(Positions& x, const Faces& faces, const std::vector<std::vector<int>>& neighbours) {
  std::vector<unsigned char> moved(x.rows(), 0);
  for (int pass = 0; pass < 10; ++pass) {
    const Positions vertex_normals = area_weighted_vertex_normals(x, faces);
    const Positions normals = face_normals(x, faces);
    std::vector<int> folded;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d around =
          vertex_normals.row(faces(f, 0)) + vertex_normals.row(faces(f, 1)) + vertex_normals.row(faces(f, 2));
      if (normals.row(f).dot(around) < 0)
        for (int k = 0; k < 3; ++k) folded.push_back(faces(f, k));
    }
    if (folded.empty()) break;
    for (int i : folded) {
      if (neighbours[i].empty()) continue;
      Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
      for (int j : neighbours[i]) centroid += x.row(j);
      x.row(i) = centroid / static_cast<double>(neighbours[i].size());
      moved[i] = 1;
    }
  }
  return static_cast<int>(std::count(moved.begin(), moved.end(), 1));
}

}  // namespace

bool noise_adaptive_smooth(const Positions& positions, const Faces& faces, const NoiseAdaptiveSmoothingOptions& options,
                           Positions& result, NoiseAdaptiveSmoothingReport& report, std::string& error,
                           const std::function<void(int, const char*)>& progress) {
  report = NoiseAdaptiveSmoothingReport{};
  StageClock clock(report.stages);
  auto step = [&](int percent, const char* what) {
    if (progress) progress(percent, what);
  };
  if (!check_triangle_mesh(positions, faces, error)) return false;
  if (!(options.strength > 0) || !std::isfinite(options.strength)) {
    error = "the strength must be a positive number";
    return false;
  }
  const int n = static_cast<int>(positions.rows());
  const double edge = mean_edge_length(positions, faces);
  if (!(edge > 0)) {
    error = "the mesh has no edge of positive length";
    return false;
  }

  double sigma = options.noise;
  if (!(sigma > 0)) {
    step(2, "Hamiltonian cycle");
    HamiltonianCycle cycle;
    if (!hamiltonian_cycle(faces, n, options.cycle, cycle, error)) return false;
    clock.done("cycle");
    step(15, "Noise estimate (finest IMF)");
    if (!estimate_noise(positions, faces, cycle, options.emd, report.noise, error)) return false;
    clock.done("noise estimate");
    sigma = report.noise.relative();
  }
  report.sigma_used = sigma;
  // A noise-free mesh gives sigma ~ 0: mu is then capped where the filter is the identity to
  // well under a thousandth of an edge.
  report.mu = options.mu > 0 ? options.mu : std::min(kMuScale / std::sqrt(options.strength * std::max(sigma, 1e-12)), 1e3);

  step(30, "Least-squares smoothing");
  const Eigen::RowVector3d centre = positions.colwise().mean();
  const Positions v = (positions.rowwise() - centre) / edge;  // unit mean edge
  const auto neighbours = vertex_neighbours(faces, n);
  const Eigen::SparseMatrix<double> l = uniform_laplacian(neighbours);
  const Eigen::SparseMatrix<double> l2 = l * l;
  const Eigen::SparseMatrix<double> l2t = l2.transpose();
  const double mu4 = std::pow(report.mu, 4);
  // (L^2)^T L^2 x + mu^4 x = mu^4 v by conjugate gradients, Jacobi-preconditioned, from x = v:
  // two sparse products per iteration and no factor (a factor of the 4-ring matrix fills in
  // badly on large meshes). The condition number is at most 1 + 16 / mu^4.
  const Eigen::VectorXd inverse_diagonal =
      (Eigen::VectorXd(l2.cwiseAbs2().transpose() * Eigen::VectorXd::Ones(n)).array() + mu4).inverse();
  auto apply_a = [&](const Positions& y) -> Positions { return l2t * Positions(l2 * y) + mu4 * y; };
  const Positions b = mu4 * v;
  Positions x = v;
  Positions r = b - apply_a(x);
  Positions z = inverse_diagonal.asDiagonal() * r;
  Positions p = z;
  Eigen::RowVector3d rz = (r.array() * z.array()).colwise().sum();
  const double b_norm = std::max(b.norm(), 1e-300);
  const double start_residual = std::max(r.norm() / b_norm, kSmoothingTolerance);
  double residual = r.norm() / b_norm;
  int iterations = 0;
  for (; residual > kSmoothingTolerance && iterations < kSmoothingMaxIterations; ++iterations) {
    const Positions ap = apply_a(p);
    const Eigen::RowVector3d pap = (p.array() * ap.array()).colwise().sum();
    Eigen::RowVector3d alpha, beta;
    for (int k = 0; k < 3; ++k) alpha[k] = pap[k] > 0 ? rz[k] / pap[k] : 0.0;
    x += p * alpha.asDiagonal();
    r -= ap * alpha.asDiagonal();
    z = inverse_diagonal.asDiagonal() * r;
    const Eigen::RowVector3d rz_next = (r.array() * z.array()).colwise().sum();
    for (int k = 0; k < 3; ++k) beta[k] = rz[k] > 0 ? rz_next[k] / rz[k] : 0.0;
    p = z + p * beta.asDiagonal();
    rz = rz_next;
    residual = r.norm() / b_norm;
    if (iterations % 16 == 0)
      step(30 + static_cast<int>(60 * std::log(start_residual / std::max(residual, kSmoothingTolerance)) /
                                 std::log(start_residual / kSmoothingTolerance)),
           "Least-squares smoothing (conjugate gradients)");
  }
  report.iterations = iterations;
  report.relative_residual = residual;
  if (residual > kSmoothingTolerance) {
    error = "conjugate gradients stopped at relative residual " + std::to_string(residual) + " after " +
            std::to_string(iterations) + " iterations";
    return false;
  }
  clock.done("solve");

  // Tangential moves capped, except around faces the cap would leave tilted (more than 60
  // degrees from the uncapped result's face): there the slide untangles noise-flipped triangles.
  const Positions uncapped = x;
  const double cap = kTangentialCap * sigma * sigma * options.strength;
  const Positions normals = area_weighted_vertex_normals(x, faces);
  for (int i = 0; i < n; ++i) {
    const Eigen::RowVector3d move = x.row(i) - v.row(i);
    const Eigen::RowVector3d normal = normals.row(i);
    const Eigen::RowVector3d tangential = move - move.dot(normal) * normal;
    const double length = tangential.norm();
    if (length > cap) x.row(i) -= tangential * (1 - cap / length);
  }
  const Positions smooth_normals = face_normals(uncapped, faces);
  for (int pass = 0; pass < 3; ++pass) {
    const Positions capped_normals = face_normals(x, faces);
    bool changed = false;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      if (capped_normals.row(f).dot(smooth_normals.row(f)) >= 0.5) continue;
      for (int k = 0; k < 3; ++k) {
        const int i = faces(f, k);
        changed |= x.row(i) != uncapped.row(i);
        x.row(i) = uncapped.row(i);
      }
    }
    if (!changed) break;
  }
  report.unfolded_vertices = unfold(x, faces, neighbours);
  result = (x * edge).rowwise() + centre;
  if (!result.allFinite()) {
    error = "the solve produced non-finite positions";
    return false;
  }
  const Eigen::VectorXd moves = (result - positions).rowwise().norm();
  report.max_displacement = moves.maxCoeff();
  report.rms_displacement = std::sqrt(moves.squaredNorm() / n);
  step(100, "Done");
  return true;
}

}  // namespace hht
