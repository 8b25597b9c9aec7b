#include "mesh/mesh_checks.h"

namespace hht {

bool check_triangle_mesh(const Positions& positions, const Faces& faces, std::string& error) {
  if (faces.rows() == 0) {
    error = "the mesh has no faces (a point cloud?): this filter needs a triangle mesh";
    return false;
  }
  Eigen::Index bad = 0;
  for (Eigen::Index i = 0; i < positions.rows(); ++i) bad += positions.row(i).allFinite() ? 0 : 1;
  if (bad > 0) {
    error = std::to_string(bad) + " vertices have NaN or infinite coordinates; remove them first";
    return false;
  }
  return true;
}

}  // namespace hht
