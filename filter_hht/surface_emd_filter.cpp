// "HHT: Surface EMD" (3D-EMD, Wang et al. 2012): EMD of a per-vertex signal computed on the
// surface itself; an IMF or a residue into quality, or the mesh rebuilt from the k-th residue.
#include "filter_spec.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"
#include "surface_emd_parameters.h"

#include "mesh/mean_curvature.h"

namespace hht_plugin {

namespace {

enum Source { CurvatureSignal, CurrentQuality };
enum Output { ImfToQuality, ResidueToQuality, RebuildFromResidue };

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichEnum("source", CurvatureSignal, QStringList{"Curvature signal (G = 2H)", "Current vertex quality"},
                      "Signal to decompose",
                      "The paper's curvature signal G = <L V, n>, or whatever is in vertex quality now. Rebuilding "
                      "the mesh needs the curvature signal."));
  p.addParam(RichEnum("output", ImfToQuality,
                      QStringList{"IMF k into quality", "Residue k into quality", "Mesh rebuilt from residue k"},
                      "Result",
                      "IMF k (the 'IMF number') or the k-th residue (signal minus the k finest IMFs; 'Rebuild from "
                      "residue k') into vertex quality with a colour ramp, or the mesh rebuilt from the k-th "
                      "residue of G (smoothing, the paper's Figs. 9b and 10b)."));
  p.addParam(RichInt("imf", 1, "IMF number (1 = finest)", "Which IMF goes into quality."));
  declare_surface_emd_parameters(p);
  p.addParam(RichFloat("rampPercentile", 2.0f, "Colour ramp clipping (%)",
                       "The colour ramp spans this percentile to its complement of the written values (0 to 50)."));
  declare_emd_parameters(p);
}

bool apply(FilterRun& run) {
  Stopwatch total;
  MeshModel& model = *run.document.mm();
  hht::Positions positions;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  const RichParameterList& par = run.parameters;
  hht::SurfaceEmdSmoothingOptions options;
  if (!surface_emd_smoothing_options(par, options, run.error) ||
      !check_range("the colour ramp clipping", par.getFloat("rampPercentile"), 0, 50, run.error, " percent"))
    return false;
  const int output = std::clamp(par.getEnum("output"), 0, 2);
  const bool from_quality = par.getEnum("source") == CurrentQuality;
  std::string message;

  if (output == RebuildFromResidue) {
    if (from_quality) {
      run.error = "Nothing was changed: the mesh can only be rebuilt from the curvature signal (source).";
      return false;
    }
    run.report(5, "Surface EMD and reconstruction");
    hht::Positions result;
    hht::SurfaceEmdSmoothingReport report;
    if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string& why) {
          return hht::surface_emd_smoothing(positions, faces, options, out, report, why);
        }, run.error, input_map))
      return false;
    run.log(QString("Surface EMD smoothing: %1 IMFs (sifts per IMF: %2), rebuilt from residue %3; %4 "
                    "factorisations; largest vertex move %5")
                .arg(report.imfs).arg(QStringList([&] {
                  QStringList s;
                  for (int k : report.sifts) s << QString::number(k);
                  return s;
                }()).join(' ')).arg(report.residue_used).arg(report.emd.factorizations).arg(report.max_displacement));
    run.log(stage_times_line(report.stages));
    return true;
  }

  const int imf = par.getInt("imf") - 1;
  if (output == ImfToQuality && imf < 0) {
    run.error = "Nothing was changed: the IMF number starts at 1 (the finest IMF).";
    return false;
  }
  Eigen::VectorXd signal;
  if (from_quality) {
    if (!model.hasDataMask(MeshModel::MM_VERTQUALITY)) {
      run.error = "Nothing was changed: the mesh has no vertex quality to decompose.";
      return false;
    }
    signal = quality_on_rows(model.cm, input_map, positions.rows());
  } else {
    hht::MeanCurvature curvature;
    if (!hht::mean_curvature(positions, faces, curvature, message)) {
      run.error = nothing_changed(message);
      return false;
    }
    signal = curvature.signal;
  }
  run.report(10, "Surface EMD");
  hht::SurfaceEmdResult decomposition;
  if (!hht::surface_emd(positions, faces, signal, options.emd, decomposition, message)) {
    run.error = nothing_changed(message);
    return false;
  }
  const int count = static_cast<int>(decomposition.imfs.size());
  Eigen::VectorXd values;
  if (output == ImfToQuality) {
    if (imf >= count) {
      run.error = QString("Nothing was changed: the decomposition has %1 IMFs, IMF %2 was asked for.").arg(count).arg(imf + 1);
      return false;
    }
    values = decomposition.imfs[imf];
  } else {
    values = decomposition.residue;
    for (int k = std::min(options.residue, count); k < count; ++k) values += decomposition.imfs[k];
  }
  std::pair<double, double> range;
  if (!show_as_quality(model, values, par.getFloat("rampPercentile"), range, run.error, input_map)) return false;
  QStringList sifts;
  for (int k : decomposition.sifts) sifts << QString::number(k);
  run.log(QString("Surface EMD of the %1: %2 IMFs (sifts per IMF: %3), %4 factorisations")
              .arg(from_quality ? "vertex quality" : "curvature signal G = 2H").arg(count).arg(sifts.join(' '))
              .arg(decomposition.report.factorizations));
  run.log(QString("  quality = %1, colour ramp over [%2, %3]; %4 s")
              .arg(output == ImfToQuality ? QString("IMF %1").arg(imf + 1)
                                          : QString("residue %1").arg(std::min(options.residue, count)))
              .arg(range.first).arg(range.second).arg(total.seconds(), 0, 'f', 3));
  return true;
}

}  // namespace

FilterSpec surface_emd_filter() {
  return {"HHT: Surface EMD",
          "Empirical Mode Decomposition computed on the surface itself (the 3D-EMD of <i>Wang et al.</i>, Graphical "
          "Models 74(4), 2012, the baseline of the paper's Table 1): extrema are vertices above (below) all their "
          "one-ring neighbours, envelopes are bi-harmonic fields (cotangent weights, Voronoi areas) through them, "
          "with the 1D EMD's SD and 15-extrema stopping rules.<br>Writes IMF k or the k-th residue into quality, or "
          "rebuilds the mesh from the k-th residue of the curvature signal (smoothing, the paper's Figs. 9b, 10b). "
          "One sparse factorisation per envelope and sift: much slower than HHT: Hilbert Spectra on large meshes.",
          // Not in Quality: the window test clicks that menu's items by position.
          MeshLabFilter::FilterClass(MeshLabFilter::VertexColoring | MeshLabFilter::Smoothing),
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL |
              MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
