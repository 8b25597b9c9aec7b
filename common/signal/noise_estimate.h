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
//
// That floor is capped by the flat hinges (mesh/hinge_heights.h; ours, not the paper's): sigma
// is at most kFlatHingeBound times the estimate read from the kHingeQuantile quantile of
// |hinge height|. On a noise-free CAD export, whose flat hinges are exact, that reads 0 where
// the IMF reads 0.07-0.40 mean edges (spool, couplingdown, rotor, cube-meshed); on a noisy
// mesh it reads 0.4-1.5 times the IMF's estimate (heavy noise along the normals of coarse
// CAD meshes, whose flat parts it mostly slides), so the cap binds only below 0.4: at light
// noise on CAD meshes, where it is nearer the truth than the IMF's floor (docs/quality.md).
// It reads 0 only when a tenth of the hinges or more are exactly flat: a noisy scan with a
// planar cut or a filled hole keeps its estimate (such caps hold a small share of its hinges).
// Nor is the cap taken under impulsive noise (a share of the vertices moved, the others left
// where they were), which leaves the untouched flat parts exactly flat: where enough vertices
// stand off flat surroundings as spikes (mesh/flat_hinge_spikes.h), the flat hinges read the
// part the noise missed. The MAD of a mixture of moved and unmoved vertices reads it low
// (blade with a tenth of its vertices moved: 0.05 mean edges for 0.15), so sigma is then the
// larger of the IMF's estimate and sqrt(spike share) times the spikes' RMS one-ring height, the
// noise's RMS over the vertices amid flat hinges. On a surface without exactly flat parts the
// estimate also reads scattered spikes (mesh/scattered_spikes.h); where they read impulsive
// noise, sigma is left as above (only the log shows it) and the filters remove the spikes instead
// of smoothing by it (filters/spike_removal.h; docs/quality.md item 26).
#pragma once

#include "signal/emd.h"
#include "cycle/hamiltonian_cycle.h"
#include "mesh/flat_hinge_spikes.h"
#include "mesh/mesh_arrays.h"
#include "mesh/scattered_spikes.h"
#include "mesh/vertex_adjacency.h"

#include <string>

namespace hht {

struct NoiseEstimate {
  double sigma = 0;          // standard deviation per coordinate, in the mesh's length unit
  double mean_edge = 0;      // mean edge length
  double relative() const { return mean_edge > 0 ? sigma / mean_edge : 0; }  // sigma / mean edge
  int samples = 0;           // IMF 1 samples the MAD was taken over
  double imf_sigma = 0;      // the finest IMF's estimate, before the cap
  double imf_rms_sigma = 0;  // the same from the IMF's RMS instead of its MAD
  double surely_noise_sigma = 0;  // a lower bound on sigma from IMFs 1 and 2 (kDetailImfRatio; 0: none surely)
  double hinge_sigma = 0;    // the flat hinges' estimate (0 on a mesh with fewer than kMinHinges)
  FlatHingeSpikes spikes;    // vertices standing off flat surroundings (role left empty)
  double spike_sigma = 0;    // the spikes' RMS one-ring height (length unit)
  ScatteredSpikes scattered;  // vertices standing off any surroundings (mesh/scattered_spikes.h)
  bool capped() const { return sigma < imf_sigma; }
  bool rests_on_few_samples() const;  // fewer than kFewImfSamples: see there
  // Impulsive noise read amid flat hinges (no cap; sigma read from the spikes too), or else from
  // scattered spikes (the filters then remove the spikes: filters/spike_removal.h).
  bool impulsive() const { return spikes.impulsive() || scattered_impulsive(); }
  bool scattered_impulsive() const { return !spikes.impulsive() && scattered.impulsive(); }
};

// Below this sigma (in mean edges) an estimated noise counts as none: the filters that estimate
// it leave the mesh exactly as it is, without their solves (clean fandisk and spool read 0: a
// tenth of their hinges are flat to the last digit; the denoiser's smoothing would otherwise
// estimate the noise again, since 0 asks it to).
constexpr double kNoiseFree = 1e-4;

// The cap: sigma <= kFlatHingeBound * hinge_sigma, with hinge_sigma the kHingeQuantile quantile
// of |hinge height| over that quantile of |N(0, 1)| (0.1257), on meshes of kMinHinges hinges
// or more.
constexpr double kHingeQuantile = 0.1;
constexpr double kFlatHingeBound = 2.5;
constexpr int kMinHinges = 50;

// A lower bound on the noise, for the log (ours; docs/quality.md item 38): where an estimate may be
// the mesh's own detail, how much of it is surely noise. Noise puts nearly all of its height signal
// into IMF 1: IMF 2's spread (MAD) is kNoiseImf2Share of IMF 1's (bunny00, camel, homer at 10-20%).
// A clean mesh's own detail spreads over both: IMF 1's spread over IMF 2's is at most
// kDetailImfRatio on libcgal-demo's clean meshes (femur 1.68, armadillo 1.66, bull 1.61, most
// 0.3-1.4). With s1, s2 the spreads, r = kDetailImfRatio and c = kNoiseImf2Share, IMF 1 holds at
// least sqrt(max(0, s1^2 - r^2 s2^2) / (1 - r^2 c^2)) of noise, and at most s1: 0 on clean coarse meshes, 0-0.4 of
// the estimate at 2% noise, 0.5-0.9 at 10%, about all of it beyond. It is no estimate (a regular
// mesh at 5% can read 0) and decides nothing: leaving the mesh as it is where it reads little
// was measured and not kept (it left the plugin's own default noise on some meshes).
constexpr double kDetailImfRatio = 1.7;
constexpr double kNoiseImf2Share = 0.39;

// Clean meshes without flat parts read up to this (sigma / mean edge) from their own detail at the
// edge scale: b9_mesh 0.140, bones 0.102, femur 0.102, bull 0.090 (docs/quality.md, "Goals not
// reached": that detail is as white as noise, so no reading tells the two apart). An estimate at
// or below it that no flat hinge capped may be such detail rather than noise: the filters say so.
constexpr double kCleanDetailReads = 0.15;

// An estimate whose MAD was taken over fewer IMF 1 samples than this reads anything from one noise
// draw to the next: boeing, a soup of open strips with 6 of its 2,741 vertices interior, reads
// 0.014-0.28 mean edges at 20% noise over six draws. Boundary vertices do not make up for it (their
// own estimate reads 0.55-1.0 of the truth, depending on the mesh; docs/quality.md "Goals not
// reached"): the filters say so and ask for the noise level.
constexpr int kFewImfSamples = 50;

// Part of the height noise's standard deviation (as MAD / 0.6745) that the first IMF holds,
// under the default EMD options (see above).
constexpr double kImf1Share = 1.0;

// The estimate is within what a clean mesh's own detail reads (kCleanDetailReads), above the
// noise-free reading, and not capped by flat hinges (a capped one read the noise itself).
bool may_be_surface_detail(const NoiseEstimate& estimate);

// x with P(|N(0, 1)| <= x) = q, by bisection on erf (0.1257 for q = 0.1).
double folded_normal_quantile(double q);

// Per-vertex height over the one-ring mean, along the normal (0 for vertices of no face).
Eigen::VectorXd one_ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);

// Fails on a mesh without faces or with non-finite coordinates. `cycle` is hamiltonian_cycle()
// of the same faces.
bool estimate_noise(const Positions& positions, const Faces& faces, const HamiltonianCycle& cycle,
                    const EmdOptions& emd_options, NoiseEstimate& out, std::string& error);

}  // namespace hht
