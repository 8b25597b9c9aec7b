#include "reconstruction/normal_vertex_update.h"

namespace hht {

Positions fit_vertices_to_normals(const Positions& positions, const Faces& faces, const Positions& face_normals,
                                  int iterations) {
  Positions v = positions;
  const Eigen::Index n = positions.rows();
  Eigen::VectorXi count = Eigen::VectorXi::Zero(n);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    if (face_normals.row(f).squaredNorm() > 0)
      for (int k = 0; k < 3; ++k) ++count[faces(f, k)];
  Positions step(n, 3);
  for (int it = 0; it < iterations; ++it) {
    step.setZero();
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d normal = face_normals.row(f);
      if (normal.squaredNorm() == 0) continue;
      const Eigen::RowVector3d centroid = (v.row(faces(f, 0)) + v.row(faces(f, 1)) + v.row(faces(f, 2))) / 3.0;
      for (int k = 0; k < 3; ++k) step.row(faces(f, k)) += normal * normal.dot(centroid - v.row(faces(f, k)));
    }
    for (Eigen::Index i = 0; i < n; ++i)
      if (count[i] > 0) v.row(i) += step.row(i) / count[i];
  }
  return v;
}

}  // namespace hht
