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

// The faces a smoothing still leaves turned over (against the input, and not folded in the
// input: against the sum of its corners' unnormalised area-weighted normals), when they are few: at most `max_share` of all faces. So few are wrinkles of a clean
// irregular triangulation (faces standing 50-90 degrees from the surface around them, which the
// smoothing laid over the other way), not faces tilted by noise, which turns many more (cow,
// femur, bull, man: 0.02-0.08% clean, 0.28-1.1% at 10% noise; docs/quality.md). Each goes back
// the least share of the way (in twentieths) that un-turns it, first its own vertices, else
// these and their neighbours, and only if no face around turns over against the input or
// against the smoothed surface (the sum of its corners' area-weighted normals on `result` as
// given), unless the input had it so. Returns the faces un-turned (0 when there are too many).
// With `max_share` 1 every such face is taken: the denoiser's refinement, whose start has no folds
// but the noise's, stands up all the faces it turned over itself.
int unturn_few_turned_faces(const Positions& input, const Faces& faces, double max_share, Positions& result);

}  // namespace hht
