// "Bilateral Mesh Denoising" (Fleishman, Drori, Cohen-Or 2003): the paper's main competitor.
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "filters/bilateral_denoise.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  const hht::BilateralOptions d;
  p.addParam(RichFloat("sigmaC", float(d.sigma_c), "sigma_c (x mean edge length)",
                       "Closeness width, in mean edge lengths; neighbours within 2 sigma_c take part (paper: 0.4; 0.01 "
                       "to 10, the work grows with its square)."));
  p.addParam(RichFloat("sigmaS", float(d.sigma_s), "sigma_s (x mean edge length)",
                       "Width on the neighbours' offsets along the normal, in mean edge lengths: smaller keeps more "
                       "features (paper: 0.15 for the torus, 0.05 for Fandisk; 0.0001 to 100)."));
  p.addParam(RichInt("passes", d.passes, "Passes", "Iterations, normals recomputed each time (paper: 5 torus, 3 Fandisk; 0 to 1000)."));
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  hht::BilateralOptions o;
  o.sigma_c = run.parameters.getFloat("sigmaC");
  o.sigma_s = run.parameters.getFloat("sigmaS");
  o.passes = run.parameters.getInt("passes");
  if (!check_range("sigma_c", o.sigma_c, 0.01, 10, run.error, " mean edge lengths (the work grows with its square)") ||
      !check_range("sigma_s", o.sigma_s, 1e-4, 100, run.error, " mean edge lengths") ||
      !check_range("passes", o.passes, 0, 1000, run.error))
    return false;
  Stopwatch clock;
  run.report(10, "Bilateral denoising");
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string&) {
        out = hht::bilateral_denoise(positions, faces, o);
        return true;
      }, run.error, input_map))
    return false;
  run.log(QString("Bilateral mesh denoising: sigma_c %1, sigma_s %2 (x mean edge length), %3 passes; %4 s")
              .arg(o.sigma_c).arg(o.sigma_s).arg(o.passes).arg(clock.seconds(), 0, 'f', 3));
  return true;
}

}  // namespace

FilterSpec bilateral_filter() {
  return {"Bilateral Mesh Denoising",
          "Bilateral mesh denoising of <i>Fleishman, Drori and Cohen-Or</i>, <b>Bilateral mesh denoising</b>, ACM TOG "
          "22(3), 2003: each vertex moves along its normal by a bilateral average of its neighbours' offsets, with a "
          "closeness width sigma_c and a feature width sigma_s, both in mean edge lengths. The paper's competitor.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
