#include "reconstruction/face_normal_pass.h"

#include "mesh/face_rings.h"
#include "reconstruction/normal_vertex_update.h"

namespace hht {

namespace {

// Each face's target: the unit mean of the area vectors of the faces sharing a vertex with it.
Positions mean_ring_normals(const Positions& positions, const Faces& faces) {
  const Eigen::Index m = faces.rows();
  Positions area_vectors(m, 3);  // twice the area times the unit normal
  for (Eigen::Index f = 0; f < m; ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0));
    area_vectors.row(f) = (positions.row(faces(f, 1)) - a).cross(positions.row(faces(f, 2)) - a);
  }
  const IndexLists around = vertex_faces(faces, static_cast<int>(positions.rows()));
  Positions targets(m, 3);
  std::vector<int> ring;
  for (Eigen::Index f = 0; f < m; ++f) {
    face_ring(faces, around, f, ring);
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (const int g : ring) sum += area_vectors.row(g);
    const double length = sum.norm();
    targets.row(f) = length > 0 ? Eigen::RowVector3d(sum / length) : Eigen::RowVector3d::Zero();
  }
  return targets;
}

}  // namespace

// One face ring at a time, and the area vectors gone before the fit allocates its own arrays: this
// pass set the smoothing's peak memory on large meshes.
Positions face_normal_pass(const Positions& positions, const Faces& faces) {
  return fit_vertices_to_normals(positions, faces, mean_ring_normals(positions, faces), kFaceNormalPassIterations);
}

}  // namespace hht
