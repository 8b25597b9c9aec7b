// The two neighbours of each border vertex along its border: the vertices it shares an edge of
// one face with. The smoothing lets a border vertex move freely along its border and along the
// normal, and across the border only as far as the noise would (docs/quality.md item 35): the
// uniform Laplacian's one-sided ring there pulls open borders and the rims of holes inwards.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <array>
#include <vector>

namespace hht {

// {-1, -1} for a vertex on no border edge, or on more or fewer than two (a pinched or dangling
// border vertex, where "along the border" has no single direction).
using BorderNeighbours = std::vector<std::array<int, 2>>;

// `adjacency` is vertex_adjacency() of the same faces.
BorderNeighbours border_neighbours(const Faces& faces, const VertexAdjacency& adjacency);

// The border neighbours of the sampled vertices `kept` (breadth_first_patches.h), re-indexed into
// it: the mesh's own borders only, not the sample's rims.
BorderNeighbours border_neighbours_among(const BorderNeighbours& border, const std::vector<int>& kept);

// Clamps each border vertex's move from `from` to `x` across the border to at most `limit`: the
// part within the tangent plane of `unit_normals`, square to the chord between its two border
// neighbours in `from`. Returns how many border vertices it looked at (those with a direction).
int clamp_moves_across_borders(const Positions& from, const Positions& unit_normals, const BorderNeighbours& border,
                               Positions& x, double limit);

}  // namespace hht
