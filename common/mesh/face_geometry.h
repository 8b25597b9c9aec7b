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

// The median over the faces of each one's altitude onto its longest side (twice its area over
// that side; 0 for a degenerate face): how thin the triangles are, slivers small. 0 without faces.
double median_face_altitude(const Positions& positions, const Faces& faces);

}  // namespace hht
