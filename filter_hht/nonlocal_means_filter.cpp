// "Non-Local Means Denoising" after Yoshizawa, Belyaev & Seidel 2006 (the paper's ref. [32]).
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "filters/nonlocal_means_denoise.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  const hht::NonLocalMeansOptions d;
  p.addParam(RichFloat("eta1", float(d.eta1), "eta1: search radius (x mean edge length)",
                       "Neighbours within this distance take part; the spatial Gaussian falls to e^-2 there "
                       "(paper's torus: 3; 0.01 to 10, the work grows with its square)."));
  p.addParam(RichFloat("eta2", float(d.eta2), "eta2: similarity width (x mean edge length)",
                       "Width of the weight on the difference of the two vertices' neighbourhoods (paper's torus: "
                       "1.3; 0.0001 to 100)."));
  p.addParam(RichFloat("eta3", float(d.eta3), "eta3: stencil spacing (x mean edge length)",
                       "Ring spacing of the neighbourhood compared (paper's torus: 1.0; 0.01 to 10)."));
  p.addParam(RichInt("iterations", d.iterations, "Iterations", "Passes, normals recomputed each time (0 to 1000)."));
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  hht::NonLocalMeansOptions o;
  o.eta1 = run.parameters.getFloat("eta1");
  o.eta2 = run.parameters.getFloat("eta2");
  o.eta3 = run.parameters.getFloat("eta3");
  o.iterations = run.parameters.getInt("iterations");
  if (!check_range("eta1", o.eta1, 0.01, 10, run.error, " mean edge lengths (the work grows with its square)") ||
      !check_range("eta2", o.eta2, 1e-4, 100, run.error, " mean edge lengths") ||
      !check_range("eta3", o.eta3, 0.01, 10, run.error, " mean edge lengths") ||
      !check_range("iterations", o.iterations, 0, 1000, run.error))
    return false;
  Stopwatch clock;
  run.report(10, "Non-local means denoising");
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string&) {
        out = hht::nonlocal_means_denoise(positions, faces, o);
        return true;
      }, run.error, input_map))
    return false;
  run.log(QString("Non-local means denoising: eta1 %1, eta2 %2, eta3 %3 (x mean edge length), %4 iterations; %5 s")
              .arg(o.eta1).arg(o.eta2).arg(o.eta3).arg(o.iterations).arg(clock.seconds(), 0, 'f', 3));
  return true;
}

}  // namespace

FilterSpec nonlocal_means_filter() {
  return {"Non-Local Means Denoising",
          "Mesh denoising after <i>Yoshizawa, Belyaev and Seidel</i>, <b>Smoothing by example: mesh denoising by "
          "averaging with similarity-based weights</b>, SMI 2006: each vertex moves along its normal by a weighted "
          "mean of its neighbours' offsets, the weights combining distance (eta1) and the similarity of the two "
          "vertices' neighbourhoods (eta2, compared over rings spaced eta3), all in mean edge lengths. The formulas "
          "chosen are in common/nonlocal_means_denoise.h.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
