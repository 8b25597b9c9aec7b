#include "mesh/face_geometry.h"

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

}  // namespace hht
