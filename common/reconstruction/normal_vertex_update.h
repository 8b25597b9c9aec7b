// Moves vertices so that the faces' normals approach given target normals, keeping creases
// where the targets change sharply: the iterative vertex update of Sun, Rosin, Martin and
// Langbein ("Fast and effective feature-preserving mesh denoising", 2007). Each iteration moves
// every vertex v by the mean over its faces f of n_f <n_f, c_f - v> (c_f the face centroid): the
// vertex slides onto the planes the target normals define through the current centroids.
#pragma once

#include "mesh/mesh_arrays.h"

#include <vector>

namespace hht {

// `face_normals`: one unit target normal per face (a zero row leaves that face out). `fixed`:
// empty, or one flag per vertex, 1 for a vertex that stays where it is.
Positions fit_vertices_to_normals(const Positions& positions, const Faces& faces, const Positions& face_normals,
                                  int iterations, const std::vector<unsigned char>& fixed = {});

}  // namespace hht
