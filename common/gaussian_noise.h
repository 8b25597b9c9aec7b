// The paper's noise model: each vertex moves by a Gaussian amount of standard deviation
// sigma = percent of the mean edge length, along a uniformly random direction or along its
// normal. Reproducible for a given seed (on one standard library).
#pragma once

#include "mesh_arrays.h"

namespace hht {

enum class NoiseDirection { Random, Normal };

double mean_edge_length(const Positions& positions, const Faces& faces);

// Returns the displaced positions; vertices of no face do not move.
Positions add_gaussian_noise(const Positions& positions, const Faces& faces, double percent_of_mean_edge,
                             NoiseDirection direction, unsigned seed);

}  // namespace hht
