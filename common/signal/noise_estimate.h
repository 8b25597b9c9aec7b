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
// part of that noise's standard deviation that IMF 1 holds. For white noise it is 0.95
// (tests/unit/noise_estimate_test.cpp); the height signal of neighbours along the cycle is
// negatively correlated (they share one-rings), which pushes nearly all of it into IMF 1: 1.0,
// measured on a sphere with isotropic and normal noise of 5-20% of the mean edge, where the
// estimate is then within 6% (at 30% the noisy normals make it about 10% low). On coarse irregular meshes the triangulation adds a floor
// (cow: 0.07 mean edges without noise) and heavy noise is under-estimated by up to 20%.
// Boundary vertices are left out of the MAD (their one-ring mean lies to one side).
#pragma once

#include "signal/emd.h"
#include "cycle/hamiltonian_cycle.h"
#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <string>

namespace hht {

struct NoiseEstimate {
  double sigma = 0;          // standard deviation per coordinate, in the mesh's length unit
  double mean_edge = 0;      // mean edge length
  double relative() const { return mean_edge > 0 ? sigma / mean_edge : 0; }  // sigma / mean edge
  int samples = 0;           // IMF 1 samples the MAD was taken over
};

// Part of the height noise's standard deviation (as MAD / 0.6745) that the first IMF holds,
// under the default EMD options (see above).
constexpr double kImf1Share = 1.0;

// Per-vertex height over the one-ring mean, along the normal (0 for vertices of no face).
Eigen::VectorXd one_ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);

// Fails on a mesh without faces or with non-finite coordinates. `cycle` is hamiltonian_cycle()
// of the same faces.
bool estimate_noise(const Positions& positions, const Faces& faces, const HamiltonianCycle& cycle,
                    const EmdOptions& emd_options, NoiseEstimate& out, std::string& error);

}  // namespace hht
