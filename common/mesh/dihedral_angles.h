// The angle between the normals of the two faces on each edge: what the crease contrast and the
// faces near creases are read from (crease_contrast.h, faces_near_creases.h), computed once.
#pragma once

#include "mesh/mesh_arrays.h"

#include <vector>

namespace hht {

struct DihedralAngle {
  int a, b;        // the edge's vertices
  double radians;  // between the two faces' unit normals, in [0, pi]
};

// One per pair of faces sharing an edge, both of nonzero area; on a non-manifold edge each
// further face is paired with the first. Boundary edges have none.
std::vector<DihedralAngle> dihedral_angles(const Positions& positions, const Faces& faces);

}  // namespace hht
