// "HHT: Adaptive Smooth": smoothing whose strength is set by the noise level that the finest
// IMF of the cycle signal shows (common/noise_adaptive_smoothing.h; ours, not the paper's).
#include "filter_spec.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"

#include "evaluation/gaussian_noise.h"
#include "filters/noise_adaptive_smoothing.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichFloat("strength", 1.0f, "Strength",
                       "Multiplies the smoothing the noise estimate and the cross-validation call for: 1 is the "
                       "measured best on the evaluation corpus (docs/quality.md), above 1 smooths more, below 1 less "
                       "(0.1 to 10)."));
  p.addParam(RichFloat("noisePercent", 0.0f, "Noise level (% of mean edge, 0 = estimate)",
                       "Standard deviation of the noise along the surface normal in percent of the mean edge length "
                       "(per coordinate for isotropic noise; HHT: Add Gaussian Noise logs it, about sigma / 1.73 for "
                       "its random directions). 0 "
                       "estimates it from the finest IMF of the one-ring height signal along a Hamiltonian cycle, "
                       "capped by the exactly flat hinges of CAD meshes (a clean CAD export reads as noise-free and "
                       "is left as it is); give a value only when you know it, or to smooth such a mesh (0 to 1000): the "
                       "cut-off is then the one that minimises Stein's unbiased risk with that noise. A clean curved mesh "
                       "reads its own fine detail as up to 15% noise (the log says when an estimate is in that range): "
                       "to keep that detail on a mesh you know to be clean or nearly so, give a small value."));
  declare_cycle_and_emd_parameters(p);
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  const RichParameterList& par = run.parameters;
  hht::NoiseAdaptiveSmoothingOptions options;
  options.strength = par.getFloat("strength");
  options.noise = par.getFloat("noisePercent") / 100.0;
  options.unbiased_risk = options.noise > 0;  // a given noise level is the truth: Stein's risk chooses the cut-off
  options.cycle = cycle_options(par);
  options.emd = emd_options(par);
  if (!check_range("the strength", options.strength, 0.1, 10, run.error) ||
      !check_range("the noise level (% of the mean edge)", 100 * options.noise, 0, 1000, run.error) ||
      !check_emd_parameters(par, run.error))
    return false;
  hht::NoiseAdaptiveSmoothingReport report;
  auto progress = [&](int percent, const char* stage) { run.report(percent, stage); };
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string& message) {
        return hht::noise_adaptive_smooth(positions, faces, options, out, report, message, progress);
      }, run.error, input_map))
    return false;
  const double edge = hht::mean_edge_length(positions, faces);
  if (options.noise > 0)
    run.log(QString("Adaptive smooth: noise given, sigma %1% of the mean edge length %2").arg(100 * options.noise).arg(edge));
  else
    run.log(QString("Adaptive smooth: noise sigma %1% of the mean edge length %2 (%3; %4 IMF samples)%5")
                .arg(100 * report.sigma_used, 0, 'f', 1).arg(edge)
                .arg(noise_estimate_text(report.despiked_then_filtered ? report.input_noise : report.noise))
                .arg(report.noise.samples)
                .arg(report.noise_free ? "; give the noise level to smooth it anyway" : ""));
  if (const QString line = spike_removal_line(report.spikes_removed, report.spike_removal, static_cast<int>(positions.rows()),
                                                report.sigma_used);
      !line.isEmpty())
    run.log(line);
  if (report.noise_free || report.spikes_removed) {
    run.log(stage_times_line(report.stages));
    return true;
  }
  if (report.cutoff_by_risk)
    run.log(QString("  cut-off by Stein's unbiased risk with the given noise, on %1 vertices (%2 conjugate gradient "
                    "iterations)")
                .arg(report.selection_vertices).arg(report.selection_iterations));
  else if (report.selection_vertices > 0)
    run.log(QString("  cut-off by cross-validation on %1 vertices (%2 conjugate gradient iterations): %3")
                .arg(report.selection_vertices).arg(report.selection_iterations)
                .arg(report.cutoff_selected ? "stronger than the noise level's" : "the noise level's kept"));
  run.log(QString("  cut-off mu %1 (strength %2), %3 conjugate gradient iterations; RMS vertex move %4, largest %5 "
                  "(x mean edge)")
              .arg(report.mu, 0, 'f', 3).arg(options.strength).arg(report.iterations)
              .arg(report.rms_displacement / edge, 0, 'f', 3).arg(report.max_displacement / edge, 0, 'f', 3));
  if (report.unfolded_vertices > 0 || report.held_vertices > 0 || report.restored_faces > 0 || report.unturned_faces > 0)
    run.log(QString("  %1 vertices moved to their neighbours' centroid to undo folds, %2 held within %3 noise sigmas, "
                    "%4 faces turned over put back, %5 more moved back until no longer turned over (wrinkles of the triangulation)")
                .arg(report.unfolded_vertices).arg(report.held_vertices).arg(hht::kMoveRadius).arg(report.restored_faces)
                .arg(report.unturned_faces));
  if (report.border_vertices_held > 0)
    run.log(QString("  %1 border vertices moved across their border by at most %2 noise sigma (the one-sided "
                    "Laplacian there pulls open borders and the rims of holes in)")
                .arg(report.border_vertices_held).arg(hht::kBorderMoveAcross));
  if (const QString line = tangential_share_line(report.tangential_share); !line.isEmpty()) run.log(line);
  run.log(smoothing_finish_line(report));
  if (const QString line = untouched_vertices_line(report.untouched_vertices_kept); !line.isEmpty()) run.log(line);
  run.log(stage_times_line(report.stages));
  return true;
}

}  // namespace

FilterSpec adaptive_smooth_filter() {
  return {"HHT: Adaptive Smooth",
          "Removes noise with a strength set by the noise itself: the noise level is estimated from the finest IMF "
          "of the one-ring height signal along a Hamiltonian cycle (Kopsinis and McLaughlin's EMD noise estimate), "
          "then the mesh is rebuilt by a least-squares solve that keeps mu^4 / (mu^4 + mu^2 k^2 + k^4) of each frequency k of the "
          "uniform Laplacian, mu set by the noise or, where generalized cross-validation finds it better (a dense, "
          "smooth surface), a stronger one, with tangential slides capped by the noise level, and one face-normal "
          "pass, or Taubin Smooth's slide along the surface instead of the cap, where a recorrupted-to-recorrupted "
          "risk estimate says it lowers the error. Not the paper's "
          "method (its curvature filter leaves stripes and keeps the noise's tangential part): see docs/quality.md "
          "for why and for how it compares with Taubin, HC Laplacian and TwoStep smoothing. A clean mesh is smoothed "
          "lightly, a clean CAD mesh with exactly flat parts not at all; the connectivity is never changed.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
