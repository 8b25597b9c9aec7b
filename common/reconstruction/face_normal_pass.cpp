#include "reconstruction/face_normal_pass.h"

#include "reconstruction/normal_vertex_update.h"

#include <vector>

namespace hht {

Positions face_normal_pass(const Positions& positions, const Faces& faces) {
  const Eigen::Index m = faces.rows();
  Positions area_vectors(m, 3);  // twice the area times the unit normal
  for (Eigen::Index f = 0; f < m; ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0));
    area_vectors.row(f) = (positions.row(faces(f, 1)) - a).cross(positions.row(faces(f, 2)) - a);
  }
  // The faces around each vertex, in compressed rows.
  std::vector<int> offsets(positions.rows() + 1, 0), around(3 * m);
  for (Eigen::Index f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) ++offsets[faces(f, k) + 1];
  for (Eigen::Index i = 0; i < positions.rows(); ++i) offsets[i + 1] += offsets[i];
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (Eigen::Index f = 0; f < m; ++f)
    for (int k = 0; k < 3; ++k) around[fill[faces(f, k)]++] = static_cast<int>(f);

  Positions targets(m, 3);
  std::vector<int> seen(m, -1);
  for (Eigen::Index f = 0; f < m; ++f) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      const int v = faces(f, k);
      for (int c = offsets[v]; c < offsets[v + 1]; ++c) {
        const int g = around[c];
        if (seen[g] == f) continue;  // a face sharing two vertices counts once
        seen[g] = static_cast<int>(f);
        sum += area_vectors.row(g);
      }
    }
    const double length = sum.norm();
    targets.row(f) = length > 0 ? Eigen::RowVector3d(sum / length) : Eigen::RowVector3d::Zero();
  }
  return fit_vertices_to_normals(positions, faces, targets, kFaceNormalPassIterations);
}

}  // namespace hht
