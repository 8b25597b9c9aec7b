// How much of isotropic noise's tangential part a mesh can hold. Noise of sigma per coordinate
// moves each vertex off its neighbours' centroid along its tangent plane by a mean square of
// 2 sigma^2 (1 + 1 / valence); the triangulation's own irregularity adds to that. So a mesh whose
// measured tangential offsets fall short of it carries less tangential noise than sigma, as
// with noise along the normals only (the denoising literature's protocol), where any
// tangential slide of a smoother is error (ours, docs/quality.md item 21).
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

namespace hht {

// The mean squared tangential offset of the interior vertices from their one-ring centroids,
// over what isotropic noise of `sigma` alone gives them, at most 1 (1 also when no vertex is
// interior or sigma is not positive). `unit_normals` per vertex, smooth enough to tell the
// tangent plane (a few rings averaged).
double tangential_noise_share(const Positions& v, const Positions& unit_normals, const VertexAdjacency& adjacency,
                              double sigma);

}  // namespace hht
