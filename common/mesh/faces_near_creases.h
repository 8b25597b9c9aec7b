// Which faces lie near a crease: those with a vertex on an edge whose two faces' normals are
// more than a given angle apart. The denoiser reads it off its noise-level smoothing (noise
// gone, creases still there, rounded) to give the guided normal filter a narrow range width at
// the creases, which it must keep, and a wide one elsewhere, where the surface's own curvature
// needs it (docs/quality.md item 14).
#pragma once

#include "mesh/mesh_arrays.h"

#include <vector>

namespace hht {

// One flag per face. Edges of one face (boundary) are no creases; on a non-manifold edge each
// further face is compared with the first. Faces of zero area have no normal and make none.
std::vector<unsigned char> faces_near_creases(const Positions& positions, const Faces& faces, double degrees);

}  // namespace hht
