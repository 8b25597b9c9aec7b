// Which faces lie near a crease: those with a vertex on an edge whose two faces' normals are
// more than a given angle apart. The denoiser reads it off its noise-level smoothing (noise
// gone, creases still there, rounded) to give the guided normal filter a narrow range width at
// the creases, which it must keep, and a wide one elsewhere, where the surface's own curvature
// needs it (docs/quality.md item 14).
#pragma once

#include "mesh/dihedral_angles.h"

#include <vector>

namespace hht {

// One flag per face, from the mesh's dihedral_angles(): edges of one face (boundary) are no
// creases, nor are those of zero-area faces, which have no normal.
std::vector<unsigned char> faces_near_creases(const std::vector<DihedralAngle>& angles, const Faces& faces,
                                              Eigen::Index vertex_count, double degrees);

}  // namespace hht
