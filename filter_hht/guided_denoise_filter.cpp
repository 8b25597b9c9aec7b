// "Guided Normal Filtering Denoise": the field's feature-preserving denoiser on its own
// (common/guided_normal_denoise.h), the baseline the HHT denoiser is measured against.
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "filters/guided_normal_denoise.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  const hht::GuidedNormalDenoiseOptions d;
  p.addParam(RichInt("rounds", d.rounds, "Rounds",
                     "Rounds of normal filtering and vertex update (1 to 100); heavier noise wants more."));
  p.addParam(RichInt("normalPasses", d.normal_passes, "Normal filtering passes per round",
                     "Guided normal filtering passes (0 to 1000) before each vertex update."));
  p.addParam(RichFloat("sigma", float(d.sigma), "Range width (sigma_r)",
                       "Width of the range kernel on unit guidance normals (0.05 to 2): smaller keeps weaker creases, "
                       "larger smooths more (the authors' default 0.35)."));
  p.addParam(RichInt("vertexIterations", d.vertex_iterations, "Vertex update iterations per round",
                     "Iterations (0 to 1000) of the vertex update towards the filtered normals (Sun et al. 2007)."));
  p.addParam(RichEnum("guidance", 0,
                      QStringList{"Most consistent patch (guided, Zhang et al. 2015)",
                                  "The face's own normal (bilateral normal filtering, Zheng et al. 2011)"},
                      "Range kernel on",
                      "What the range kernel compares: the guidance normals of the most consistent patch around each "
                      "face, or each face's own filtered normal (bilateral normal filtering; its authors' defaults are "
                      "20 passes, 10 vertex iterations and one round: resources/bilateral_normal_denoise.mlx)."));
  p.addParam(RichBool("standUpTurnedFaces", true, "Stand up turned faces",
                      "Ours, not the published methods': faces the vertex update turned over against the input (and "
                      "not folded there) are stood back up at the end, each moved back the least share of the way "
                      "that does it. On a clean irregular mesh the filters turn hundreds of faces over without it "
                      "(docs/quality.md item 40). Off: the methods as published."));
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  hht::GuidedNormalDenoiseOptions o;
  o.rounds = run.parameters.getInt("rounds");
  o.normal_passes = run.parameters.getInt("normalPasses");
  o.sigma = run.parameters.getFloat("sigma");
  o.vertex_iterations = run.parameters.getInt("vertexIterations");
  const bool bilateral = run.parameters.getEnum("guidance") == 1;
  if (bilateral) o.guidance = hht::NormalGuidance::OwnNormal;
  o.stand_up_turned_faces = run.parameters.getBool("standUpTurnedFaces");
  if (!check_range("rounds", o.rounds, 1, 100, run.error) ||
      !check_range("normalPasses", o.normal_passes, 0, 1000, run.error) ||
      !check_range("sigma", o.sigma, 0.05, 2, run.error) ||
      !check_range("vertexIterations", o.vertex_iterations, 0, 1000, run.error))
    return false;
  Stopwatch clock;
  run.report(10, bilateral ? "Bilateral normal filtering and vertex update" : "Guided normal filtering and vertex update");
  hht::GuidedNormalDenoiseReport report;
  if (!move_vertices_checked(model, positions, result, [&](hht::Positions& out, std::string& message) {
        return hht::guided_normal_denoise(positions, faces, o, out, message, {}, &report);
      }, run.error, input_map))
    return false;
  run.log(QString("%1 normal filtering denoise: %2 round(s) of %3 passes (sigma_r %4) and %5 vertex iterations; "
                  "%6 s")
              .arg(bilateral ? "Bilateral" : "Guided")
              .arg(o.rounds).arg(o.normal_passes).arg(o.sigma).arg(o.vertex_iterations).arg(clock.seconds(), 0, 'f', 3));
  if (o.stand_up_turned_faces)
    run.log(QString("  %1 faces the vertex update turned over stood back up").arg(report.stood_up_faces));
  return true;
}

}  // namespace

FilterSpec guided_denoise_filter() {
  return {"Guided Normal Filtering Denoise",
          "Feature-preserving denoising by guided mesh normal filtering (<i>Zhang, Deng, Zhang, Bouaziz and Liu</i>, "
          "<b>Guided mesh normal filtering</b>, Pacific Graphics 2015): face normals are filtered by a joint bilateral "
          "filter whose range kernel compares guidance normals from the most consistent patch around each face, then "
          "the vertices are fitted to them (Sun et al. 2007). With the range kernel on each face's own normal it is "
          "bilateral normal filtering (<i>Zheng, Fu, Au and Tai</i>, <b>Bilateral normal filtering for mesh "
          "denoising</b>, TVCG 2011). No HHT: the baselines the HHT denoiser is measured against (docs/quality.md).",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
