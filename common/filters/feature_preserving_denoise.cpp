#include "filters/feature_preserving_denoise.h"

#include "mesh/crease_contrast.h"
#include "mesh/face_geometry.h"
#include "mesh/faces_near_creases.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/flip_guard.h"

#include "mesh/mesh_checks.h"
#include "evaluation/gaussian_noise.h"
#include "filters/guided_normal_denoise.h"
#include "reconstruction/planar_regions.h"
#include "reconstruction/keep_untouched_vertices.h"
#include "reconstruction/normal_vertex_update.h"

#include <algorithm>
#include <map>

namespace hht {

namespace {

using Step = std::function<void(int, const char*)>;  // progress: percent and stage

// A low-pass filtered copy of a 1D signal, or nothing when EMD finds no IMF in it.
bool low_pass(const std::vector<double>& signal, SignalBoundary boundary, const EmdOptions& base, double cutoff,
              std::vector<double>& out) {
  EmdOptions o = base;
  o.boundary = boundary;
  const EmdResult e = emd(signal, o);
  if (e.imfs.empty()) return false;
  HilbertTransformer t(static_cast<int>(signal.size()));
  std::vector<HilbertSpectrum> spectra;
  for (const auto& imf : e.imfs) spectra.push_back(t.spectrum(imf, boundary));
  out = filter_by_frequency(e, spectra, {cutoff, 0.5, false}, 0.0);
  return true;
}

// Repeated (1/4, 1/2, 1/4) averaging along a line; the ends of an open line average with
// their one neighbour.
std::vector<double> laplacian_smoothing(std::vector<double> s, bool closed, int passes) {
  const size_t n = s.size();
  if (n < 3) return s;
  std::vector<double> next(n);
  for (int p = 0; p < passes; ++p) {
    for (size_t i = 0; i < n; ++i) {
      const bool first = i == 0, last = i + 1 == n;
      const double left = first ? (closed ? s[n - 1] : s[i]) : s[i - 1];
      const double right = last ? (closed ? s[0] : s[i]) : s[i + 1];
      next[i] = 0.25 * left + 0.5 * s[i] + 0.25 * right;
    }
    s.swap(next);
  }
  return s;
}

// The paper's sec. 4.3 on `positions` (features already in `report`), rebuilt into `result`.
bool paper_stage(const Positions& positions, const Faces& faces, const DenoiseOptions& options, Positions& result,
                 DenoiseReport& report, StageClock& clock, const Step& step,
                 std::string& error) {
  const int n = static_cast<int>(positions.rows());
  std::vector<unsigned char> is_feature(n, 0);
  for (int v = 0; v < n; ++v) is_feature[v] = report.type[v] != FeatureType::None;

  step(20, "Curvature signal");
  MeanCurvature curvature;
  if (!mean_curvature(positions, faces, curvature, error)) return false;
  const Eigen::VectorXd& g = curvature.signal;
  clock.done("signal");

  // Non-feature signal: sifted with feature vertices masked, low-passed, averaged over cycles.
  Eigen::VectorXd filtered = Eigen::VectorXd::Zero(n);
  const int cycles = std::max(1, options.cycles);
  for (int k = 0; k < cycles; ++k) {
    step(25 + 35 * k / cycles, "Hamiltonian cycle and EMD of the non-feature signal");
    HamiltonianCycle cycle;
    CycleOptions seeded = options.cycle;
    seeded.seed = options.cycle.seed + 7919 * k;
    if (!hamiltonian_cycle(faces, n, seeded, cycle, error)) return false;
    std::vector<std::vector<double>> per_segment;
    const auto segments = signals_along_cycle(cycle, g);
    for (size_t s = 0; s < segments.size(); ++s) {
      std::vector<unsigned char> mask;
      for (int i = cycle.segment_begin[s]; i < cycle.segment_begin[s + 1]; ++i) mask.push_back(is_feature[cycle.order[i]]);
      EmdOptions o = options.emd;
      o.never_extremum = &mask;
      o.boundary = SignalBoundary::Periodic;
      const EmdResult e = emd(segments[s], o);
      std::vector<HilbertSpectrum> spectra;
      if (!e.imfs.empty()) {
        HilbertTransformer t(static_cast<int>(segments[s].size()));
        for (const auto& imf : e.imfs) spectra.push_back(t.spectrum(imf, SignalBoundary::Periodic));
      }
      if (k == 0 && s == 0) {
        CycleDecomposition d;
        d.emd.push_back(e);
        d.spectra.push_back(spectra);
        report.imfs = summarize_imfs(d);
      }
      per_segment.push_back(filter_by_frequency(e, spectra, {options.cutoff, 0.5, false}, 0.0));
      for (size_t j = 0; j < per_segment.back().size(); ++j) per_segment.back()[j] -= segments[s][j];
    }
    filtered += g + values_on_vertices(cycle, per_segment, faces, Eigen::VectorXd::Zero(n));
    if (k == 0) report.cycle = std::move(cycle);
  }
  filtered /= cycles;
  clock.done("non-feature signal");

  // Feature lines: each its own signal (corners excluded; they are averaged below).
  step(65, "Feature line signals");
  const FeatureLines& fl = report.feature_lines;
  for (size_t l = 0; l < fl.lines.size(); ++l) {
    std::vector<int> vertices;
    for (int v : fl.lines[l])
      if (report.type[v] != FeatureType::Corner) vertices.push_back(v);
    if (vertices.empty()) continue;
    std::vector<double> signal, out;
    for (int v : vertices) signal.push_back(g[v]);
    const bool closed = fl.closed[l] != 0;
    if (low_pass(signal, closed ? SignalBoundary::Periodic : SignalBoundary::Open, options.emd, options.cutoff, out))
      ++report.lines_by_emd;
    else
      out = laplacian_smoothing(signal, closed, options.short_line_passes);
    for (size_t i = 0; i < vertices.size(); ++i) filtered[vertices[i]] = out[i];
  }
  // Feature vertices on no line (chains too short to link) keep the cycle's filtered value.
  // Corners: the mean over corners of the same type (valence and convexity).
  std::map<std::pair<int, bool>, std::pair<double, int>> by_type;
  for (size_t c = 0; c < fl.corners.size(); ++c) {
    auto& acc = by_type[{fl.corner_valence[c], g[fl.corners[c]] >= 0}];
    acc.first += g[fl.corners[c]];
    ++acc.second;
  }
  for (size_t c = 0; c < fl.corners.size(); ++c) {
    const auto& acc = by_type[{fl.corner_valence[c], g[fl.corners[c]] >= 0}];
    filtered[fl.corners[c]] = acc.first / acc.second;
  }
  clock.done("feature signals");

  step(70, "Reconstruction");
  if (!reconstruct_positions(positions, faces, curvature, filtered, options.reconstruction, result, report.reconstruction,
                             error))
    return false;
  clock.done("reconstruction");

  return true;
}

// The refinement of `result` in place: guided normal filtering and vertex update in rounds (see
// the header), progress from `from` to `to` percent. `near_creases` (of the noise-level smoothing;
// empty: one range width) and report.untangled as the route found them.
bool refine(const Faces& faces, const DenoiseOptions& options, double sigma, double edge,
            const std::vector<unsigned char>& near_creases, Positions& result, DenoiseReport& report,
            const Step& step, int from, int to, std::string& error) {
  // Below half a round's noise, one round with passes in proportion to the noise: light noise
  // (Fandisk at 5%) is still cleaned, a clean curved mesh is not faceted.
  int normal_passes = options.refine_normal_passes;
  const bool rounds_by_noise = options.refine_rounds <= 0;
  report.refine_rounds_asked = options.refine_rounds;
  if (rounds_by_noise) {
    report.refine_rounds_asked = std::max(1, static_cast<int>(std::lround(sigma / kNoisePerRound)));
    if (sigma < 0.5 * kNoisePerRound)
      normal_passes = static_cast<int>(std::lround(normal_passes * sigma / (0.5 * kNoisePerRound)));
  }
  report.refine_normal_passes = normal_passes;
  if (normal_passes > 0 && options.refine_vertex_iterations > 0) {
    step(from, "Refinement: guided normal filtering and vertex update");
    GuidedNormalDenoiseOptions refine;
    refine.rounds = 1;
    refine.normal_passes = normal_passes;
    refine.sigma = options.refine_normal_sigma;
    if (!near_creases.empty() && options.refine_smooth_sigma > options.refine_normal_sigma) {
      refine.face_sigma.resize(near_creases.size());
      for (size_t f = 0; f < near_creases.size(); ++f)
        refine.face_sigma[f] = near_creases[f] ? options.refine_normal_sigma : options.refine_smooth_sigma;
      report.refine_near_creases =
          static_cast<double>(std::count(near_creases.begin(), near_creases.end(), 1)) / static_cast<double>(near_creases.size());
    }
    refine.vertex_iterations = options.refine_vertex_iterations;
    report.refine_fit_each_pass = options.refine_fit_each_pass && (sigma >= kNoisePerRound || report.untangled);
    if (report.refine_fit_each_pass) {
      refine.fit_each_pass = true;
      refine.vertex_iterations = kFitEachPassIterations;
    }
    const Positions rebuilt = result;
    // Rounds set by the noise end early at one that drifts, and go on (up to kExtraRoundsFactor times
    // as many) while each converges (kRoundDriftStep, kRoundConvergedStep); a given count is done as is.
    // On thin faces (kSliverAltitude) the extra rounds follow the count against their altitude.
    const int asked = report.refine_rounds_asked;
    int converging = asked;
    if (rounds_by_noise && options.refine_sliver_altitude > 0) {
      report.refine_median_altitude = median_face_altitude(result, faces) / edge;
      const double thin = std::clamp(options.refine_sliver_altitude / report.refine_median_altitude, 1.0, kMaxSliverFactor);
      converging = std::max(asked, static_cast<int>(std::lround(sigma * thin / kNoisePerRound)));
    }
    const int max_rounds =
        rounds_by_noise ? std::max(converging, static_cast<int>(std::lround(options.refine_extra_rounds_factor * converging)))
                        : asked;
    report.refine_rounds_allowed = max_rounds;
    GuidedNormalDenoiseOptions own;  // the last rounds: bilateral normal filtering, one width
    own.normal_passes = refine.normal_passes;
    own.vertex_iterations = refine.vertex_iterations;
    own.fit_each_pass = refine.fit_each_pass;
    own.sigma = kOwnNormalSigma;
    own.guidance = NormalGuidance::OwnNormal;
    for (int round = 0; round < max_rounds; ++round) {
      const bool own_normals = options.refine_own_normals && (round >= asked - 1 || report.untangled);
      Positions next;
      if (!guided_normal_denoise(result, faces, own_normals ? own : refine, next, error, [&](double done) {
            step(from + static_cast<int>((to - from) * (round + done) / max_rounds),
                 "Refinement: guided normal filtering and vertex update");
          }))
        return false;
      if (round > 0 && rounds_by_noise && sigma * edge > 0) {
        const double moved = std::sqrt((next - result).rowwise().squaredNorm().mean()) / (sigma * edge);
        report.refine_steps.push_back(moved);
        // The noise's count unrounded: rounded, blade's second round at 20% was judged as drifting
        // or converging by a sigma of 0.1502 or 0.1497 (docs/quality.md item 29).
        const bool within_count = round < sigma / kNoisePerRound;
        report.refine_round_undone = moved > (within_count ? options.refine_drift_step : options.refine_converged_step);
        if (report.refine_round_undone) break;
      }
      result.swap(next);
      ++report.refine_rounds;
      report.refine_own_normal_rounds += own_normals;
    }
    // Discrepancy bound: the refinement removes noise, so it may move vertices by about the
    // noise's RMS and no more; more is the guided filter faceting curved parts of the surface.
    const double allowed = kRefineMoveToNoise * std::sqrt(3.0) * sigma * edge;
    const double moved = std::sqrt((result - rebuilt).rowwise().squaredNorm().mean());
    if (moved > allowed) {
      result = rebuilt + (result - rebuilt) * (allowed / moved);
      report.refine_scaled = allowed / moved;
    }
    // The start has no folds but the noise's own (left out): a face the vertex update turned
    // over against it is a fold the refinement made (slivers at creases; docs/quality.md item 15).
    if (options.refine_unturn) report.refine_unturned_faces = unturn_few_turned_faces(rebuilt, faces, 1.0, result);
  }
  return true;
}

// The sharp features of `positions` into the report: for the paper's stage and for showing them;
// nothing else needs them, and on a large mesh they cost as much as the smoothing
// (docs/benchmarks.md).
bool detect_features(const Positions& positions, const Faces& faces, const DenoiseOptions& options, DenoiseReport& report,
                     StageClock& clock, const Step& step, int percent, std::string& error) {
  step(percent, "Sharp feature detection");
  if (!detect_sharp_features(positions, faces, options.features, report.type, error)) return false;
  report.feature_lines = link_feature_lines(positions, faces, report.type);
  report.feature_vertices =
      static_cast<int>(std::count_if(report.type.begin(), report.type.end(), [](FeatureType t) { return t != FeatureType::None; }));
  report.lines = static_cast<int>(report.feature_lines.lines.size());
  report.corners = static_cast<int>(report.feature_lines.corners.size());
  report.features_detected = true;
  clock.done("features");
  return true;
}

bool show_features_and_finish(const Positions& positions, const Faces& faces, const DenoiseOptions& options,
                              DenoiseReport& report, StageClock& clock, const Step& step, std::string& error) {
  if (options.detect_features && options.show_features && !detect_features(positions, faces, options, report, clock, step, 99, error))
    return false;
  step(100, "Done");
  return true;
}

// The refined `result`'s planar regions made flat (item 36); faces this turns over against the
// refinement's `start` are stood back up, as the refinement's own are.
bool flatten_planar_parts(const Positions& start, const Faces& faces, const DenoiseOptions& options, Positions& result,
                          DenoiseReport& report, StageClock& clock, std::string& error) {
  if (!options.flatten_planar_regions) return true;
  Positions flat;
  PlanarRegionReport planar;
  if (!flatten_planar_regions(result, faces, options.planar_regions, flat, planar, error)) return false;
  if (planar.regions > 0 && options.refine_unturn)
    report.refine_unturned_faces += unturn_few_turned_faces(start, faces, 1.0, flat);
  result.swap(flat);
  report.planar_regions = planar.regions;
  report.planar_region_faces = planar.faces;
  report.planar_fit_iterations = planar.fit_iterations;
  clock.done("planar regions");
  return true;
}

// `start` refined into `result`, after the paper's stage when asked for.
bool refine_from(const Positions& positions, const Positions& start, const Faces& faces, const DenoiseOptions& options,
                 double sigma, double edge, const std::vector<unsigned char>& near_creases, Positions& result,
                 DenoiseReport& report, StageClock& clock, const Step& step, std::string& error) {
  const int from = options.paper_stage ? 70 : report.creases_revealed ? 50 : 30;
  if (options.detect_features && (options.paper_stage || options.show_features) &&
      !detect_features(positions, faces, options, report, clock, step, report.creases_revealed ? 51 : 31, error))
    return false;
  result = start;
  if (options.paper_stage && !paper_stage(start, faces, options, result, report, clock, step, error)) return false;
  if (!refine(faces, options, sigma, edge, near_creases, result, report, step, from, 99, error)) return false;
  if (report.refine_normal_passes > 0 && options.refine_vertex_iterations > 0) {
    clock.done("refinement");
    if (!flatten_planar_parts(start, faces, options, result, report, clock, error)) return false;
  }
  step(100, "Done");
  return true;
}

// The routes after the untangling smoothing (`smoothed`, its dihedral `angles`, read into `report`)
// with `distort_weight` 0 or 1 (item 17): by the smoothing's creases to the adaptive smoothing, the
// refinement or a blend of both. Progress from 30 percent.
bool denoise_after_untangling(const Positions& positions, const Faces& faces, const DenoiseOptions& options, double sigma,
                              double edge, const Positions& smoothed, const std::vector<DihedralAngle>& angles,
                              double distort_weight, Positions& result, DenoiseReport& report, const Step& step,
                              std::string& error) {
  StageClock clock(report.stages);
  report.distort_weight = distort_weight;
  report.untangled = options.untangle && !report.smoothing_distorts() &&
                     report.flipped_faces > options.tangled_share * static_cast<double>(faces.rows());
  const Positions& start = report.untangled ? smoothed : positions;
  // A surface without sharp creases (organic): the guided refinement, made for creases, would
  // facet it; the adaptive smoothing with its cross-validated cut-off is the better result. Long
  // crease lines are creases too, however few of the edges they hold (a finely meshed part).
  const bool creases = report.crease_contrast >= options.crease_contrast || report.crease_lines >= kCreaseLines;
  report.flat_parts_refined = !creases && options.refine_flat_parts && report.noise.capped() && !report.untangled;
  const bool may_smooth = options.smooth_surfaces_by_smoothing && !options.paper_stage && !creases &&
                          !report.flat_parts_refined && !report.smoothing_distorts();
  const bool refinement_on = options.refine_normal_passes > 0 && options.refine_vertex_iterations > 0;
  // Between no_crease_contrast and crease_contrast the reading is uncertain (organic meshes with
  // sharp details and CAD parts with soft creases read there, and one mesh reads on both sides of
  // a threshold from one noise draw to the next): the refinement and the smoothing are blended,
  // the smoothing's share falling across the band, which beats either result alone on most such
  // meshes (docs/quality.md item 32).
  const bool uncertain = may_smooth && refinement_on && report.crease_contrast >= options.no_crease_contrast;
  // Heavy noise flattens the creases of a flat-faced part's smoothing into the organic range: a
  // refinement is tried, and where it brings back flat faces meeting at creases the surface is
  // refined after all. The trial fits the vertices once a round, half the full refinement's
  // time, and reads the same (docs/quality.md item 31). In the uncertain band the refinement
  // itself is read so.
  const bool try_refinement = may_smooth && refinement_on && !uncertain && sigma >= kCreaseRevealNoise;
  std::vector<unsigned char> near_creases;  // of the noise-level smoothing, for the refinement's range widths
  if (!may_smooth || try_refinement || uncertain) near_creases = faces_near_creases(angles, faces, smoothed.rows(), kCreaseDihedral);
  Positions refined;  // tried or blended
  if (try_refinement || uncertain) {
    refined = start;
    DenoiseOptions refinement = options;  // the trial fits the vertices once a round
    refinement.refine_fit_each_pass = options.refine_fit_each_pass && uncertain;
    DenoiseReport trial_report;  // the trial's rounds are not the result's
    trial_report.untangled = report.untangled;
    if (!refine(faces, refinement, sigma, edge, near_creases, refined, uncertain ? report : trial_report, step, 30, 50, error))
      return false;
    clock.done(uncertain ? "refinement" : "refinement tried");
    report.refined_crease_contrast = crease_contrast(refined, faces);
    report.creases_revealed = report.refined_crease_contrast >= kRevealedCreaseContrast;
    if (uncertain && !flatten_planar_parts(start, faces, options, refined, report, clock, error)) return false;
  }
  if (may_smooth && !report.creases_revealed) {
    const int from = try_refinement || uncertain ? 50 : 40;
    step(from, "No sharp creases: adaptive smoothing");
    NoiseAdaptiveSmoothingOptions smoothing;  // the adaptive smoothing's own filter
    smoothing.keep_untouched = false;
    smoothing.hold_borders = options.hold_borders;
    smoothing.noise = sigma;
    smoothing.unbiased_risk = options.noise > 0;  // the user's noise level: its cut-off by Stein's risk
    if (!noise_adaptive_smooth(positions, faces, smoothing, result, report.smoothing, error, [&](int percent, const char*) {
          step(from + (99 - from) * percent / 100, "No sharp creases: adaptive smoothing");
        }))
      return false;
    clock.done("adaptive smoothing");
    report.smoothing_weight = !uncertain ? 1.0
                                         : (options.crease_contrast - report.crease_contrast) /
                                               (options.crease_contrast - options.no_crease_contrast);
    if (uncertain) result = report.smoothing_weight * result + (1 - report.smoothing_weight) * refined;
    return show_features_and_finish(positions, faces, options, report, clock, step, error);
  }
  if (uncertain) {  // revealed: the refinement is the result
    result.swap(refined);
    return show_features_and_finish(positions, faces, options, report, clock, step, error);
  }
  return refine_from(positions, start, faces, options, sigma, edge, near_creases, result, report, clock, step, error);
}

// The denoiser over every vertex; feature_preserving_denoise then keeps those impulsive noise left alone.
bool denoise_every_vertex(const Positions& positions, const Faces& faces, const DenoiseOptions& options,
                          Positions& result, DenoiseReport& report, std::string& error, const Progress& progress) {
  StageClock clock(report.stages);
  const Step step = [&](int percent, const char* what) {
    if (progress) progress(percent, what);
  };
  if (!(options.refine_drift_step > 0) || !(options.refine_converged_step >= 0) ||
      !(options.refine_extra_rounds_factor >= 1 && options.refine_extra_rounds_factor <= 10) ||
      !(options.refine_sliver_altitude >= 0 && options.refine_sliver_altitude <= 10)) {
    error = "refinement round rule out of range: drift step above 0, converged step at least 0, extra rounds factor 1 to 10, sliver altitude 0 to 10";
    return false;
  }
  if (!(options.distorting_move_low >= 0 && options.distorting_move_low <= options.distorting_move_high)) {
    error = "distorting move band out of range: from 0 up to distorting_move_high";
    return false;
  }
  if (!(options.folded_low >= 0 && options.folded_low <= options.folded_high)) {
    error = "folded share band out of range: from 0 up to folded_high";
    return false;
  }
  if (!(options.tangled_share >= 0 && options.tangled_share <= 1)) {
    error = "tangled share out of range: 0 to 1";
    return false;
  }
  if (!(options.no_crease_contrast >= 0 && options.no_crease_contrast <= options.crease_contrast && std::isfinite(options.crease_contrast))) {
    error = "crease contrast band out of range: from 0 up to crease_contrast";
    return false;
  }
  if (!check_triangle_mesh(positions, faces, error)) return false;
  const int n = static_cast<int>(positions.rows());

  step(2, "Noise estimate (finest IMF)");
  double sigma = options.noise;
  if (!(sigma > 0)) {
    HamiltonianCycle cycle;
    if (!hamiltonian_cycle(faces, n, options.cycle, cycle, error)) return false;
    if (!estimate_noise(positions, faces, cycle, options.emd, report.noise, error)) return false;
    report.cycle = std::move(cycle);
    sigma = report.noise.relative();
    clock.done("noise estimate");
  }
  report.sigma_used = sigma;
  report.type.assign(n, FeatureType::None);

  // Impulsive noise read from scattered spikes: the spikes put back, every other vertex as it was
  // (too dense for that: denoised as any noise).
  if (options.remove_scattered_spikes && !options.paper_stage && report.noise.scattered_impulsive()) {
    step(20, "Impulsive noise: spike removal");
    Positions despiked = remove_spikes(positions, faces, vertex_adjacency(faces, n), report.spike_removal);
    clock.done("spike removal");
    if (report.spike_removal.sparse) {
      result.swap(despiked);
      report.spikes_removed = true;
      return show_features_and_finish(positions, faces, options, report, clock, step, error);
    }
    // Too dense for the removal alone: what it left denoised as any noise (docs/quality.md items 26
    // and 27).
    return filter_despiked(despiked, faces, report.cycle, options, report, error,
                           [&](const Positions& p, const DenoiseOptions& o, DenoiseReport& r) {
                             return denoise_every_vertex(p, faces, o, result, r, error, progress);
                           });
  }

  // No noise to remove: the input as it is (the paper's stage, when asked for, still runs).
  if (!(options.noise > 0) && sigma < kNoiseFree && !options.paper_stage) {
    report.noise_free = true;
    result = positions;
    return show_features_and_finish(positions, faces, options, report, clock, step, error);
  }

  const double edge = mean_edge_length(positions, faces);
  if (!options.untangle && !(options.smooth_surfaces_by_smoothing && !options.paper_stage))
    return refine_from(positions, positions, faces, options, sigma, edge, {}, result, report, clock, step, error);

  step(8, "Untangling: noise-adaptive smoothing");
  NoiseAdaptiveSmoothingOptions smoothing;
  smoothing.noise = sigma;
  smoothing.select_cutoff = false;  // the noise level's cut-off: the refinement was measured from it
  smoothing.unturn_wrinkles = false;  // the tangle test counts the faces this smoothing turns
  smoothing.face_normal_pass = false;  // the refinement was measured from the smoothing without them
  smoothing.taubin_slide = false;
  smoothing.keep_untouched = false;  // feature_preserving_denoise keeps them at the end
  smoothing.hold_borders = options.hold_borders;
  smoothing.first_order = options.untangle_first_order;
  smoothing.mu_scale = options.untangle_mu_scale;
  NoiseAdaptiveSmoothingReport smoothing_report;
  Positions smoothed;
  if (!noise_adaptive_smooth(positions, faces, smoothing, smoothed, smoothing_report, error,
                             [&](int percent, const char*) { step(8 + 22 * percent / 100, "Untangling: noise-adaptive smoothing"); }))
    return false;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const auto normal = [&](const Positions& p) {
      const Eigen::RowVector3d a = p.row(faces(f, 0));
      return Eigen::RowVector3d((p.row(faces(f, 1)) - a).cross(p.row(faces(f, 2)) - a));
    };
    report.flipped_faces += normal(positions).dot(normal(smoothed)) < 0;
  }
  // A smoothing that moves the mesh further than the noise did distorts it, unless a tenth of the
  // faces are folded (item 17); each reading has an uncertain band, where the weight of the
  // refinement from the input moves linearly (items 33 and 34).
  const double noise_rms = std::sqrt(3.0) * sigma * edge;
  report.smoothing_move = noise_rms > 0 ? std::sqrt((smoothed - positions).rowwise().squaredNorm().mean()) / noise_rms : 0;
  const std::vector<unsigned char> folded = folded_faces(positions, faces);
  report.folded_faces = static_cast<int>(std::count(folded.begin(), folded.end(), 1));
  const double low = options.distorting_move_low, high = options.distorting_move_high;
  const double move_weight = report.smoothing_move <= low ? 0.0
                             : report.smoothing_move >= high ? 1.0
                                                             : (report.smoothing_move - low) / (high - low);
  const double folded_share = report.folded_faces / static_cast<double>(faces.rows());
  const double fold_weight = folded_share >= options.folded_high ? 0.0
                             : folded_share < options.folded_low ? 1.0
                                                                 : (options.folded_high - folded_share) / (options.folded_high - options.folded_low);
  const double distort_weight = options.refine_where_smoothing_distorts ? move_weight * fold_weight : 0.0;
  // The smoothing's creases, read once for whichever routes follow.
  const std::vector<DihedralAngle> angles = dihedral_angles(smoothed, faces);
  const CreaseReadings readings = read_creases(angles);
  report.crease_contrast = readings.contrast;
  report.crease_lines = readings.lines;
  clock.done("untangling");
  if (distort_weight == 0 || distort_weight == 1)
    return denoise_after_untangling(positions, faces, options, sigma, edge, smoothed, angles, distort_weight, result, report,
                                    step, error);

  // An uncertain reading (items 33, 34): the mesh refined from its input (item 17) and routed as
  // usual from the same readings, the two blended with distort_weight on the first. The report is
  // the usual route's.
  const auto part = [&](int from, int to) -> Step {
    return [&step, from, to](int percent, const char* what) { step(from + (to - from) * (percent - 30) / 70, what); };
  };
  const auto seconds = [](const DenoiseReport& r) {
    double sum = 0;
    for (const StageTime& stage : r.stages) sum += stage.seconds;
    return sum;
  };
  const double read = seconds(report);
  DenoiseReport refined_report = report;
  Positions refined;
  if (!denoise_after_untangling(positions, faces, options, sigma, edge, smoothed, angles, 1.0, refined, refined_report,
                                part(30, 60), error))
    return false;
  if (!denoise_after_untangling(positions, faces, options, sigma, edge, smoothed, angles, 0.0, result, report, part(60, 99),
                                error))
    return false;
  result = distort_weight * refined + (1 - distort_weight) * result;
  report.distort_weight = distort_weight;
  report.stages.push_back({"refinement from the input (blended)", seconds(refined_report) - read});
  step(100, "Done");
  return true;
}

}  // namespace

bool feature_preserving_denoise(const Positions& positions, const Faces& faces, const DenoiseOptions& options,
                                Positions& result, DenoiseReport& report, std::string& error,
                                const Progress& progress) {
  report = DenoiseReport{};
  if (!denoise_every_vertex(positions, faces, options, result, report, error, progress)) return false;
  // An estimate that read no impulsive noise read the same input: no need to look again.
  if (!report.noise_free && (options.noise > 0 || report.noise.spikes.impulsive())) {
    StageClock clock(report.stages);
    report.untouched_vertices_kept = keep_untouched_vertices(positions, faces, result);
    clock.done("impulsive noise check");
  }
  return true;
}

}  // namespace hht
