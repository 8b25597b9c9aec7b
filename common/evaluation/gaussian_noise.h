// Gaussian noise of standard deviation sigma = percent of the mean edge length:
//  - Random: the paper's model, a Gaussian amount along a uniformly random direction;
//  - Normal: a Gaussian amount along the area-weighted vertex normal (the denoising literature);
//  - Isotropic: independent Gaussian noise on each coordinate (what a scanner's noise looks
//    like: sqrt(3) sigma RMS displacement, two thirds of its power tangential).
// Reproducible for a given seed (on one standard library).
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

enum class NoiseDirection { Random, Normal, Isotropic };

double mean_edge_length(const Positions& positions, const Faces& faces);

// Returns the displaced positions; vertices of no face do not move.
Positions add_gaussian_noise(const Positions& positions, const Faces& faces, double percent_of_mean_edge,
                             NoiseDirection direction, unsigned seed);

}  // namespace hht
