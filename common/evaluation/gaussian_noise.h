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

// Returns the displaced positions; vertices of no face do not move. With `moved_share` below 1,
// impulsive noise (the denoising literature's other model): each vertex moves with that
// probability, the others stay exactly where they were.
Positions add_gaussian_noise(const Positions& positions, const Faces& faces, double percent_of_mean_edge,
                             NoiseDirection direction, unsigned seed, double moved_share = 1);

// The RMS of the displacement from `clean` to `noisy` along the clean mesh's vertex normals, over
// the noisy mesh's mean edge: the noise level the smoothing and denoising filters estimate and
// take as given (sigma for noise along the normals or per coordinate; about sigma / sqrt 3 along
// random directions; noise lengthens the edges, so a little less at heavy noise). Vertices of no
// face are left out; 0 if none is left.
double noise_along_normals(const Positions& clean, const Positions& noisy, const Faces& faces);

}  // namespace hht
