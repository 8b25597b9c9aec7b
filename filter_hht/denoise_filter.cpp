// "HHT: Feature-Preserving Denoise": the paper's divide-and-conquer denoising (sec. 4.3).
#include "filter_spec.h"
#include "hht_parameters.h"
#include "mesh_adapter.h"

#include "feature_preserving_denoise.h"

#include <vcg/complex/allocate.h>

namespace hht_plugin {

namespace {

enum Show { ShowNothing, SelectFeatureVertices, FeatureLineLayer };

void declare(MeshDocument&, RichParameterList& p) {
  const hht::DenoiseOptions d;
  p.addParam(RichBool("detectFeatures", true, "Preserve sharp features",
                      "Detect sharp features and process them as their own signals (CAD-like models). Off: no feature "
                      "separation, for smooth models such as the paper's torus."));
  p.addParam(RichFloat("featureAngle", float(d.features.angle_degrees), "Feature angle (deg)",
                       "A crease is a feature when the (noise-filtered) normals of its two faces differ by more than "
                       "this angle: 90 on a cube edge, 0 on a plane. Lower it to catch weak creases."));
  p.addParam(RichInt("normalFilterIterations", d.features.filter_iterations, "Normal filtering passes",
                     "Passes of guided normal filtering before the feature detection votes, so that noise does not "
                     "look like creases. 0 for noise-free input."));
  p.addParam(RichFloat("cutoff", float(d.cutoff), "Cut-off frequency",
                       "Instantaneous frequencies above this (cycles per sample) are removed from the curvature "
                       "signals, along the cycle and along each feature line."));
  p.addParam(RichInt("cycles", d.cycles, "Cycles averaged",
                     "Hamiltonian cycles (different seeds) along which the non-feature signal is filtered; the results "
                     "are averaged, which removes the stripes a single cycle leaves."));
  declare_cycle_and_emd_parameters(p);
  p.addParam(RichInt("shortLinePasses", d.short_line_passes, "Laplacian passes on short lines",
                     "Feature lines too short for EMD are smoothed by this many passes of a 1D Laplacian instead."));
  p.addParam(RichFloat("lambda", float(d.reconstruction.lambda), "Position weight (lambda)",
                       "Weight of the input positions in the reconstruction, relative to the mean edge length."));
  p.addParam(RichInt("refineNormalPasses", d.refine_normal_passes, "Refinement: normal filtering passes",
                     "After the HHT reconstruction, clean the face normals by this many passes of guided normal "
                     "filtering (keeps creases) and fit the vertices to them. 0 gives the paper's method alone; the "
                     "refinement lowers the normal error well below it (docs/benchmarks.md)."));
  p.addParam(RichInt("refineVertexIterations", d.refine_vertex_iterations, "Refinement: vertex update iterations",
                     "Iterations of the vertex update towards the filtered normals (Sun et al. 2007)."));
  p.addParam(RichEnum("showFeatures", ShowNothing,
                      QStringList{"Nothing", "Select the feature vertices", "Add the feature lines as a layer"},
                      "Show the detected features",
                      "Also show the detection (the paper's Fig. 4c-d): feature vertices selected, or a new layer "
                      "with the feature lines as polylines, one colour per line."));
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
  layer->UpdateBoxAndNormals();
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions, result;
  hht::Faces faces;
  if (!read_triangle_mesh(model.cm, positions, faces, run.error)) return false;
  const RichParameterList& par = run.parameters;
  hht::DenoiseOptions o;
  o.detect_features = par.getBool("detectFeatures");
  o.features.angle_degrees = par.getFloat("featureAngle");
  o.features.filter_iterations = std::max(0, par.getInt("normalFilterIterations"));
  o.cutoff = par.getFloat("cutoff");
  o.cycles = std::max(1, par.getInt("cycles"));
  o.cycle = cycle_options(par);
  o.emd = emd_options(par);
  o.short_line_passes = std::max(0, par.getInt("shortLinePasses"));
  o.reconstruction.lambda = par.getFloat("lambda");
  o.refine_normal_passes = std::max(0, par.getInt("refineNormalPasses"));
  o.refine_vertex_iterations = std::max(0, par.getInt("refineVertexIterations"));
  if (!(o.cutoff >= 0 && o.cutoff <= 0.5) || !(o.reconstruction.lambda > 0)) {
    run.error = "Nothing was changed: the cut-off must lie in [0, 0.5] and lambda must be positive.";
    return false;
  }
  hht::DenoiseReport report;
  std::string message;
  auto progress = [&](int percent, const char* stage) { run.report(percent, stage); };
  if (!hht::feature_preserving_denoise(positions, faces, o, result, report, message, progress)) {
    run.error = nothing_changed(message);
    return false;
  }
  move_vertices(model, result);
  const int show = par.getEnum("showFeatures");
  if (show == SelectFeatureVertices) {
    size_t i = 0;
    for (auto& v : model.cm.vert) {
      if (v.IsD()) continue;
      if (report.type[i++] != hht::FeatureType::None) v.SetS(); else v.ClearS();
    }
  } else if (show == FeatureLineLayer) {
    add_feature_layer(run.document, result, report.feature_lines, "Feature lines of " + model.label());
  }

  if (o.detect_features)
    run.log(QString("Feature-preserving denoise: %1 feature vertices, %2 feature lines (%3 by EMD, %4 by 1D Laplacian), "
                    "%5 corners")
                .arg(report.feature_vertices).arg(report.lines).arg(report.lines_by_emd)
                .arg(report.lines - report.lines_by_emd).arg(report.corners));
  else
    run.log("Denoise without feature separation");
  run.log(QString("  non-feature signal: low-pass at %1 cycles/sample along %2 cycle(s), %3 IMFs on the first; "
                  "%4 of %5 vertices on it")
              .arg(o.cutoff).arg(o.cycles).arg(report.imfs.size()).arg(report.cycle.order.size()).arg(positions.rows()));
  run.log(QString("  reconstruction: lambda %1, %2 CG iterations, relative residual %3")
              .arg(o.reconstruction.lambda).arg(report.reconstruction.iterations)
              .arg(report.reconstruction.relative_residual, 0, 'g', 3));
  if (o.refine_normal_passes > 0 && o.refine_vertex_iterations > 0)
    run.log(QString("  refinement: %1 guided normal filtering passes, %2 vertex update iterations")
                .arg(o.refine_normal_passes).arg(o.refine_vertex_iterations));
  else
    run.log("  no refinement (the paper's method alone)");
  run.log(stage_times_line(report.stages));
  return true;
}

}  // namespace

FilterSpec denoise_filter() {
  return {"HHT: Feature-Preserving Denoise",
          "Denoises the mesh while keeping its sharp edges and corners, by the divide-and-conquer HHT of the paper's "
          "sec. 4.3: sharp features are detected (normal voting with neighbour support, on guided-filtered normals) "
          "and linked into feature lines; the cycle's curvature signal is sifted with feature vertices never taken as "
          "extrema and low-pass filtered on instantaneous frequency; every feature line is filtered as its own 1D "
          "signal (or by a 1D Laplacian when too short); corners of the same type share their mean signal; the mesh is "
          "rebuilt by the Laplacian least-squares solve. A refinement (not in the paper) then cleans the face normals "
          "by guided normal filtering and fits the vertices to them. The connectivity is never changed.",
          MeshFilterInterface::Smoothing,
          MeshFilterInterface::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL | MeshModel::MM_VERTFLAGSELECT,
          declare,
          apply};
}

}  // namespace hht_plugin
