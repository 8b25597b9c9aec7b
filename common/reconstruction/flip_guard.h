// A guard against faces turned over by a filter: where a result face points against the same
// face of the input (a fold the filter made: enhancement amplifies the curvature signal, which
// the cotangent Laplacian makes erratic on slivers), its vertices go back to their input
// positions, repeated until no such face is left. Faces degenerate in the input are ignored.
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

// Returns how many vertices were restored.
int restore_turned_faces(const Positions& input, const Faces& faces, Positions& result);

// The same for a smoothing, which must turn over the faces that noise folded: a turned face goes
// back only if it was not folded in the input (against the sum of its corners' area-weighted
// normals there) and, with its vertices back, it lies within `max_degrees` of the result's
// surface (the same sum on the result) while no face around them points against that surface.
// On a clean mesh these are wrinkles of the triangulation the smoothing straightened over; a face
// tilted by noise does not fit the smoothed surface once put back. Returns the faces restored.
int restore_turned_faces_that_fit(const Positions& input, const Faces& faces, double max_degrees, Positions& result);

}  // namespace hht
