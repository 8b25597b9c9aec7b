// Per-face normal, centroid and area of a triangle mesh: what the normal filters weigh faces by.
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

struct FaceGeometry {
  Positions normals;  // unit, zero for a degenerate face
  Positions centroids;
  Eigen::VectorXd areas;
};

FaceGeometry face_geometry(const Positions& positions, const Faces& faces);

}  // namespace hht
