// "HHT: Feature-Preserving Denoise": noise estimated by the HHT, untangling, guided normal
// refinement in rounds set by the noise, and optionally the paper's divide-and-conquer stage
// (sec. 4.3) before it (common/feature_preserving_denoise.h).
#include "filter_spec.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"

#include "filters/feature_preserving_denoise.h"
#include "evaluation/gaussian_noise.h"

#include <vcg/complex/allocate.h>

namespace hht_plugin {

namespace {

enum Show { ShowNothing, SelectFeatureVertices, FeatureLineLayer };

// Caps on the work the parameters ask for: passes and iterations are linear in the mesh each.
constexpr int kMaxPasses = 1000, kMaxCycles = 100;

// The dialog: what a user tunes first (noise, untangling, refinement, features), then the
// paper's optional stage and its parameters, then the experts' cycle and EMD rules.
void declare(const MeshDocument&, RichParameterList& p) {
  const hht::DenoiseOptions d;
  p.addParam(RichFloat("noisePercent", float(100 * d.noise), "Noise level (% of mean edge, 0 = estimate)",
                       "Standard deviation of the noise along the surface normal in percent of the mean edge length "
                       "(per coordinate for isotropic noise; HHT: Add Gaussian Noise logs it, about sigma / 1.73 for "
                       "its random directions; 0 to 1000). 0 estimates "
                       "it from the finest IMF of the one-ring height signal along a Hamiltonian cycle, capped by the "
                       "exactly flat hinges of CAD meshes (a clean CAD export reads as noise-free and is left as it "
                       "is); it sets the number of refinement rounds and the untangling smoothing, and on a surface without sharp "
                       "creases the adaptive smoothing's cut-off by Stein's unbiased risk. A clean curved mesh "
                       "reads its own fine detail as up to 15% noise (the log says when an estimate is in that range): "
                       "to keep that detail on a mesh you know to be clean or nearly so, give a small value."));
  p.addParam(RichBool("untangle", d.untangle, "Untangle folded triangles first",
                      QString("Noise with a tangential part (a scanner's) folds small triangles over, which no normal "
                              "filter repairs. When more than 0.75% of the faces point away from those of the "
                              "noise-adaptive smoothing (HHT: Adaptive Smooth), the denoiser starts from that smoothing; "
                              "not when the smoothing moves the mesh further than the noise did and fewer than a tenth of its faces "
                              "are folded (a coarse CAD export, whose few-edge features it would flatten: refined from the "
                              "input); a move of %1 to %2 times the noise's, or %3% to %4% of the faces folded, is "
                              "uncertain, and the two results are blended.")
                          .arg(hht::kDistortingMoveLow)
                          .arg(hht::kDistortingMoveHigh)
                          .arg(100 * hht::kHeavilyFoldedLow)
                          .arg(100 * hht::kHeavilyFoldedHigh)));
  p.addParam(RichBool("smoothCreaseless", d.smooth_surfaces_by_smoothing, "Smooth surfaces without sharp creases",
                      QString("When the smoothed mesh shows no sharp creases (the 98th percentile of its dihedral angles "
                              "under %1 times their median, and its edges over 12 times the median forming lines shorter "
                              "than twice the mesh's breadth: organic models), the result is HHT: Adaptive Smooth's instead "
                              "of the refinement, which would facet it; from %1 to %2 times, an uncertain reading, the two "
                              "blended (the smoothing's share falling across that band), unless the refinement brings back "
                              "flat faces meeting at creases; not on a mesh whose exactly flat parts capped the noise "
                              "estimate and that needed no untangling (a lightly noisy CAD part), nor on one that the "
                              "smoothing distorts (see Untangle). Turn off to force the refinement, e.g. on a CAD part with "
                              "rounded edges. Ignored with the paper's stage on.")
                          .arg(hht::kNoCreaseContrast)
                          .arg(hht::kCreaseContrast)));
  p.addParam(RichInt("refineRounds", d.refine_rounds, "Refinement rounds (0 = by the noise)",
                     "Rounds of guided normal filtering and vertex update (0 to 100); 0 takes one per 10% of noise "
                     "(below 5%, one round of proportionally fewer passes, so a clean mesh is barely touched), stops "
                     "early at a round that moves the mesh by more than 0.18 noise sigmas (it would facet curved "
                     "parts) and adds up to half as many again while each moves it by less than 0.1 (converging "
                     "onto flat parts)."));
  p.addParam(RichInt("refineNormalPasses", d.refine_normal_passes, "Refinement: normal filtering passes",
                     "Guided normal filtering passes (which keep creases) per round before the vertices are fitted to "
                     "the normals (0 to 1000). 0: no refinement (with the paper's stage on, the paper's method "
                     "alone)."));
  p.addParam(RichInt("refineVertexIterations", d.refine_vertex_iterations, "Refinement: vertex update iterations",
                     "Iterations of the vertex update towards the filtered normals after each round's passes (Sun et "
                     "al. 2007; 0 to 1000). Where the noise is heavy (an estimate of 10% of the mean edge or more) or "
                     "the untangling started from the smoothing, the vertices are fitted after every pass instead, 10 "
                     "iterations each."));
  p.addParam(RichBool("refineOwnNormals", d.refine_own_normals, "Refinement: last round on own normals",
                      "The refinement's last round (every round when it starts from the untangling's smoothing) filters "
                      "each face normal with a range kernel on the faces' own normals (bilateral normal filtering, Zheng "
                      "et al. 2011) instead of the patch guidance: it keeps small features and creases the patches blur "
                      "(measured on CAD parts at 2-30% noise, docs/quality.md item 16). Off: every round guided."));
  p.addParam(RichBool("detectFeatures", d.detect_features, "Preserve sharp features",
                      "Detect sharp features and process them as their own signals (CAD-like models) in the paper's "
                      "stage; they are detected only for that stage or to show them. Off: no feature separation, for "
                      "smooth models such as the paper's torus."));
  p.addParam(RichFloat("featureAngle", float(d.features.angle_degrees), "Feature angle (deg)",
                       "A crease is a feature when the (noise-filtered) normals of its two faces differ by more than "
                       "this angle (0 to 180): 90 on a cube edge, 0 on a plane. Lower it to catch weak creases."));
  p.addParam(RichInt("normalFilterIterations", d.features.filter_iterations, "Normal filtering passes",
                     "Passes of guided normal filtering before the feature detection votes, so that noise does not "
                     "look like creases (0 to 1000). 0 for noise-free input."));
  p.addParam(RichEnum("showFeatures", ShowNothing,
                      QStringList{"Nothing", "Select the feature vertices", "Add the feature lines as a layer"},
                      "Show the detected features",
                      "Also show the detection (the paper's Fig. 4c-d): feature vertices selected, or a new layer "
                      "with the feature lines as polylines, one colour per line."));
  p.addParam(RichBool("paperStage", d.paper_stage, "Paper's HHT stage",
                      "Run the paper's divide-and-conquer HHT (sec. 4.3: feature lines as their own signals, the "
                      "cycle's curvature signal low-passed, Laplacian reconstruction) before the refinement. Off by "
                      "default: measured, the refinement alone is better on most cases (docs/quality.md). The "
                      "parameters below act on this stage only."));
  p.addParam(RichFloat("cutoff", float(d.cutoff), "Paper's stage: cut-off frequency",
                       "Instantaneous frequencies above this (cycles per sample, 0 to 0.5) are removed from the "
                       "curvature signals, along the cycle and along each feature line."));
  p.addParam(RichInt("cycles", d.cycles, "Paper's stage: cycles averaged",
                     QString("Hamiltonian cycles (different seeds) along which the non-feature signal is filtered "
                             "(1 to %1); the results are averaged, which removes the stripes a single cycle leaves.")
                         .arg(kMaxCycles)));
  p.addParam(RichInt("shortLinePasses", d.short_line_passes, "Paper's stage: Laplacian passes on short lines",
                     "Feature lines too short for EMD are smoothed by this many passes of a 1D Laplacian instead (0 "
                     "to 1000)."));
  p.addParam(RichFloat("lambda", float(d.reconstruction.lambda), "Paper's stage: position weight (lambda)",
                       "Weight of the input positions in the reconstruction, relative to the mean edge length "
                       "(0.0001 to 10000)."));
  declare_cycle_and_emd_parameters(p);
}

void add_feature_layer(MeshDocument& document, const hht::Positions& positions, const hht::FeatureLines& lines,
                       const QString& label) {
  MeshModel* layer = document.addNewMesh("", label, false);
  layer->updateDataMask(MeshModel::MM_VERTCOLOR);
  CMeshO& m = layer->cm;
  for (size_t l = 0; l < lines.lines.size(); ++l) {
    const auto& line = lines.lines[l];
    const vcg::Color4b colour = vcg::Color4b::Scatter(int(std::max<size_t>(lines.lines.size(), 2)), int(l));
    const size_t first = m.vert.size();
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, line.size());
    for (int v : line) {
      vi->P() = Point3m(positions(v, 0), positions(v, 1), positions(v, 2));
      (vi++)->C() = colour;
    }
    const size_t segments = lines.closed[l] ? line.size() : line.size() - 1;
    auto ei = vcg::tri::Allocator<CMeshO>::AddEdges(m, segments);
    for (size_t i = 0; i < segments; ++i, ++ei) {
      ei->V(0) = &m.vert[first + i];
      ei->V(1) = &m.vert[first + (i + 1) % line.size()];
    }
  }
  update_box_and_normals(*layer);
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  const RichParameterList& par = run.parameters;
  hht::DenoiseOptions o;
  o.noise = par.getFloat("noisePercent") / 100.0;
  o.untangle = par.getBool("untangle");
  o.smooth_surfaces_by_smoothing = par.getBool("smoothCreaseless");
  o.paper_stage = par.getBool("paperStage");
  o.refine_rounds = par.getInt("refineRounds");
  if (!check_range("the noise level (% of the mean edge)", 100 * o.noise, 0, 1000, run.error) ||
      !check_range("refineRounds", o.refine_rounds, 0, 100, run.error))
    return false;
  o.detect_features = par.getBool("detectFeatures");
  const int show = par.getEnum("showFeatures");
  o.show_features = show != ShowNothing;
  o.features.angle_degrees = par.getFloat("featureAngle");
  o.features.filter_iterations = par.getInt("normalFilterIterations");
  o.cutoff = par.getFloat("cutoff");
  o.cycles = par.getInt("cycles");
  o.cycle = cycle_options(par);
  o.emd = emd_options(par);
  o.short_line_passes = par.getInt("shortLinePasses");
  o.reconstruction.lambda = par.getFloat("lambda");
  o.refine_normal_passes = par.getInt("refineNormalPasses");
  o.refine_vertex_iterations = par.getInt("refineVertexIterations");
  o.refine_own_normals = par.getBool("refineOwnNormals");
  if (!check_range("the feature angle", o.features.angle_degrees, 0, 180, run.error, " degrees") ||
      !check_range("normalFilterIterations", o.features.filter_iterations, 0, kMaxPasses, run.error) ||
      !check_range("the cut-off", o.cutoff, 0, 0.5, run.error, " cycles per sample") ||
      !check_range("cycles", o.cycles, 1, kMaxCycles, run.error, " (each costs one more cycle and EMD)") ||
      !check_emd_parameters(par, run.error) ||
      !check_range("shortLinePasses", o.short_line_passes, 0, kMaxPasses, run.error) ||
      !check_lambda(o.reconstruction.lambda, run.error) ||
      !check_range("refineNormalPasses", o.refine_normal_passes, 0, kMaxPasses, run.error) ||
      !check_range("refineVertexIterations", o.refine_vertex_iterations, 0, kMaxPasses, run.error))
    return false;
  hht::DenoiseReport report;
  auto progress = [&](int percent, const char* stage) { run.report(percent, stage); };
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string& message) {
        return hht::feature_preserving_denoise(positions, faces, o, out, report, message, progress);
      }, run.error, input_map))
    return false;
  if (show == SelectFeatureVertices) {
    Eigen::VectorXd feature(static_cast<Eigen::Index>(report.type.size()));
    for (size_t r = 0; r < report.type.size(); ++r)
      feature[static_cast<Eigen::Index>(r)] = report.type[r] != hht::FeatureType::None;
    const Eigen::VectorXd on_mesh = hht::to_input_vertices(feature, input_map);  // a split vertex: its result's copy
    Eigen::Index i = 0;
    for (auto& v : model.cm.vert) {
      if (v.IsD()) continue;
      if (on_mesh[i++] > 0) v.SetS(); else v.ClearS();
    }
  } else if (show == FeatureLineLayer) {
    add_feature_layer(run.document, result, report.feature_lines, "Feature lines of " + model.label());
  }

  const double edge = hht::mean_edge_length(positions, faces);
  run.log(QString("Feature-preserving denoise: noise sigma %1% of the mean edge length %2 (%3)")
              .arg(100 * report.sigma_used, 0, 'f', 1).arg(edge)
              .arg(o.noise > 0 ? QString("given") : noise_estimate_text(report.despiked_then_filtered ? report.input_noise : report.noise)));
  if (report.features_detected)
    run.log(QString("  features: %1 vertices, %2 feature lines, %3 corners")
                .arg(report.feature_vertices).arg(report.lines).arg(report.corners));
  if (const QString line = spike_removal_line(report.spikes_removed, report.spike_removal, static_cast<int>(positions.rows()),
                                                report.sigma_used);
      !line.isEmpty())
    run.log(line);
  if (report.noise_free || report.spikes_removed) {
    run.log(stage_times_line(report.stages));
    return true;
  }
  if (o.untangle)
    run.log(QString("  untangling: %1 faces flipped against the noise-adaptive smoothing; %2")
                .arg(report.flipped_faces)
                .arg(report.untangled ? "started from that smoothing" : "started from the input"));
  if (report.distort_weight > 0 && report.distort_weight < 1)
    run.log(QString("  that smoothing moved the mesh by %1 times the noise's RMS with %2% of its faces folded, an uncertain "
                    "reading (a move from %3 to %4, or from %5% to %6% of the faces folded): the result is %7% the "
                    "refinement from the input and %8% the usual route's below")
                .arg(report.smoothing_move, 0, 'f', 2).arg(100.0 * report.folded_faces / faces.rows(), 0, 'f', 1)
                .arg(hht::kDistortingMoveLow).arg(hht::kDistortingMoveHigh)
                .arg(100 * hht::kHeavilyFoldedLow).arg(100 * hht::kHeavilyFoldedHigh)
                .arg(100 * report.distort_weight, 0, 'f', 0).arg(100 * (1 - report.distort_weight), 0, 'f', 0));
  if (report.smoothing_distorts())
    run.log(QString("  that smoothing moved the mesh by %1 times the noise's RMS with %2% of its faces folded: it "
                    "distorts features a few edges wide (a coarse CAD export); refined from the input, not smoothed")
                .arg(report.smoothing_move, 0, 'f', 2).arg(100.0 * report.folded_faces / faces.rows(), 0, 'f', 1));
  if (o.paper_stage) {
    run.log(QString("  paper's stage: %1 lines by EMD, %2 by 1D Laplacian; low-pass at %3 cycles/sample along %4 "
                    "cycle(s), %5 IMFs on the first; reconstruction lambda %6, %7 CG iterations")
                .arg(report.lines_by_emd).arg(report.lines - report.lines_by_emd).arg(o.cutoff).arg(o.cycles)
                .arg(report.imfs.size()).arg(o.reconstruction.lambda).arg(report.reconstruction.iterations));
  }
  if (report.crease_contrast > 0)
    run.log(QString("  crease contrast of the smoothed mesh %1, its crease lines %2 times its breadth "
                    "(below %3 and %4: no sharp creases; a contrast from %3 to %5 is uncertain)%6")
                .arg(report.crease_contrast, 0, 'f', 1).arg(report.crease_lines, 0, 'f', 1)
                .arg(hht::kNoCreaseContrast).arg(hht::kCreaseLines).arg(hht::kCreaseContrast)
                .arg(!report.smoothed_instead() ? ""
                     : report.smoothing.cutoff_by_risk ? "; the result is the adaptive smoothing (cut-off by Stein's unbiased risk with the given noise)"
                                   : "; the result is the adaptive smoothing (cross-validated cut-off)"));
  const bool blended = report.smoothing_weight > 0 && !report.smoothed_instead();
  if (report.refined_crease_contrast > 0 && report.crease_contrast >= hht::kNoCreaseContrast)
    run.log(QString("  uncertain creases: the refinement reads a crease contrast of %1 (%2 %3: %4)")
                .arg(report.refined_crease_contrast, 0, 'f', 1)
                .arg(report.creases_revealed ? "at least" : "below").arg(hht::kRevealedCreaseContrast)
                .arg(report.creases_revealed
                         ? "flat faces meeting at creases, the refinement is the result"
                         : QString("the result is %1% the adaptive smoothing and %2% the refinement")
                               .arg(100 * report.smoothing_weight, 0, 'f', 0)
                               .arg(100 * (1 - report.smoothing_weight), 0, 'f', 0)));
  else if (report.refined_crease_contrast > 0)
    run.log(QString("  heavy noise (%1 mean edges, from %2 on) can hide a part's creases from the smoothed mesh: a "
                    "trial refinement reads a crease contrast of %3 (%4 %5: %6)")
                .arg(report.sigma_used, 0, 'f', 3).arg(hht::kCreaseRevealNoise)
                .arg(report.refined_crease_contrast, 0, 'f', 1)
                .arg(report.creases_revealed ? "at least" : "below").arg(hht::kRevealedCreaseContrast)
                .arg(report.creases_revealed ? "flat faces meeting at creases, refined after all"
                                             : "no creases brought back, smoothed"));
  if (report.flat_parts_refined)
    run.log("  no sharp creases read for certain, but the mesh has exactly flat parts (its noise estimate was capped by them): "
            "a CAD part, refined all the same");
  if (report.smoothed_instead() || blended) {
    if (const QString line = tangential_share_line(report.smoothing.tangential_share); !line.isEmpty()) run.log(line);
    run.log(smoothing_finish_line(report.smoothing));
  }
  if (report.smoothed_instead()) {
    run.log("  no refinement (the surface has no sharp creases)");
  } else if (report.refine_normal_passes > 0 && o.refine_vertex_iterations > 0) {
    const int own_rounds = report.refine_own_normal_rounds, guided_rounds = report.refine_rounds - own_rounds;
    const QString which = guided_rounds == 0 ? QString("all")
                                             : QString("the first %1 guided, the last %2").arg(guided_rounds).arg(own_rounds);
    const QString rounds = own_rounds == 0 ? QString("all guided")
                                           : QString("%1 on the faces' own normals (bilateral normal filtering, range width %2)")
                                                 .arg(which).arg(hht::kOwnNormalSigma);
    const QString fitting = report.refine_fit_each_pass
                                ? QString("each followed by %1 vertex update iterations (heavy or tangling noise)")
                                      .arg(hht::kFitEachPassIterations)
                                : QString("then %1 vertex update iterations").arg(o.refine_vertex_iterations);
    run.log(QString("  refinement: %1 round(s) of %2 normal filtering passes, %3; %4")
                .arg(report.refine_rounds).arg(report.refine_normal_passes).arg(fitting).arg(rounds));
    if (report.refine_near_creases >= 0 && guided_rounds > 0)
      run.log(QString("  guided rounds: range width %1 on the %2% of the faces near the smoothed mesh's creases (sharper "
                      "than %3 degrees), %4 elsewhere")
                  .arg(o.refine_normal_sigma).arg(100 * report.refine_near_creases, 0, 'f', 1).arg(hht::kCreaseDihedral)
                  .arg(o.refine_smooth_sigma));
    if (!report.refine_steps.empty()) {
      QStringList moves;
      for (double m : report.refine_steps) moves << QString::number(m, 'f', 3);
      const QString thin = report.refine_median_altitude > 0 && report.refine_median_altitude < o.refine_sliver_altitude
                               ? QString(" (up to %1 while they converge: the faces' median altitude is %2 mean edges)")
                                     .arg(report.refine_rounds_allowed).arg(report.refine_median_altitude, 0, 'f', 2)
                               : QString();
      run.log(QString("  rounds: %1 set by the noise%4; moves of rounds 2 on (noise sigmas): %2%3")
                  .arg(report.refine_rounds_asked).arg(moves.join(", "))
                  .arg(!report.refine_round_undone ? QString()
                       : report.refine_rounds < report.refine_rounds_asked
                           ? QString("; the last drifted (above %1) and was undone").arg(o.refine_drift_step)
                           : QString("; the last did not converge (above %1) and was undone").arg(o.refine_converged_step))
                  .arg(thin));
    }
    if (report.refine_unturned_faces > 0)
      run.log(QString("  %1 faces the refinement turned over against its start stood back up").arg(report.refine_unturned_faces));
    if (report.planar_regions > 0)
      run.log(QString("  %1 planar regions made flat (%2% of the faces: each within %3 degrees of its seed face, bending "
                      "at most %4 degree over the region; the vertices fitted in %5 iterations)")
                  .arg(report.planar_regions).arg(100.0 * report.planar_region_faces / faces.rows(), 0, 'f', 1)
                  .arg(o.planar_regions.seed_degrees).arg(o.planar_regions.max_bend_degrees)
                  .arg(report.planar_fit_iterations));
  } else {
    run.log("  no refinement");
  }
  if (const QString line = untouched_vertices_line(report.untouched_vertices_kept); !line.isEmpty()) run.log(line);
  run.log(stage_times_line(report.stages));
  return true;
}

}  // namespace

FilterSpec denoise_filter() {
  return {"HHT: Feature-Preserving Denoise",
          "Denoises the mesh while keeping its sharp edges and corners. The noise level is estimated from the finest "
          "IMF of the one-ring height signal along a Hamiltonian cycle, capped by the exactly flat hinges of CAD "
          "meshes (a clean one is left as it is); a mesh whose triangles the noise folded over "
          "is first untangled by the noise-adaptive smoothing; then face normals are cleaned by guided normal "
          "filtering (which keeps creases) and the vertices fitted to them, in as many rounds as the noise calls "
          "for. Optionally the paper's divide-and-conquer HHT (sec. 4.3: feature lines as their own 1D signals, the "
          "cycle's curvature signal low-passed on instantaneous frequency, Laplacian reconstruction) runs first; "
          "docs/quality.md measures each part. The connectivity is never changed.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL | MeshModel::MM_VERTFLAGSELECT,
          declare,
          apply};
}

}  // namespace hht_plugin
