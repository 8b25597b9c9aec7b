// A sample of a large mesh for the scores that choose the smoothing's settings (the
// cross-validated cut-off, the recorrupted risk of the face-normal pass): `patches` breadth-first
// patches grown over the one-rings from seeds spread evenly over the vertex order, `budget`
// vertices in all. Whole patches, not scattered vertices, so that the filters scored on them see
// one-rings as on the full mesh except along the patches' rims.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <vector>

namespace hht {

// The original indices of the sampled vertices, each patch's in breadth-first order.
std::vector<int> breadth_first_patches(const VertexAdjacency& adjacency, int budget, int patches);

// The one-rings among the sampled vertices only (indices into `kept`).
VertexAdjacency adjacency_among(const VertexAdjacency& adjacency, const std::vector<int>& kept);

// The faces whose three corners are sampled, re-indexed into `kept`.
Faces faces_among(const Faces& faces, int vertex_count, const std::vector<int>& kept);

// The rows of `all` at `kept`.
Positions rows_at(const Positions& all, const std::vector<int>& kept);

}  // namespace hht
