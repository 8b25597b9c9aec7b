// Feature-preserving denoising by the HHT (the paper's sec. 4.3, Figs. 4, 8-10): sharp
// features are detected and linked into feature lines; the curvature signal is then processed
// by divide and conquer:
//   - the cycle's signal is sifted with feature vertices never taken as extrema, so the
//     envelopes, and thus the IMFs of the smooth regions, are not bent by the creases, and is
//     low-pass filtered on instantaneous frequency (averaged over several cycles);
//   - each feature line is its own 1D signal (periodic when the line is closed), decomposed and
//     low-pass filtered the same way; a line too short for EMD is smoothed by a 1D Laplacian;
//   - corners take the mean signal of the corners of their type (same number of lines, same sign);
// then the mesh is rebuilt from the recombined signal by the Laplacian least-squares solve.
//
// What is ours (docs/quality.md measures each part and says why):
//  - the noise level is estimated first, from the finest IMF of the one-ring height signal along
//    the cycle (noise_estimate.h);
//  - untangling: noise with a tangential part (a scanner's) folds small triangles over, which no
//    normal filter repairs; when more than kTangledShare of the faces point away from those of the
//    noise-adaptive smoothing (noise_adaptive_smoothing.h), the smoothed mesh is the start;
//  - refinement: face normals cleaned by guided normal filtering, which keeps creases, and the
//    vertices fitted to them (Sun et al. 2007), in rounds whose number the noise sets (below
//    5% of the mean edge, one round of fewer passes)
//    (guided_normal_denoise.h); the filter's range width is kRefineSmoothSigma away from the
//    creases of the noise-level smoothing (faces_near_creases.h, kCreaseDihedral): at the creases
//    the narrow width keeps them, elsewhere the surface's own curvature needs the wide one; a
//    face the refinement turns over against its start (the input, or the untangling's
//    smoothing), which noise has not folded, is its own fold: it is stood back up (flip_guard.h);
//    the last round the noise asks for (and any after it) is bilateral normal filtering instead
//    (Zheng et al. 2011: the range kernel on each face's own normal, kOwnNormalSigma wide): once
//    the patch guidance has taken heavy noise down, or at light noise from the start, it keeps
//    small features and creases that the patches blur; from the untangling's smoothing, which
//    has little noise left, every round is (docs/quality.md item 16); from one round's noise on,
//    or from the untangled start, the vertices are fitted after every pass (kFitEachPassIterations);
//  - the refined mesh's planar regions are made flat (planar_regions.h; docs/quality.md item 36);
//  - surfaces without sharp creases (crease_contrast.h of the smoothed mesh below kNoCreaseContrast,
//    and its crease lines shorter than kCreaseLines: a finely meshed part's creases are too few
//    edges for the contrast's percentile, item 28)
//    get the adaptive smoothing, cross-validated cut-off, as the result instead: the refinement
//    facets them; between kNoCreaseContrast and kCreaseContrast, where the reading is uncertain,
//    a blend of the two (item 32); not a mesh with exactly flat parts (its noise estimate capped
//    by the flat hinges) that needed no untangling: a lightly noisy coarse CAD part, whose
//    few-vertex creases the smoothing of the crease contrast flattens; nor, at heavy noise
//    (kCreaseRevealNoise) or in the uncertain band, one whose (trial) refinement brings back flat
//    faces meeting at creases (kRevealedCreaseContrast);
//  - a mesh that the noise-level smoothing moves further than the noise did (kDistortingMoveHigh) is
//    refined from its input, neither untangled nor smoothed, unless a tenth of its faces are folded
//    (kHeavilyFoldedLow/High): on a coarse CAD export, whose features are a few edges wide, the smoothing
//    turns faces over by itself, which the tangle test took for noise, and flattens the features,
//    which no refinement brings back (docs/quality.md item 17); where the move (from
//    kDistortingMoveLow) or the folded share (from kHeavilyFoldedLow) is uncertain, that result and
//    the usual route's are blended (items 33, 34);
//  - the paper's HHT stage above is off by default (paper_stage): measured, it makes the result
//    worse than the refinement alone on most cases (docs/quality.md).
#pragma once

#include "cycle/feature_lines.h"
#include "mesh/sharp_features.h"
#include "filters/guided_normal_denoise.h"
#include "filters/noise_adaptive_smoothing.h"
#include "filters/spectral_mesh_filter.h"
#include "reconstruction/planar_regions.h"

namespace hht {

// Share of faces flipped against the smoothed mesh above which the denoiser starts from it.
constexpr double kTangledShare = 0.0075;
// Noise (sigma / mean edge) per refinement round: rounds = max(1, round(sigma / this)); below
// half a round's noise, one round whose normal passes shrink in proportion to the noise, so a
// clean curved mesh is not faceted (clean homer: 9.2 degrees with a full round).
constexpr double kNoisePerRound = 0.1;

// The refinement's rounds (when set by the noise) are cut short and extended by how far each
// moves the mesh (RMS, in sigma * mean edge), measured after the first: a round within the noise's
// count (sigma / kNoisePerRound, unrounded: item 29) that moves it by more than kRoundDriftStep
// is undone and ends the refinement (the guided
// filter re-faceting curved parts of an irregular mesh: each such round adds error on turbine
// and anchor_dense); after that count, up to kExtraRoundsFactor times as many rounds go on while
// each moves it by less than kRoundConvergedStep (converging onto flat pieces: cube, blade).
// docs/quality.md item 11.
constexpr double kRoundDriftStep = 0.18;
constexpr double kRoundConvergedStep = 0.10;
constexpr double kExtraRoundsFactor = 1.5;

// Thin faces: the noise tilts a face by about sigma over its altitude, not over the mean edge. On
// a mesh whose faces' median altitude (median_face_altitude) is under kSliverAltitude mean edges,
// the rounds after the noise's count may go on, while each converges, up to kExtraRoundsFactor
// times the count taken against that altitude (sigma * kSliverAltitude / altitude) instead of
// the mean edge. Blade, long slivers of median altitude 0.14: three to five rounds instead of one
// or two, 1.2-5 degrees lower at 10-30% (docs/quality.md item 41). The factor is at most
// kMaxSliverFactor: on a soup of needles the rounds stay bounded.
constexpr double kSliverAltitude = 0.55;
constexpr double kMaxSliverFactor = 4.0;

// From one round's noise on (sigma >= kNoisePerRound), or from the untangled start, the refinement
// fits the vertices after every normal pass, kFitEachPassIterations vertex update iterations each,
// as the guided filter's authors do, instead of once after all passes: heavy noise, or noise that
// folded the triangulation, leaves normals that no surface takes (slivers, tangles), and filtering
// them on is wasted. At lighter noise the one fit stays: fitting after every pass multiplies the
// vertex updates, which facet curved parts (docs/quality.md item 24).
constexpr int kFitEachPassIterations = 10;

// The refinement may move vertices by at most this times the noise's RMS (sqrt(3) sigma); a
// larger move is scaled down to it.
constexpr double kRefineMoveToNoise = 0.75;

// Below kNoCreaseContrast (crease_contrast.h of the noise-level smoothing) the surface has no sharp
// creases and the result is the adaptive smoothing (cross-validated cut-off) instead of the
// refinement; from kCreaseContrast on it has creases and is refined; in between the two results are
// blended, the smoothing's share falling linearly from 1 to 0 across the band. The corpus's organic
// meshes read 5-9, its CAD parts with creases 9.5-22; lion-head reads 8.1-9.4 and mannequin-devil
// 9-11 from one noise draw to the next, where the blend beats both results (docs/quality.md item 32).
constexpr double kNoCreaseContrast = 8.5;
constexpr double kCreaseContrast = 11.0;
// ... unless its crease lines (crease_contrast.h) are at least this long: the creases of a
// finely meshed part, too few edges for the contrast's percentile (fandisk with every triangle cut
// in 16 reads 3.7-5.8 at 2-30% noise, the meshed cube so cut 3.8; organic meshes read at most 1.0
// where their contrast is below 9, lion-head at 2%; docs/quality.md item 28).
constexpr double kCreaseLines = 2.0;

// From this noise on (sigma / mean edge), a surface read without sharp creases is given a trial
// refinement (the vertices fitted once a round: half the time), and is refined after all
// where the trial's result reads a crease contrast (crease_contrast.h) of at least
// kRevealedCreaseContrast: flat faces meeting at sharp creases. Heavy noise flattens the creases
// of a flat-faced part's smoothing into the organic range (fandisk at 70% reads 7.3), which no
// reading of the smoothing tells apart (item 30); the trial on such parts reads 78-150 where on
// organic meshes and coarse CAD exports it reads at most 40 (docs/quality.md item 31). Below this
// noise the smoothing's contrast was right (the parts read below 9 only from 0.31 on), and the trial would cost its time on every organic mesh for nothing.
constexpr double kCreaseRevealNoise = 0.25;
constexpr double kRevealedCreaseContrast = 60.0;

// The noise-level smoothing distorts a mesh whose features are a few edges wide (a coarse CAD
// export): it moves it by more than the noise's RMS (sqrt(3) sigma) times kDistortingMoveHigh, where
// on the corpus's organic and CAD meshes it moves it by at most 0.96 of it. Such a mesh is refined
// from its input, neither untangled nor smoothed, unless at least kHeavilyFoldedHigh of its faces are
// folded against their corners' normals (heavy tangential noise, which only the smoothing
// undoes). docs/quality.md item 17. From kDistortingMoveLow to kDistortingMoveHigh the reading is
// uncertain: coarse exports read 0.8-1.5, one mesh on both sides of a threshold from one noise draw
// to the next, and which result serves it better does not follow the reading; there both run and
// are blended, the share of the refinement from the input rising linearly across the band (organic
// meshes with fewer than kHeavilyFoldedLow folded read at most 0.89; item 33). The folded share is
// read with a band too, from kHeavilyFoldedLow to kHeavilyFoldedHigh, where the refinement from the
// input's share falls linearly (coarse exports read on both sides of a tenth from one noise draw to
// the next; item 34).
constexpr double kDistortingMoveLow = 0.9;
constexpr double kDistortingMoveHigh = 1.1;
constexpr double kHeavilyFoldedLow = 0.08;
constexpr double kHeavilyFoldedHigh = 0.12;

// The refinement's range width on faces not within one ring of an edge sharper than
// kCreaseDihedral degrees on the noise-level smoothing (docs/quality.md item 14): the narrow
// width there (refine_normal_sigma) left turbine's curved blades faceted.
constexpr double kRefineSmoothSigma = 0.45;
constexpr double kCreaseDihedral = 30.0;

// The range width of the refinement's last round, on each face's own unit normal (bilateral
// normal filtering's authors' default; 0.3 and 0.45 measured worse: docs/quality.md item 16).
constexpr double kOwnNormalSigma = 0.35;

// The untangling's smoothing (and the crease contrast measured on it) keeps the second-order
// filter at the noise law's scale that the refinement, kTangledShare and kCreaseContrast were
// measured with: with the adaptive smoothing's first-order term as the start, the refinement did
// worse on fandisk and the meshed cube at 20-30% isotropic noise (docs/quality.md item 9).
constexpr double kUntangleFirstOrder = 0.0;
constexpr double kUntangleMuScale = 0.233;

struct DenoiseOptions {
  bool paper_stage = false;     // the paper's divide-and-conquer HHT stage before the refinement
  bool remove_scattered_spikes = true;  // impulsive noise read from scattered spikes: removed first
                                        // (filters/spike_removal.h; off: the despiked mesh's own run)
  double noise = 0;             // sigma / mean edge length; 0 or less: estimated
  bool untangle = true;         // start from the noise-adaptive smoothing when the input is tangled
  bool hold_borders = true;     // both smoothings hold border vertices (noise_adaptive_smoothing.h; experiments: off)
  double untangle_first_order = kUntangleFirstOrder;  // that smoothing's filter (experiments)
  double untangle_mu_scale = kUntangleMuScale;
  bool smooth_surfaces_by_smoothing = true;  // no sharp creases (kNoCreaseContrast): the adaptive smoothing
                                             // (not with the paper's stage: that asks for the paper's method)
  bool refine_flat_parts = true;  // a mesh with exactly flat parts (its noise estimate capped by the
                                  // flat hinges: a CAD part) keeps the refinement unless untangled;
                                  // with the noise given (no estimate) the rule cannot apply
  bool refine_where_smoothing_distorts = true;  // kDistortingMoveLow/High, kHeavilyFoldedLow/High (items 17, 33, 34)
  bool detect_features = true;  // false: the torus-like case, no feature separation (Fig. 8)
  bool show_features = false;   // detect them for the caller (report.type, feature_lines) even where
                                // no stage uses them; otherwise only the paper's stage asks for them
  SharpFeatureOptions features;
  CycleOptions cycle;
  int cycles = 4;             // cycles whose filtered non-feature signals are averaged
  EmdOptions emd;
  double cutoff = 0.05;       // instantaneous frequencies above this are removed (cycles per sample)
  int short_line_passes = 10; // 1D Laplacian passes on feature lines too short for EMD
  ReconstructionOptions reconstruction = [] {
    ReconstructionOptions o;
    o.lambda = 1.0;
    return o;
  }();
  int refine_rounds = 0;              // 0: set by the noise (kNoisePerRound) and by each round's move
  int refine_normal_passes = 8;       // guided normal filtering passes per round; 0: no refinement
  double refine_normal_sigma = 0.25;  // range width of that filter, on unit normals (~15 degrees)
  double refine_smooth_sigma = kRefineSmoothSigma;  // away from creases; at most refine_normal_sigma: one width everywhere
  bool refine_unturn = true;  // faces the refinement turns over against its start stood back up (item 15)
  bool flatten_planar_regions = true;  // the refined part's planar regions made flat (planar_regions.h, item 36)
  PlanarRegionOptions planar_regions;   // their thresholds (experiments)
  int refine_vertex_iterations = 20;  // vertex update iterations towards the filtered normals
  bool refine_own_normals = true;  // the last round(s), every round when untangled, on the faces' own normals (item 16)
  bool refine_fit_each_pass = true;  // from kNoisePerRound's noise on or untangled, vertices fitted after every pass (item 24)
  double refine_drift_step = kRoundDriftStep;        // with rounds set by the noise (experiments)
  double refine_converged_step = kRoundConvergedStep;
  double refine_extra_rounds_factor = kExtraRoundsFactor;
  double refine_sliver_altitude = kSliverAltitude;  // 0: the count against the mean edge alone (experiments)
  double distorting_move_low = kDistortingMoveLow;  // the uncertain band of item 17's rule (experiments)
  double distorting_move_high = kDistortingMoveHigh;
  double folded_low = kHeavilyFoldedLow;  // the folded share's band of item 17's rule (experiments)
  double folded_high = kHeavilyFoldedHigh;
  double tangled_share = kTangledShare;  // the untangling's gate (experiments)
  double no_crease_contrast = kNoCreaseContrast;  // the uncertain band of the route (experiments)
  double crease_contrast = kCreaseContrast;
};

struct DenoiseReport {
  NoiseEstimate noise;         // the estimate (sigma 0 when the noise was given)
  double sigma_used = 0;       // relative to the mean edge
  bool untangled = false;      // started from the noise-adaptive smoothing
  int flipped_faces = 0;       // input faces flipped against that smoothing
  double smoothing_move = 0;   // that smoothing's RMS move, in noise RMS (sqrt(3) sigma)
  int folded_faces = 0;        // input faces folded against their corners' normals
  double crease_contrast = 0;  // of that smoothing (0: not measured)
  double crease_lines = 0;     // its crease lines' length (crease_contrast.h; 0: not measured)
  bool noise_free = false;     // the estimate read less than kNoiseFree: the result is the input
  double smoothing_weight = 0;  // the adaptive smoothing's share of the result: 1 when smoothed_instead(),
                                // between 0 and 1 when blended with the refinement (uncertain creases)
  bool smoothed_instead() const { return smoothing_weight == 1; }  // no sharp creases: the result is the adaptive smoothing
  double refined_crease_contrast = 0;  // the crease contrast of the refinement tried (no sharp creases read,
                                       // at kCreaseRevealNoise or more) or blended (uncertain creases); 0: none
  bool creases_revealed = false;  // ... at least kRevealedCreaseContrast: the refinement alone is the result
  NoiseAdaptiveSmoothingReport smoothing;  // when smoothing_weight > 0: that smoothing's report
  bool flat_parts_refined = false;  // no sharp creases read, but flat parts: refined all the same
  double distort_weight = 0;  // the refinement from the input's share of the result: 1 when smoothing_distorts(),
                              // between 0 and 1 when blended with the usual route (an uncertain move, item 33; the
                              // rest of the report is that route's)
  // The noise-level smoothing moved the mesh beyond the noise: refined from the input.
  bool smoothing_distorts() const { return distort_weight == 1; }
  int refine_rounds_asked = 0;   // given, or set by the noise
  int refine_rounds_allowed = 0;  // the most that were allowed while converging (with thin faces more)
  double refine_median_altitude = 0;  // of the refinement's start, in mean edges (with rounds set by the noise)
  int refine_rounds = 0;         // done
  std::vector<double> refine_steps;  // with rounds set by the noise: the move of each round after the
                                     // first (RMS, in sigma * mean edge)
  bool refine_round_undone = false;  // the last of refine_steps was undone and ended the rounds
  int refine_normal_passes = 0;  // per round, as used
  bool refine_fit_each_pass = false;  // the vertices were fitted after every pass (kFitEachPassIterations)
  double refine_scaled = 1;      // < 1: the refinement's move was scaled down to the noise's RMS
  double refine_near_creases = -1;  // share of the faces given the narrow range width (-1: one width for all)
  int refine_unturned_faces = 0;  // turned over by the refinement against its start, stood back up
  int planar_regions = 0;        // of the refined mesh, made flat (item 36)
  int planar_region_faces = 0;   // in them
  int planar_fit_iterations = 0;  // of the vertex update that made them flat (item 37)
  int refine_own_normal_rounds = 0;  // rounds done with the range kernel on the faces' own normals
  int untouched_vertices_kept = 0;  // impulsive noise: vertices of exactly flat hinges kept as they were (keep_untouched_vertices.h)
  bool spikes_removed = false;  // impulsive noise read from scattered spikes: the result is the input despiked
  SpikeRemovalReport spike_removal;  // when spikes_removed or despiked_then_filtered (filters/spike_removal.h)
  bool despiked_then_filtered = false;  // too dense for the removal alone: its result denoised at
                                        // despiked_noise's level (noise: the despiked mesh's estimate)
  NoiseEstimate input_noise;   // when despiked_then_filtered: the input's estimate, which read the spikes
  bool features_detected = false;  // report.type and feature_lines hold the input's features
  int feature_vertices = 0;
  int corners = 0;
  int lines = 0;
  int lines_by_emd = 0;        // long enough for EMD; the others were smoothed by a 1D Laplacian
  HamiltonianCycle cycle;      // the first cycle
  std::vector<ImfSummary> imfs;  // of the first cycle's non-feature signal
  ReconstructionReport reconstruction;
  std::vector<StageTime> stages;
  std::vector<FeatureType> type;  // per vertex
  FeatureLines feature_lines;
};

bool feature_preserving_denoise(const Positions& positions, const Faces& faces, const DenoiseOptions& options,
                                Positions& result, DenoiseReport& report, std::string& error,
                                const Progress& progress = {});

}  // namespace hht
