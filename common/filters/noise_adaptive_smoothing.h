// Noise-adaptive smoothing (ours, not the paper's; docs/quality.md says why and measures it):
//   1. the noise level sigma is estimated from the finest IMF of the one-ring height signal
//      along the Hamiltonian cycle (noise_estimate.h);
//   2. the positions are rebuilt by a least-squares solve in the form of the paper's eq. 9-11,
//      with zero targets for the Laplacian and its square:
//      min ||L^2 V~||^2 + mu^2 ||L V~||^2 + mu^4 ||V~ - V||^2, L the uniform Laplacian (robust on
//      slivers, and it pulls tangential noise out). Per eigenmode k of L the filter keeps
//      mu^4 / (mu^4 + mu^2 k^2 + k^4): flatter in the pass band than Taubin's lambda|mu or the
//      first-order ||L V~||^2 alone, and a gentler roll-off than the second-order Butterworth
//      mu^4 / (mu^4 + k^4), which gives a lower angle error (all measured, docs/quality.md items 2
//      and 9). The cut-off is the noise level's, mu = kMuScale / sqrt(strength
//      * sigma), sigma in mean edges, or a stronger one where generalized cross-validation finds
//      it better (cutoff_selection.h): the best cut-off depends on the surface as well as on the
//      noise, and a dense smooth mesh takes a much stronger filter than a coarse detailed one
//      (select_cutoff); its choice is made kSelectionBias stronger, since its squared risk favours
//      weaker filters than the angle error does. When the user gives the noise level
//      (unbiased_risk), the cut-off instead minimises Stein's unbiased estimate of the same risk
//      with that sigma, weaker or stronger than the noise law's (kUnbiasedRiskRange,
//      kStrongestSelected), biased the same way: the law's cut-off is too strong for a mesh whose
//      own detail at the edge scale outweighs light noise (bull at 2%: 6.28 degrees against the
//      noisy 4.92; 4.78 so chosen), and the estimate cannot be used so, since it reads that detail
//      as noise (docs/quality.md item 18).
//   3. each vertex's move along its tangent plane is capped at kTangentialCap * sigma^2 mean
//      edges: the uniform Laplacian also slides vertices of an irregular (clean) triangulation
//      towards their neighbours' centroid, which is no noise; tangential noise is of the order
//      of sigma, so light noise allows little sliding and heavy noise more; faces the cap would
//      leave tilted by more than 60 degrees keep the uncapped slide (it untangles them). The cap
//      is scaled by the share of isotropic noise's tangential part that the input's tangential
//      offsets hold (tangential_noise.h): noise along the normals has none, and there any slide
//      is error (ours, docs/quality.md item 21);
//   4. faces left folded against the surface around them get their vertices moved to their
//      one-ring centroids;
//   4b. the finish is chosen by a recorrupted risk estimate (recorrupted_risk.h): the smoothing is
//      rerun on a copy of the input with more noise added (at the cut-off the law gives that
//      noise) and finished each way allowed, and the results are compared with a second copy whose
//      noise is independent of the first's (three draws). The ways: with each face's normal
//      replaced by the mean of its neighbours' and the vertices following (face_normal_pass.h) or
//      not: well-shaped meshes keep it (small faces stand up that the cap of step 3 left tilted),
//      coarse meshes with detail at the edge scale and CAD parts with creases do not (ours,
//      docs/quality.md item 20); and, where the input's tangential offsets hold about isotropic
//      noise's (the share of step 3 is kSlideShare or more), step 3 by Taubin's slide instead of
//      the cap (the move along the normals the solve's, the move across them Taubin's smoothing's,
//      taubin_smoothing.h): its sharp roll-off takes out the finest tangential noise and drifts
//      less than a strong low-pass, which smooth regular meshes want (ours, docs/quality.md
//      item 22);
//   5. no vertex ends further than kMoveRadius * sigma * max(1, strength) mean edges from where
//      it was: Gaussian noise moved it by more than 4 sigma with a probability of about 0.1%
//      (3 degrees of freedom), while the uniform Laplacian moves a vertex with long edges (a
//      CAD part's fans) by several mean edges (turbine at 10% noise: RMS vertex error 70.7 to
//      22.8, in 1e-4 of the diagonal; ours, docs/quality.md);
//   6. faces the smoothing turned over go back to the input where they fit the smoothed surface
//      (within kRestoredFaceTilt; flip_guard.h): on clean irregular meshes these are wrinkles of
//      the triangulation, which a noisy face does not pass for (ours, docs/quality.md);
//   7. if the faces still turned over are few (kWrinkleShare of all faces at most), they are
//      wrinkles too and each goes back the least share of the way that un-turns it (flip_guard.h;
//      ours: noise turns many more, and there this step would undo the smoothing's work).
// Why not the paper's curvature filter for this: docs/quality.md (filtering along one cycle
// leaves stripes, the keep-tangential target carries the input's noise into the result, and
// the cotangent Laplacian breaks on slivers).
#pragma once

#include "filters/spike_removal.h"
#include "signal/noise_estimate.h"
#include "util/stage_clock.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace hht {

// The low-pass's first-order weight (biharmonic_low_pass.h): its gentler roll-off gives a lower
// angle error than the pure second-order filter at the best cut-off of each, and loses less where
// the cut-off is off (docs/quality.md item 9).
constexpr double kFirstOrder = 1.0;
// The noise law's scale for that filter, chosen on the ten organic meshes at 10-30% noise (lab,
// seed 11; 0.25-0.31 all better than the second-order filter's best), checked by the harness
// (docs/quality.md item 9).
constexpr double kMuScale = 0.28;
constexpr double kTangentialCap = 7.0;
// How far, in noise sigmas, the smoothing may move a vertex (times the strength above 1).
constexpr double kMoveRadius = 4.0;
// A face the smoothing turned over goes back if, put back, it is within this of the smoothed
// surface (degrees).
constexpr double kRestoredFaceTilt = 60.0;
// Step 7 runs when at most this share of the faces is still turned over: clean irregular meshes
// have 0.02-0.08% (cow, femur, bull, man), at 10% noise 0.28-1.1% (docs/quality.md item 13).
constexpr double kWrinkleShare = 0.0015;
// With the noise given, Stein's risk is searched from kUnbiasedRiskRange times weaker than the noise
// law's cut-off to kStrongestSelected times stronger.
constexpr double kUnbiasedRiskRange = 4.0;
// The cross-validated cut-off is divided by this: its squared risk has its minimum at a weaker
// filter than the mean angle error's (docs/quality.md items 5 and 10).
constexpr double kSelectionBias = 1.2;
// The weakest cut-off the cross-validation scores, relative to the noise level's (docs/quality.md).
constexpr double kWeakestSearched = 1.5;
// The strongest: the noise level's cut-off divided by this. Simple smooth surfaces take far
// stronger filters than the law's (mech-holes-shark, a cylinder: docs/quality.md item 19), but
// beyond 3 their vertex distance rises as their angle error falls (measured with the
// preconditioned solve, which costs no more for a stronger filter).
constexpr double kStrongestSelected = 3.0;
// Taubin's slide is a finish where the tangential share reads this or more: the share is read
// against sigma's estimate, which a smooth surface's own curvature lifts by a few percent, so
// isotropic noise on bear, mushroom or camel reads 0.89-0.94 (lab, seed 11); noise along the
// normals of a smoothly graded triangulation reads 0.1-0.3 (camel at 10%: 0.13). 0.8 and 0.85
// gave the same 62 of 66 organic cases below Taubin on both numbers, 0.9 60, 1 55
// (docs/quality.md item 23).
constexpr double kSlideShare = 0.85;
// How far a border vertex may move across its border, in noise sigmas (item 35): noise moves it
// about that far, and the uniform Laplacian's one-sided ring pulls it further in. Over 18 meshes
// with borders at 0-30% (lab), 0 (no move across) was better on open CAD sheets and worse on the
// rims of holes in organic meshes, 2 gained half of 1's.
constexpr double kBorderMoveAcross = 1.0;
// The face-normal pass's risk (step 4b): copies drawn, and the vertices of a large mesh it is
// scored on (breadth-first patches, like the cross-validation's), with a fixed seed so that the
// same input gets the same choice.
constexpr int kPassDraws = 3;
constexpr int kPassSampleVertices = 30000;
constexpr int kPassPatches = 8;
constexpr unsigned kPassSeed = 20261124;
// The solve stops once no vertex can be further than this, relative to the bounding-box
// diagonal, from the exact least-squares solution (a proven bound: biharmonic_low_pass.h).
constexpr double kSmoothingMaxError = 1e-5;

struct NoiseAdaptiveSmoothingOptions {
  double noise = 0;            // sigma / mean edge length; 0 or less: estimated
  double strength = 1;         // > 1 smooths more, < 1 less
  double mu = 0;               // > 0: this cut-off instead of the one the noise sets (experiments)
  bool select_cutoff = true;   // a stronger cut-off than the noise level's where cross-validation finds one
  bool unbiased_risk = false;  // `noise` is the truth (the user's): the cut-off by Stein's unbiased risk instead
  bool unturn_wrinkles = true;  // step 7 (the denoiser's untangling counts the smoothing's own turns)
  bool face_normal_pass = true;  // step 4b where its risk is lower (the denoiser's untangling: off)
  bool taubin_slide = true;      // step 3 by Taubin's slide where its risk is lower (the untangling: off)
  bool keep_untouched = true;    // impulsive noise: the vertices it left alone kept (keep_untouched_vertices.h; the denoiser does its own)
  bool tangential_share = true;  // step 3's cap scaled by the tangential noise the offsets allow (experiments: off)
  bool remove_scattered_spikes = true;  // impulsive noise read from scattered spikes: removed first (off: the despiked mesh's own run)
  bool hold_borders = true;      // border vertices move across their border by at most kBorderMoveAcross sigmas (experiments: off)
  // Experiments (bench/quality_lab, docs/quality.md items 8-10): the tangential cap's factor
  // (infinity: no cap), the noise law's scale, how much weaker than the noise law's cut-off the
  // cross-validation may choose, the low-pass's first-order weight (0: second order only), the
  // bias applied to the cross-validated cut-off (1: none), and how much stronger than the noise
  // law's cut-off either search may go (item 19).
  double tangential_cap = kTangentialCap;
  double mu_scale = kMuScale;
  double weaker_allowed = 1;
  double first_order = kFirstOrder;
  double selection_bias = kSelectionBias;
  double strongest_selected = kStrongestSelected;
  double move_radius = kMoveRadius;
  // Experiments on step 4b (docs/quality.md, "Other noise models"): only this finish (0 the cap,
  // 1 Taubin's slide, 2 the cap and the face-normal pass, 3 the slide and the pass; -1 the risk
  // chooses), and the recorrupted copies' noise scaled by this.
  int forced_finish = -1;
  double copy_noise_scale = 1;
  CycleOptions cycle;
  EmdOptions emd;
};

struct NoiseAdaptiveSmoothingReport {
  NoiseEstimate noise;         // as estimated (sigma 0 when `noise` was given)
  double sigma_used = 0;       // relative to the mean edge
  bool noise_free = false;     // the estimate read less than kNoiseFree: the result is the input
  double mu = 0;
  bool cutoff_selected = false;  // mu from cross-validation (stronger than the noise level's)
  bool cutoff_by_risk = false;   // mu from Stein's unbiased risk with the given noise
  int selection_iterations = 0;  // conjugate gradient iterations of the selection's solves
  int selection_vertices = 0;    // vertices it scored on (a sample of a large mesh)
  double max_displacement = 0;
  double rms_displacement = 0;
  double tangential_share = 1;  // step 3's cap relative to isotropic noise's (tangential_noise.h)
  int border_vertices_held = 0;  // border vertices whose move across the border was taken out (item 35)
  int unfolded_vertices = 0;   // moved to their one-ring centroid to undo a fold
  int held_vertices = 0;       // held at kMoveRadius noise sigmas from where they were
  int restored_faces = 0;      // turned over by the smoothing, put back (step 6)
  int unturned_faces = 0;      // still turned, few: moved back until no longer turned (step 7)
  bool face_normal_pass = false;  // step 4b was kept
  bool taubin_slide = false;      // step 3 took Taubin's slide instead of the cap
  int untouched_vertices_kept = 0;  // impulsive noise: vertices of exactly flat hinges kept as they were
  bool spikes_removed = false;  // impulsive noise read from scattered spikes: the result is the input despiked
  SpikeRemovalReport spike_removal;  // when spikes_removed or despiked_then_filtered
  bool despiked_then_filtered = false;  // too dense for the removal alone: its result smoothed at
                                        // despiked_noise's level (noise: the despiked mesh's estimate)
  NoiseEstimate input_noise;   // when despiked_then_filtered: the input's estimate, which read the spikes
  int finishes_scored = 0;        // finishes (step 3's two ways, with step 4b or not) scored against each other
  bool finish_risk_scored = false;  // their risks were scored (false: one finish allowed, or a copy's solve failed)
  double finish_risk_change = 0;  // the chosen finish's recorrupted risk over the plain one's (cap, no pass), minus 1
  int iterations = 0;          // conjugate gradient iterations of the solve
  double error_bound = 0;      // largest position error of the solve, at most, / bbox diagonal
  std::vector<StageTime> stages;
};

// How steps 3 and 4b are done; step 4b's recorrupted risk chooses among those the options allow.
struct SmoothingFinish {
  bool taubin_slide = false;  // step 3 by Taubin's slide, not by the cap
  bool normal_pass = false;   // step 4b
};

// Step 4b's choice: the finish of least `mean` risk (`per_draw`: each draw's risk per finish), but
// Taubin's slide only if every draw scores it below the best capped finish: its choice hangs on
// the tangential noise, which the copies know only as well as sigma's estimate, and where one draw
// says otherwise it is a near tie that the draws decide (lab: 58 of 66 organic cases below Taubin
// on both numbers, against 57 by the mean alone; docs/quality.md item 22). Without a capped
// finish: the least mean.
size_t choose_finish(const std::vector<SmoothingFinish>& finishes, const std::vector<std::vector<double>>& per_draw,
                     const std::vector<double>& mean);

bool noise_adaptive_smooth(const Positions& positions, const Faces& faces, const NoiseAdaptiveSmoothingOptions& options,
                           Positions& result, NoiseAdaptiveSmoothingReport& report, std::string& error,
                           const std::function<void(int, const char*)>& progress = {});

}  // namespace hht
