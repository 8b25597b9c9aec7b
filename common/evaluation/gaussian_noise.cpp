#include "evaluation/gaussian_noise.h"

#include "mesh/vertex_normals.h"

#include <cmath>
#include <random>

namespace hht {

double mean_edge_length(const Positions& p, const Faces& f) {
  double sum = 0;
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) sum += (p.row(f(i, k)) - p.row(f(i, (k + 1) % 3))).norm();
  return f.rows() > 0 ? sum / (3.0 * f.rows()) : 0.0;
}

Positions add_gaussian_noise(const Positions& positions, const Faces& faces, double percent_of_mean_edge,
                             NoiseDirection direction, unsigned seed, double moved_share) {
  const double sigma = percent_of_mean_edge / 100.0 * mean_edge_length(positions, faces);
  const Positions normals = area_weighted_vertex_normals(positions, faces);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  // Which vertices move: a stream of its own, so that each moves as the full noise would move it.
  std::mt19937_64 picker(seed ^ 0x9e3779b97f4a7c15ULL);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Positions out = positions;
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    Eigen::RowVector3d dir = normals.row(i);
    if (dir.squaredNorm() == 0) continue;  // no face, no normal: left in place
    Eigen::RowVector3d move;
    if (direction == NoiseDirection::Isotropic) {
      move = sigma * Eigen::RowVector3d(gauss(rng), gauss(rng), gauss(rng));
    } else {
      if (direction == NoiseDirection::Random) {
        do {
          dir = Eigen::RowVector3d(gauss(rng), gauss(rng), gauss(rng));
        } while (dir.squaredNorm() < 1e-24);
        dir.normalize();
      }
      move = sigma * gauss(rng) * dir;
    }
    if (moved_share >= 1 || uniform(picker) < moved_share) out.row(i) += move;
  }
  return out;
}

double noise_along_normals(const Positions& clean, const Positions& noisy, const Faces& faces) {
  const Positions normals = area_weighted_vertex_normals(clean, faces);
  double along = 0;
  int counted = 0;
  for (Eigen::Index i = 0; i < normals.rows(); ++i)
    if (normals.row(i).squaredNorm() > 0) {
      along += std::pow((noisy.row(i) - clean.row(i)).dot(normals.row(i)), 2);
      ++counted;
    }
  const double edge = mean_edge_length(noisy, faces);
  return counted > 0 && edge > 0 ? std::sqrt(along / counted) / edge : 0.0;
}

}  // namespace hht
