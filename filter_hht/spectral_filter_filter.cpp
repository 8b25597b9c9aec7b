// "HHT: Spectral Filter": smooths or enhances the geometry by filtering the curvature signal's
// IMFs on their instantaneous frequency and rebuilding the mesh (the paper's sec. 4.2).
#include "filter_spec.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"

#include "filters/spectral_mesh_filter.h"

namespace hht_plugin {

namespace {

enum Band { HighFrequencies, LowFrequencies, InsideBand, OutsideBand };

// Bounds on the parameters: each cycle costs one more cycle and EMD, and 16 cycles gain little
// over 4 (cycles_bench, docs/benchmarks.md); a gain above 100 only amplifies round-off (1e9
// moved Fandisk's vertices by 3e7).
constexpr int kMaxCycles = 100;
constexpr double kMaxGain = 100;

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichEnum("band", HighFrequencies,
                      QStringList{"High frequencies (above cut-off)", "Low frequencies (below cut-off)",
                                  "Inside [low, high]", "Outside [low, high]"},
                      "Band the gain acts on",
                      "Which instantaneous frequencies get multiplied by the gain; the others are kept. With gain 0: "
                      "'High frequencies' is a low-pass filter (smoothing), 'Low frequencies' a high-pass, 'Inside' "
                      "a band-stop, 'Outside' a band-pass. With gain above 1 the band is enhanced."));
  p.addParam(RichFloat("cutoff", 0.1f, "Cut-off frequency",
                       "For the high / low bands: instantaneous frequency, in cycles per sample along the cycle "
                       "(0 to 0.5), where the band starts."));
  p.addParam(RichFloat("lowFrequency", 0.05f, "Band low edge", "For inside / outside: the band's lower frequency."));
  p.addParam(RichFloat("highFrequency", 0.15f, "Band high edge", "For inside / outside: the band's upper frequency."));
  p.addParam(RichFloat("gain", 2.0f, "Gain",
                       QString("Multiplies the selected band (the paper's phi): 0 removes it, 1 leaves the mesh as "
                               "it is, above 1 enhances it, between 0 and 1 attenuates it (0 to %1). The default "
                               "enhances the fine detail; gain 0 with lambda 0.01 is the paper's smoothing, which "
                               "makes ordinary meshes worse than MeshLab's Taubin Smooth: to remove noise use "
                               "HHT: Adaptive Smooth.").arg(kMaxGain)));
  p.addParam(RichBool("coarseToFine", false, "Keep only the coarsest IMFs instead",
                      "Ignore the band and gain: keep the residue plus the coarsest IMFs (the paper's Fig. 5 "
                      "series, from smooth to the original)."));
  p.addParam(RichInt("coarsestImfs", 0, "Coarsest IMFs kept",
                     "With 'Keep only the coarsest IMFs': how many IMFs above the residue to keep (0 = residue only)."));
  p.addParam(RichInt("cycles", 1, "Cycles averaged",
                     QString("Filter along this many Hamiltonian cycles (different seeds) and average the filtered "
                             "signals (1 to %1). 1 is the paper's method; more cycles remove the stripes that "
                             "filtering along one cycle leaves (spatial neighbours far apart on the cycle are filtered "
                             "independently), at the cost of one EMD per cycle.").arg(kMaxCycles)));
  p.addParam(RichFloat("lambda", 0.1f, "Position weight (lambda)",
                       QString("Weight of the original positions in the reconstruction (eq. 9), relative to the mean "
                               "edge length, so a scaled copy of the mesh gives the scaled result. Larger: closer to "
                               "the input; the default anchors the shape while the detail changes, the paper's 0.01 "
                               "lets it drift (%1 to %2).").arg(kMinLambda).arg(kMaxLambda)));
  p.addParam(RichBool("literalTarget", false, "Paper's literal target (normal only)",
                      expert("Rebuild with the target Laplacian G~ n of eq. 9 as written. It moves vertices "
                             "tangentially even at gain 1; the default keeps the tangential part of L V and changes "
                             "only its normal component, so gain 1 returns the mesh exactly.")));
  declare_cycle_and_emd_parameters(p);
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  const RichParameterList& par = run.parameters;

  hht::SpectralMeshFilterOptions options;
  options.cycle = cycle_options(par);
  options.cycles = par.getInt("cycles");
  options.emd = emd_options(par);
  options.gain = par.getFloat("gain");
  options.keep_coarsest = par.getBool("coarseToFine");
  options.coarsest = par.getInt("coarsestImfs");
  const int band = std::clamp(par.getEnum("band"), 0, 3);
  const double cutoff = par.getFloat("cutoff");
  const double low = par.getFloat("lowFrequency"), high = par.getFloat("highFrequency");
  if (band <= LowFrequencies && !(cutoff >= 0 && cutoff <= 0.5)) {
    run.error = "Nothing was changed: the cut-off frequency must lie in [0, 0.5] cycles per sample.";
    return false;
  }
  if (band >= InsideBand && !(low >= 0 && low <= high && high <= 0.5)) {
    run.error = "Nothing was changed: the band needs 0 <= low <= high <= 0.5 cycles per sample.";
    return false;
  }
  if (!check_range("the gain", options.gain, 0, kMaxGain, run.error) ||
      !check_range("cycles", options.cycles, 1, kMaxCycles, run.error, " (each costs one more cycle and EMD)") ||
      !check_range("coarsestImfs", options.coarsest, 0, kMaxImfsCap, run.error) ||
      !check_emd_parameters(par, run.error))
    return false;
  switch (band) {
    case HighFrequencies: options.band = {cutoff, 0.5, false}; break;
    case LowFrequencies: options.band = {0.0, cutoff, false}; break;
    case InsideBand: options.band = {low, high, false}; break;
    default: options.band = {low, high, true}; break;
  }
  options.reconstruction.lambda = par.getFloat("lambda");
  if (!check_lambda(options.reconstruction.lambda, run.error)) return false;
  options.reconstruction.target =
      par.getBool("literalTarget") ? hht::ReconstructionTarget::NormalOnly : hht::ReconstructionTarget::KeepTangential;

  hht::SpectralMeshFilterReport report;
  auto progress = [&](int percent, const char* stage) { run.report(percent, stage); };
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string& message) {
        return hht::spectral_mesh_filter(positions, faces, options, out, report, message, progress);
      }, run.error, input_map))
    return false;

  const double diagonal = (positions.colwise().maxCoeff() - positions.colwise().minCoeff()).norm();
  if (options.keep_coarsest)
    run.log(QString("Spectral filter: residue + %1 coarsest IMFs kept").arg(options.coarsest));
  else
    run.log(QString("Spectral filter: gain %1 on instantaneous frequencies %2 [%3, %4] cycles/sample, %5 cycle(s) averaged")
                .arg(options.gain).arg(options.band.outside ? "outside" : "in")
                .arg(options.band.low).arg(options.band.high).arg(options.cycles));
  run.log(QString("  cycle: %1 of %2 vertices (%3 isolated, their change interpolated from the one-ring), %4 segment(s)")
              .arg(report.cycle.order.size()).arg(positions.rows()).arg(report.cycle.isolated).arg(report.cycle.components));
  run.log(QString("  %1 IMFs (mean frequency, energy share):").arg(report.imfs.size()));
  for (const QString& line : imf_summary_lines(report.imfs)) run.log(line);
  run.log(QString("  RMS change of the curvature signal %1; reconstruction: lambda %2, %3 target, %4 CG iterations, "
                  "position error below %5 of the diagonal")
              .arg(report.signal_change_rms).arg(options.reconstruction.lambda)
              .arg(par.getBool("literalTarget") ? "literal (normal only)" : "keep-tangential")
              .arg(report.reconstruction.iterations).arg(report.reconstruction.error_bound, 0, 'g', 3));
  if (report.restored_vertices > 0)
    run.log(QString("  %1 vertices put back where the enhancement would have turned faces over").arg(report.restored_vertices));
  run.log(QString("  largest vertex move %1 (%2% of the bounding-box diagonal)")
              .arg(report.max_displacement).arg(100.0 * report.max_displacement / diagonal, 0, 'f', 4));
  run.log(stage_times_line(report.stages));
  return true;
}

}  // namespace

FilterSpec spectral_filter_filter() {
  return {"HHT: Spectral Filter",
          "Smooths or enhances the mesh geometry with the Hilbert-Huang transform (the paper's sec. 4.2, Figs. 1, 5-7): "
          "the curvature signal G along a Hamiltonian cycle is decomposed by EMD; each IMF's instantaneous frequency "
          "selects where the gain applies (G~ = sum phi(omega_i) IMF_i + residue, eq. 14); the mesh is rebuilt from "
          "G~ by the Laplacian least-squares solve of eq. 9-11.<br>"
          "Gain above 1 enhances detail (the default, as resources/enhance.mlx), gain 1 returns the mesh unchanged, "
          "gain 0 on high frequencies smooths (the paper's smoothing: to remove noise, HHT: Adaptive Smooth does "
          "better). The connectivity is never changed.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
