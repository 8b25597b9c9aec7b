// "HHT: Feature-Centric Surface EMD" (after Hu, Wang & Qin 2014): the surface EMD with the sharp
// feature vertices kept out of the envelope fitting; the mesh rebuilt from the k-th residue.
#include "filter_spec.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"
#include "surface_emd_parameters.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  const hht::SharpFeatureOptions d;
  declare_surface_emd_parameters(p);
  p.addParam(RichFloat("featureAngle", float(d.angle_degrees), "Feature angle (deg)",
                       "An edge is a crease when the filtered normals of its faces differ by more than this (0 to 180)."));
  p.addParam(RichInt("normalFilterIterations", d.filter_iterations, "Normal filtering passes",
                     "Guided normal filtering passes before detection; 0 for noise-free meshes (0 to 1000)."));
  declare_emd_parameters(p);
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  hht::SurfaceEmdSmoothingOptions options;
  if (!surface_emd_smoothing_options(run.parameters, options, run.error)) return false;
  options.feature_centric = true;
  options.features.angle_degrees = run.parameters.getFloat("featureAngle");
  options.features.filter_iterations = run.parameters.getInt("normalFilterIterations");
  if (!check_range("the feature angle", options.features.angle_degrees, 0, 180, run.error, " degrees") ||
      !check_range("normalFilterIterations", options.features.filter_iterations, 0, 1000, run.error))
    return false;
  run.report(5, "Features, surface EMD and reconstruction");
  hht::Positions result;
  hht::SurfaceEmdSmoothingReport report;
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string& message) {
        return hht::surface_emd_smoothing(positions, faces, options, out, report, message);
      }, run.error, input_map))
    return false;
  run.log(QString("Feature-centric surface EMD: %1 feature vertices kept out of the envelopes; %2 IMFs, rebuilt from "
                  "residue %3; %4 factorisations; largest vertex move %5")
              .arg(report.feature_vertices).arg(report.imfs).arg(report.residue_used).arg(report.emd.factorizations)
              .arg(report.max_displacement));
  run.log(stage_times_line(report.stages));
  return true;
}

}  // namespace

FilterSpec feature_centric_emd_filter() {
  return {"HHT: Feature-Centric Surface EMD",
          "The surface EMD (HHT: Surface EMD) of the curvature signal with the sharp feature vertices (the detector "
          "of HHT: Feature-Preserving Denoise) kept out of the envelope fitting and every IMF zero on them, so the "
          "features stay in the residue; the mesh is rebuilt from the k-th residue. A reading of <i>Hu, Wang and "
          "Qin</i>, Graphical Models 76(5), 2014, the paper's Figs. 9d and 10d.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
