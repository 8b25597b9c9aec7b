// A guard against faces turned over by a filter: where a result face points against the same
// face of the input (a fold the filter made: enhancement amplifies the curvature signal, which
// the cotangent Laplacian makes erratic on slivers), its vertices go back to their input
// positions, repeated until no such face is left. Faces degenerate in the input are ignored.
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

// Returns how many vertices were restored.
int restore_turned_faces(const Positions& input, const Faces& faces, Positions& result);

}  // namespace hht
