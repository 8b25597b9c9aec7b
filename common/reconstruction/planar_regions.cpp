#include "reconstruction/planar_regions.h"

#include "mesh/corner_table.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/normal_vertex_update.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {
namespace {

// The unit normal of the plane through `vertices` (least squares), oriented as `along`, if a
// quadric height field over that plane bends by at most `max_bend` radians at every vertex;
// otherwise zero.
Eigen::RowVector3d plane_if_flat(const Positions& p, const std::vector<int>& vertices, const Eigen::RowVector3d& along,
                                 double max_bend) {
  Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
  for (int v : vertices) mean += p.row(v);
  mean /= static_cast<double>(vertices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (int v : vertices) {
    const Eigen::Vector3d d = (p.row(v) - mean).transpose();
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(scatter);
  const Eigen::Vector3d normal = axes.eigenvectors().col(0), u = axes.eigenvectors().col(2), w = axes.eigenvectors().col(1);
  Eigen::MatrixXd basis(vertices.size(), 6);
  Eigen::VectorXd height(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    const Eigen::Vector3d d = (p.row(vertices[i]) - mean).transpose();
    const double x = d.dot(u), y = d.dot(w);
    basis.row(i) << 1, x, y, x * x, x * y, y * y;
    height[i] = d.dot(normal);
  }
  const Eigen::VectorXd quadric = basis.colPivHouseholderQr().solve(height);
  const double max_slope = std::tan(max_bend);
  for (Eigen::Index i = 0; i < basis.rows(); ++i) {
    const double x = basis(i, 1), y = basis(i, 2);
    if (std::hypot(2 * quadric[3] * x + quadric[4] * y, quadric[4] * x + 2 * quadric[5] * y) > max_slope)
      return Eigen::RowVector3d::Zero();
  }
  const Eigen::RowVector3d plane = normal.transpose();
  return plane.dot(along) < 0 ? Eigen::RowVector3d(-plane) : plane;
}

}  // namespace

bool flatten_planar_regions(const Positions& positions, const Faces& faces, const PlanarRegionOptions& options,
                            Positions& result, PlanarRegionReport& report, std::string& error) {
  CornerTable table;
  int inconsistent = 0;
  if (!build_corner_table(faces, static_cast<int>(positions.rows()), table, inconsistent, error)) return false;
  report = {};
  const Positions normals = unit_face_normals(positions, faces);
  const double within = std::cos(options.seed_degrees * M_PI / 180);
  const Eigen::Index face_count = faces.rows();
  std::vector<unsigned char> taken(face_count, 0);
  Positions targets = Positions::Zero(face_count, 3);
  std::vector<int> region, vertices;
  for (Eigen::Index seed = 0; seed < face_count; ++seed) {
    if (taken[seed] || normals.row(seed).squaredNorm() == 0) continue;
    region.assign(1, static_cast<int>(seed));
    taken[seed] = 1;
    for (size_t k = 0; k < region.size(); ++k)
      for (int c = 3 * region[k]; c < 3 * region[k] + 3; ++c) {
        const int across = table.opposite[c];
        if (across < 0) continue;
        const int face = corner_triangle(across);
        if (!taken[face] && normals.row(face).dot(normals.row(seed)) > within) {
          taken[face] = 1;
          region.push_back(face);
        }
      }
    if (static_cast<int>(region.size()) < options.min_faces) continue;
    vertices.clear();
    Eigen::RowVector3d along = Eigen::RowVector3d::Zero();
    for (int face : region) {
      along += normals.row(face);
      for (int k = 0; k < 3; ++k) vertices.push_back(faces(face, k));
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    const Eigen::RowVector3d plane = plane_if_flat(positions, vertices, along, options.max_bend_degrees * M_PI / 180);
    if (plane.squaredNorm() == 0) continue;
    for (int face : region) targets.row(face) = plane;
    ++report.regions;
    report.faces += static_cast<int>(region.size());
  }
  result = positions;
  if (report.regions == 0 || options.vertex_iterations <= 0) return true;
  double first_move = -1;
  for (int done = 0; done < std::max(options.vertex_iterations, options.max_vertex_iterations); done += options.vertex_iterations) {
    Positions next = fit_vertices_to_normals(result, faces, targets, options.vertex_iterations);
    const double move = (next - result).rowwise().squaredNorm().sum();
    result.swap(next);
    report.fit_iterations += options.vertex_iterations;
    if (first_move < 0) first_move = move;
    if (move <= options.settled * options.settled * first_move) break;
  }
  return true;
}

}  // namespace hht
