// The noise level of a mesh, estimated from the finest IMF of a signal along the Hamiltonian
// cycle (the idea of Kopsinis and McLaughlin 2009, the paper's ref. [15], and of Donoho's
// wavelet estimator: the finest scale of a noisy signal is mostly noise, and its median
// absolute deviation is robust to the few large values that real detail puts there).
//
// The signal is each vertex's height over its one-ring: h_i = <v_i - mean_j v_j, n_i>, with n_i
// the area-weighted normal. On a smooth surface h varies slowly (it is about the mean curvature
// times the squared edge length), so EMD puts it in the coarse IMFs and the residue; Gaussian
// noise of standard deviation sigma per coordinate (or along the normals) adds a white part of
// standard deviation sigma sqrt(1 + 1/valence), most of which lands in the finest IMF.
// sigma = MAD(IMF 1) / 0.6745 / sqrt(1 + 1/mean valence) / kImf1Share, where kImf1Share is the
// part of a white signal's standard deviation that IMF 1 holds (measured by
// tests/unit/noise_estimate_test.cpp on white noise, and checked on noisy meshes).
// Boundary vertices are left out of the MAD (their one-ring mean lies to one side).
#pragma once

#include "emd.h"
#include "hamiltonian_cycle.h"
#include "mesh_arrays.h"

#include <string>

namespace hht {

struct NoiseEstimate {
  double sigma = 0;          // standard deviation per coordinate, in the mesh's length unit
  double mean_edge = 0;      // mean edge length
  double relative() const { return mean_edge > 0 ? sigma / mean_edge : 0; }  // sigma / mean edge
  int samples = 0;           // IMF 1 samples the MAD was taken over
};

// Part of a white Gaussian signal's standard deviation (as MAD / 0.6745) that its first IMF
// holds, under the default EMD options.
constexpr double kImf1Share = 0.80;

// Per-vertex height over the one-ring mean, along the normal (0 for vertices of no face).
Eigen::VectorXd one_ring_heights(const Positions& positions, const Faces& faces);

// Fails on a mesh without faces or with non-finite coordinates. `cycle` is hamiltonian_cycle()
// of the same faces.
bool estimate_noise(const Positions& positions, const Faces& faces, const HamiltonianCycle& cycle,
                    const EmdOptions& emd_options, NoiseEstimate& out, std::string& error);

}  // namespace hht
