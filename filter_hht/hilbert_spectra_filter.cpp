// "HHT: Hilbert Spectra": EMD of a per-vertex signal along the Hamiltonian cycle and the
// Hilbert spectra of its IMFs; one chosen result per vertex goes into quality.
#include "filter_spec.h"
#include "frequency_plot.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"

#include "cycle/cycle_decomposition.h"
#include "mesh/mean_curvature.h"

namespace hht_plugin {

namespace {

enum Source { CurvatureSignal, CurrentQuality };
constexpr int kMaxBins = 10000;
const hht::CycleQuantity kOutputs[] = {hht::CycleQuantity::Imf, hht::CycleQuantity::Amplitude,
                                       hht::CycleQuantity::Frequency, hht::CycleQuantity::Phase,
                                       hht::CycleQuantity::Residue};

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichEnum("source", CurvatureSignal, QStringList{"Curvature signal (G = 2H)", "Current vertex quality"},
                      "Signal to analyse",
                      "The per-vertex signal to decompose: the paper's curvature signal G = <L V, n>, or "
                      "whatever is in vertex quality now (e.g. from another filter)."));
  p.addParam(RichEnum("output", 0,
                      QStringList{"IMF", "Instantaneous amplitude", "Instantaneous frequency", "Instantaneous phase",
                                  "Residue"},
                      "Result written to quality",
                      "What goes into vertex quality: IMF k itself, its instantaneous amplitude, frequency (cycles "
                      "per sample along the cycle) or phase (radians), or the residue."));
  p.addParam(RichInt("imf", 1, "IMF number (1 = finest)",
                     "Which IMF the output refers to; 1 is the finest (highest frequency). Refused when the "
                     "decomposition has fewer IMFs; vertices of a component with fewer IMFs get 0."));
  p.addParam(RichFloat("rampPercentile", 2.0f, "Colour ramp clipping (%)",
                       "The colour ramp spans this percentile to its complement of the written values (0 to 50)."));
  p.addParam(RichSaveFile("histogramFile", "", "*.png", "Save frequency distribution to",
                          "If set, saves the amplitude-weighted distribution of instantaneous frequency of each IMF "
                          "(the paper's Fig. 3) as a PNG plot and a CSV table beside it (same name, .csv)."));
  p.addParam(RichInt("bins", 50, "Histogram bins", QString("Number of frequency bins over [0, 0.5] cycles per sample (1 to %1).").arg(kMaxBins)));
  declare_cycle_and_emd_parameters(p);
}

bool apply(FilterRun& run) {
  Stopwatch clock, total;
  MeshModel& model = *run.document.mm();
  hht::Positions positions;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  const RichParameterList& par = run.parameters;
  const int imf = par.getInt("imf") - 1;
  const int output = std::clamp(par.getEnum("output"), 0, 4);
  if (imf < 0 && kOutputs[output] != hht::CycleQuantity::Residue) {
    run.error = "Nothing was changed: the IMF number starts at 1 (the finest IMF).";
    return false;
  }
  if (!check_emd_parameters(par, run.error) ||
      !check_range("the colour ramp clipping", par.getFloat("rampPercentile"), 0, 50, run.error, " percent") ||
      !check_range("the histogram bins", par.getInt("bins"), 1, kMaxBins, run.error))
    return false;

  std::string message;
  Eigen::VectorXd signal;
  if (par.getEnum("source") == CurrentQuality) {
    if (!model.hasDataMask(MeshModel::MM_VERTQUALITY)) {
      run.error = "Nothing was changed: the mesh has no vertex quality to analyse.";
      return false;
    }
    signal = quality_on_rows(model.cm, input_map, positions.rows());
  } else {
    run.report(2, "Curvature signal");
    hht::MeanCurvature curvature;
    if (!hht::mean_curvature(positions, faces, curvature, message)) {
      run.error = nothing_changed(message);
      return false;
    }
    signal = curvature.signal;
  }
  const double signal_seconds = clock.lap();

  run.report(10, "Hamiltonian cycle");
  hht::HamiltonianCycle cycle;
  if (!hht::hamiltonian_cycle(faces, static_cast<int>(positions.rows()), cycle_options(par), cycle, message)) {
    run.error = nothing_changed(message);
    return false;
  }
  const double cycle_seconds = clock.lap();

  run.report(20, "Empirical mode decomposition");
  hht::CycleDecomposition decomposition;
  if (!hht::decompose_along_cycle(cycle, signal, emd_options(par), decomposition, message)) {
    run.error = nothing_changed(message);
    return false;
  }
  const double emd_seconds = clock.lap();
  if (kOutputs[output] != hht::CycleQuantity::Residue && imf >= decomposition.imf_count()) {
    run.error = QString("Nothing was changed: the decomposition has %1 IMFs, IMF %2 was asked for.")
                    .arg(decomposition.imf_count()).arg(imf + 1);
    return false;
  }
  run.report(60, "Hilbert spectra");
  hht::compute_spectra(decomposition);
  const double spectra_seconds = clock.lap();

  QString saved;
  const QString histogram_file = par.getSaveFileName("histogramFile");
  if (!histogram_file.isEmpty()) {
    run.report(80, "Saving the frequency distribution");
    if (!save_frequency_distribution(hht::frequency_distribution(decomposition, par.getInt("bins")),
                                     histogram_file, saved, run.error)) {
      run.error = "Nothing was changed: " + run.error + ".";
      return false;
    }
  }

  run.report(90, "Writing the result into vertex quality");
  const Eigen::VectorXd values = hht::quantity_on_vertices(cycle, decomposition, kOutputs[output], imf, faces);
  std::pair<double, double> range;
  if (!show_as_quality(model, values, par.getFloat("rampPercentile"), range, run.error, input_map)) return false;

  run.log(QString("Hilbert spectra of the %1 along the Hamiltonian cycle (%2 vertices, %3 on the cycle, %4 segment(s))")
              .arg(par.getEnum("source") == CurrentQuality ? "vertex quality" : "curvature signal G = 2H")
              .arg(positions.rows()).arg(cycle.order.size()).arg(cycle.components));
  const auto summary = hht::summarize_imfs(decomposition);
  run.log(QString("  %1 IMFs; per IMF: sifts, mean instantaneous frequency (cycles/sample), share of energy:")
              .arg(summary.size()));
  for (const QString& line : imf_summary_lines(summary)) run.log(line);
  run.log(QString("  quality = %1%2, colour ramp over [%3, %4]")
              .arg(QStringList{"IMF", "instantaneous amplitude of IMF", "instantaneous frequency of IMF",
                               "instantaneous phase of IMF", "residue"}[output])
              .arg(kOutputs[output] == hht::CycleQuantity::Residue ? QString() : QString(" %1").arg(imf + 1))
              .arg(range.first).arg(range.second));
  if (!saved.isEmpty()) run.log("  frequency distribution saved to " + saved);
  run.log(QString("  times (s): signal %1, cycle %2, EMD %3, spectra %4, total %5")
              .arg(signal_seconds, 0, 'f', 3).arg(cycle_seconds, 0, 'f', 3).arg(emd_seconds, 0, 'f', 3)
              .arg(spectra_seconds, 0, 'f', 3).arg(total.seconds(), 0, 'f', 3));
  return true;
}

}  // namespace

FilterSpec hilbert_spectra_filter() {
  return {"HHT: Hilbert Spectra",
          "Decomposes a per-vertex signal read along a Hamiltonian cycle by 1D Empirical Mode Decomposition "
          "(periodic cubic-spline envelopes, SD stopping rule) into intrinsic mode functions (IMFs) and a residue, "
          "then computes each IMF's Hilbert spectrum: instantaneous amplitude, phase and frequency (HHT pipeline, "
          "steps 3 and 5 of the paper's Fig. 1).<br>"
          "Writes one chosen result per vertex into quality, with a colour ramp; logs per IMF the sifts, the mean "
          "frequency and the share of energy; can save the frequency distribution (the paper's Fig. 3) as PNG and "
          "CSV. Frequencies are in cycles per sample along the cycle (0 to 0.5). Where an IMF's amplitude is "
          "below 1e-3 of its RMS, or its phase steps backwards, its frequency is taken as the IMF's "
          "amplitude-weighted mean frequency.",
          MeshLabFilter::FilterClass(MeshLabFilter::Quality | MeshLabFilter::VertexColoring),
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR,
          declare,
          apply};
}

}  // namespace hht_plugin
