#include "mesh/face_geometry.h"

#include <algorithm>
#include <vector>

namespace hht {

FaceGeometry face_geometry(const Positions& positions, const Faces& faces) {
  FaceGeometry g;
  const Eigen::Index count = faces.rows();
  g.normals.resize(count, 3);
  g.centroids.resize(count, 3);
  g.areas.resize(count);
  for (Eigen::Index f = 0; f < count; ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0)), b = positions.row(faces(f, 1)), c = positions.row(faces(f, 2));
    const Eigen::RowVector3d n = (b - a).cross(c - a);
    const double length = n.norm();
    g.areas[f] = 0.5 * length;
    g.normals.row(f) = length > 0 ? Eigen::RowVector3d(n / length) : Eigen::RowVector3d::Zero();
    g.centroids.row(f) = (a + b + c) / 3.0;
  }
  return g;
}

double median_face_altitude(const Positions& positions, const Faces& faces) {
  if (faces.rows() == 0) return 0;
  std::vector<double> altitudes(faces.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0)), b = positions.row(faces(f, 1)), c = positions.row(faces(f, 2));
    const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    altitudes[f] = longest > 0 ? (b - a).cross(c - a).norm() / longest : 0;
  }
  const auto middle = altitudes.begin() + altitudes.size() / 2;
  std::nth_element(altitudes.begin(), middle, altitudes.end());
  return *middle;
}

}  // namespace hht
