// How much of isotropic noise's tangential part a mesh can hold. Noise of sigma per coordinate
// moves each vertex off its neighbours' centroid along its tangent plane; the triangulation's
// own layout adds to that. So a mesh whose measured tangential offsets fall short of what
// noise gives them carries less tangential noise than sigma, as with noise along the normals
// only (the denoising literature's protocol), where any tangential slide of a smoother is error
// (ours, docs/quality.md item 21).
//
// The offsets are read through their second differences (each offset minus its neighbours'
// mean): a graded sampling, whose layout changes smoothly over the surface, drops out, and
// white noise stays (ours, item 23: camel at 10% along the normals reads 0.13, 1.0 from the
// offsets themselves). A layout irregular from vertex to vertex (cow, bull, femur) stays in:
// it is as white as noise, and no reading tells the two apart (item 8).
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

namespace hht {

// Meshes of more vertices read the second differences at every (n / this)-th vertex only.
constexpr int kShareSampleVertices = 200000;

// The mean square of the second differences of the tangential offsets from the one-ring
// centroids (over the vertices whose ring is interior), over what isotropic noise of `sigma`
// alone gives them (2 sigma^2 times the sum of the squared coefficients of row i of (I - W)^2,
// W the neighbour average), at most 1 (1 also when no vertex qualifies or sigma is not
// positive). `unit_normals` per vertex, smooth enough to tell the tangent plane (a few rings
// averaged). Read at about `sample_vertices` vertices, evenly strided.
double tangential_noise_share(const Positions& v, const Positions& unit_normals, const VertexAdjacency& adjacency,
                              double sigma, int sample_vertices = kShareSampleVertices);

}  // namespace hht
