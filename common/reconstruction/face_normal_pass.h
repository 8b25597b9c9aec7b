// One pass of face-normal smoothing after the adaptive smoothing (ours; docs/quality.md item 20):
// each face's normal is replaced by the area-weighted mean of the normals of the faces sharing a
// vertex with it (itself included), and the vertices are moved towards those normals by the
// vertex update of normal_vertex_update.h. On well-shaped meshes it stands up the small faces
// that the noise's tangential part left tilted (the smoothing's tangential cap holds their
// vertices back); on coarse meshes it flattens real detail, so the smoothing keeps it only where
// a recorrupted risk estimate says it lowers the error (recorrupted_risk.h).
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

// Vertex-update iterations of the pass.
constexpr int kFaceNormalPassIterations = 2;

Positions face_normal_pass(const Positions& positions, const Faces& faces);

}  // namespace hht
