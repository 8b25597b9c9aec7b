// Moves vertices so that the faces take given target normals: the vertex update of the SD
// filter's authors (Zhang, Deng, Hong, Peng, Qin, Liu, "Static/Dynamic Filtering for Mesh
// Geometry", TVCG 2019; their MeshSDFilter code, "iterative mesh update"). A global
// least-squares fit in the style of ShapeUp, where Sun et al.'s update (normal_vertex_update.h)
// is a local averaging: each iteration
//  1. takes every face's vertices, centred on their mean, and projects them onto the plane
//     through the origin orthogonal to the face's target normal (a face turned against its
//     target, current normal . target < 0, goes onto the line in that plane that fits the
//     projected vertices best instead: a plane would fold it over);
//  2. solves  min_X  sum_f |C X_f - B_f|^2 + w |X - X0|^2  for all vertices at once, with C the
//     centring of a triangle's three vertices, B_f the projected shape from step 1 and X0 the
//     input positions; the closeness term holds the translation (which C does not see) and
//     keeps the fit from drifting, w = closeness_weight * faces / vertices.
// The system matrix depends on the connectivity only: it is factorised once per call.
// The centring keeps the mean of the vertices exactly where it was.
#pragma once

#include "mesh/mesh_arrays.h"

#include <string>

namespace hht {

// `target_normals`: one unit normal per face (a zero row asks that face to keep its shape).
// Faces must be consistently oriented (the turned-face test compares current and target normals).
// Fails with a message when the sizes do not match, the weight is not positive, iterations is
// negative or the factorisation fails; `result` is then left as it was.
bool fit_vertices_to_normals_with_closeness(const Positions& positions, const Faces& faces,
                                            const Positions& target_normals, double closeness_weight, int iterations,
                                            Positions& result, std::string& error);

}  // namespace hht
