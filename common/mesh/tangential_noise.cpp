#include "mesh/tangential_noise.h"

#include "mesh/uniform_laplacian.h"

#include <algorithm>
#include <vector>

namespace hht {

namespace {

// A boundary vertex sits off its one-sided centroid by the surface's own extent: left out.
bool interior(const VertexAdjacency& adjacency, int i) { return adjacency.valence(i) > 0 && !adjacency.boundary[i]; }

Eigen::RowVector3d tangential(const Eigen::RowVector3d& x, const Eigen::RowVector3d& unit_normal) {
  return x - x.dot(unit_normal) * unit_normal;
}

}  // namespace

double tangential_noise_share(const Positions& v, const Positions& unit_normals, const VertexAdjacency& adjacency,
                              double sigma, int sample_vertices) {
  if (!(sigma > 0)) return 1;
  const int n = adjacency.vertices();
  // First differences: each interior vertex's tangential offset from its one-ring centroid.
  Positions offsets = Positions::Zero(n, 3);
  for (int i = 0; i < n; ++i) {
    if (!interior(adjacency, i)) continue;
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) centroid += v.row(*j);
    offsets.row(i) = tangential(v.row(i) - centroid / adjacency.valence(i), unit_normals.row(i));
  }
  // Second differences, where the whole ring is interior; unit isotropic noise gives row i of
  // (I - W)^2 a mean square of sum_l c_il^2 per coordinate, two coordinates on the tangent plane.
  std::vector<double> coefficient(n, 0.0);
  std::vector<int> touched;
  double measured = 0, expected = 0;
  // On a large mesh every stride-th vertex: the ratio is a mean, and the second differences
  // touch each vertex's two rings (0.8 s at 1.66M vertices over all of them).
  const int stride = std::max(1, n / std::max(1, sample_vertices));
  for (int i = 0; i < n; i += stride) {
    if (!interior(adjacency, i)) continue;
    const double ki = adjacency.valence(i);
    bool ring_interior = true;
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    for (const int* j = adjacency.begin(i); j != adjacency.end(i) && ring_interior; ++j) {
      ring_interior = interior(adjacency, *j);
      mean += offsets.row(*j);
    }
    if (!ring_interior) continue;
    measured += tangential(offsets.row(i) - mean / ki, unit_normals.row(i)).squaredNorm();
    expected += 2 * sigma * sigma * squared_laplacian_row_gain(adjacency, i, coefficient, touched);
  }
  if (!(expected > 0)) return 1;
  return std::min(1.0, measured / expected);
}

}  // namespace hht
