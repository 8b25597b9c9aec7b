#include "mesh/mesh_checks.h"

#include <cmath>
#include <limits>
#include <sstream>

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

double bounding_box_diagonal(const Positions& positions) {
  if (positions.rows() == 0) return 0;
  return (positions.colwise().maxCoeff() - positions.colwise().minCoeff()).norm();
}

bool check_result_positions(const Positions& input, const Positions& result, std::string& error) {
  if (result.rows() != input.rows()) {
    error = "the filter returned " + std::to_string(result.rows()) + " positions for " +
            std::to_string(input.rows()) + " vertices";
    return false;
  }
  const double largest = std::numeric_limits<float>::max();
  Eigen::Index not_finite = 0;
  for (Eigen::Index i = 0; i < result.rows(); ++i)
    if (!result.row(i).allFinite() || result.row(i).cwiseAbs().maxCoeff() > largest) ++not_finite;
  if (not_finite > 0) {
    error = "the result has " + std::to_string(not_finite) +
            " vertices with NaN or infinite coordinates (or beyond single precision)";
    return false;
  }
  const double diagonal = bounding_box_diagonal(input);
  const double moved = input.rows() > 0 ? (result - input).rowwise().norm().maxCoeff() : 0.0;
  if (moved > kMaxMoveDiagonals * diagonal) {
    std::ostringstream message;
    message << "the result moved a vertex by " << moved << ", " << (diagonal > 0 ? moved / diagonal : INFINITY)
            << " times the bounding-box diagonal " << diagonal << " (at most " << kMaxMoveDiagonals
            << " allowed): the parameters are too extreme for this mesh";
    error = message.str();
    return false;
  }
  return true;
}

}  // namespace hht
