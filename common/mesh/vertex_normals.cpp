#include "mesh/vertex_normals.h"

namespace hht {

Positions summed_area_vectors(const Positions& positions, const Faces& faces) {
  Positions sums = Positions::Zero(positions.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0));
    const Eigen::RowVector3d n = (positions.row(faces(f, 1)) - a).cross(positions.row(faces(f, 2)) - a);
    for (int k = 0; k < 3; ++k) sums.row(faces(f, k)) += n;
  }
  return sums;
}

Positions area_weighted_vertex_normals(const Positions& positions, const Faces& faces) {
  Positions normals = summed_area_vectors(positions, faces);
  for (Eigen::Index i = 0; i < normals.rows(); ++i) {
    const double len = normals.row(i).norm();
    if (len > 0) normals.row(i) /= len;
  }
  return normals;
}

std::vector<unsigned char> folded_faces(const Positions& positions, const Faces& faces) {
  const Positions sums = summed_area_vectors(positions, faces);
  std::vector<unsigned char> folded(static_cast<size_t>(faces.rows()), 0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0));
    const Eigen::RowVector3d n = (positions.row(faces(f, 1)) - a).cross(positions.row(faces(f, 2)) - a);
    folded[static_cast<size_t>(f)] = n.dot(sums.row(faces(f, 0)) + sums.row(faces(f, 1)) + sums.row(faces(f, 2))) < 0;
  }
  return folded;
}

Eigen::RowVector3d unit_face_normal(const Positions& positions, const Faces& faces, Eigen::Index f) {
  const Eigen::RowVector3d a = positions.row(faces(f, 0));
  const Eigen::RowVector3d c = (positions.row(faces(f, 1)) - a).cross(positions.row(faces(f, 2)) - a);
  const double length = c.norm();
  return length > 0 ? Eigen::RowVector3d(c / length) : Eigen::RowVector3d::Zero();
}

Positions unit_face_normals(const Positions& positions, const Faces& faces) {
  Positions normals(faces.rows(), 3);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) normals.row(f) = unit_face_normal(positions, faces, f);
  return normals;
}

Positions smoothed_vertex_normals(const Positions& x, const Faces& faces, const VertexAdjacency& adjacency) {
  Positions normals = area_weighted_vertex_normals(x, faces), next(x.rows(), 3);
  for (int sweep = 0; sweep < 3; ++sweep) {
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      Eigen::RowVector3d sum = normals.row(i);
      for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) sum += normals.row(*j);
      const double length = sum.norm();
      next.row(i) = length > 0 ? Eigen::RowVector3d(sum / length) : Eigen::RowVector3d::Zero();
    }
    normals.swap(next);
  }
  return normals;
}

}  // namespace hht
