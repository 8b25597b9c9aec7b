#include "mesh/mean_curvature.h"

#include "mesh/vertex_normals.h"

namespace hht {

bool mean_curvature(const Positions& positions, const Faces& faces, MeanCurvature& out, std::string& error,
                    LaplacianTriangles triangles) {
  if (!positions.allFinite()) {
    Eigen::Index bad = 0;
    for (Eigen::Index i = 0; i < positions.rows(); ++i) bad += positions.row(i).allFinite() ? 0 : 1;
    error = std::to_string(bad) + " vertices have NaN or infinite coordinates; remove them first";
    return false;
  }
  out.triangles = triangles;
  const CotangentLaplacian laplacian = cotangent_laplacian(positions, faces, triangles, &out.delaunay);
  out.areas = laplacian.areas;
  out.normals = area_weighted_vertex_normals(positions, faces);
  out.laplacian = cotangent_matrix_times(laplacian, positions);
  out.signal.resize(positions.rows());
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    const double a = out.areas[i];
    out.laplacian.row(i) = a > 0 ? Eigen::RowVector3d(out.laplacian.row(i) / a) : Eigen::RowVector3d::Zero();
    out.signal[i] = out.laplacian.row(i).dot(out.normals.row(i));
  }
  return true;
}

}  // namespace hht
