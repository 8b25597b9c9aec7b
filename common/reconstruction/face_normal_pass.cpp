#include "reconstruction/face_normal_pass.h"

#include "mesh/face_rings.h"
#include "reconstruction/normal_vertex_update.h"

namespace hht {

Positions face_normal_pass(const Positions& positions, const Faces& faces) {
  const Eigen::Index m = faces.rows();
  Positions area_vectors(m, 3);  // twice the area times the unit normal
  for (Eigen::Index f = 0; f < m; ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0));
    area_vectors.row(f) = (positions.row(faces(f, 1)) - a).cross(positions.row(faces(f, 2)) - a);
  }
  const IndexLists rings = face_rings(faces, static_cast<int>(positions.rows()));
  Positions targets(m, 3);
  for (Eigen::Index f = 0; f < m; ++f) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (int i = rings.begin(static_cast<int>(f)); i < rings.end(static_cast<int>(f)); ++i) sum += area_vectors.row(rings.items[i]);
    const double length = sum.norm();
    targets.row(f) = length > 0 ? Eigen::RowVector3d(sum / length) : Eigen::RowVector3d::Zero();
  }
  return fit_vertices_to_normals(positions, faces, targets, kFaceNormalPassIterations);
}

}  // namespace hht
