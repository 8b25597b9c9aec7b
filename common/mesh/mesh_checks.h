// Input checks shared by the filters, with messages a MeshLab user can act on.
#pragma once

#include "mesh/mesh_arrays.h"

#include <string>

namespace hht {

// Fails on a mesh without faces and on non-finite coordinates.
bool check_triangle_mesh(const Positions& positions, const Faces& faces, std::string& error);

// The farthest a filter may move a vertex, in bounding-box diagonals of its input: a smoothing,
// denoising or enhancement that moves a vertex farther than the whole mesh is wide has broken
// down (an extreme parameter, a degenerate solve), it is not a stronger result.
constexpr double kMaxMoveDiagonals = 1.0;

// Fails when `result` (one row per vertex of `input`) has coordinates that are not finite in
// single precision (MeshLab's), or moved a vertex farther than kMaxMoveDiagonals bounding-box
// diagonals of `input`; the message says which and how far.
bool check_result_positions(const Positions& input, const Positions& result, std::string& error);

// Bounding-box diagonal of the positions (0 for none).
double bounding_box_diagonal(const Positions& positions);

}  // namespace hht
