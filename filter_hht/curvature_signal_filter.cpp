// "HHT: Curvature Signal": the paper's per-vertex signal G = <L V, n> (= 2H), into quality.
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "mesh/mean_curvature.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichFloat("rampPercentile", 2.0f, "Colour ramp clipping (%)",
                       "The colour ramp spans the values between this percentile and its complement "
                       "(2 -> 2nd to 98th percentile; 0 to 50), so a few extreme vertices do not flatten it."));
  p.addParam(RichBool("intrinsicDelaunay", true, "Intrinsic Delaunay Laplacian",
                      "Take L over the intrinsic Delaunay triangulation of the surface (its edges flipped, as "
                      "paths on the surface, until every weight is positive; faces of no area first given a "
                      "minimal width): the surface and vertices stay, slivers no longer make G erratic (on a sphere "
                      "of irregular triangles G comes 2-3 times closer to 2/r). Off: the mesh's own triangles, the "
                      "paper's L and the signal the HHT filters decompose and rebuild with. On a mesh already "
                      "Delaunay both are the same."));
}

bool apply(FilterRun& run) {
  Stopwatch clock;
  MeshModel& model = *run.document.mm();
  hht::Positions positions;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map) ||
      !check_range("the colour ramp clipping", run.parameters.getFloat("rampPercentile"), 0, 50, run.error, " percent"))
    return false;

  const bool intrinsic = run.parameters.getBool("intrinsicDelaunay");
  run.report(10, intrinsic ? "Intrinsic Delaunay triangulation, cotangent Laplacian, mixed Voronoi areas"
                           : "Cotangent Laplacian and mixed Voronoi areas");
  hht::MeanCurvature curvature;
  std::string message;
  if (!hht::mean_curvature(positions, faces, curvature, message,
                           intrinsic ? hht::LaplacianTriangles::IntrinsicDelaunay : hht::LaplacianTriangles::Mesh)) {
    run.error = nothing_changed(message);
    return false;
  }
  run.report(90, "Writing the signal into vertex quality");
  std::pair<double, double> range;
  if (!show_as_quality(model, curvature.signal, run.parameters.getFloat("rampPercentile"), range, run.error, input_map))
    return false;
  const Eigen::VectorXd& g = curvature.signal;
  if (intrinsic && curvature.delaunay.intrinsic)
    run.log(QString("Laplacian over the intrinsic Delaunay triangulation: %1 edges flipped%2")
                .arg(curvature.delaunay.flips)
                .arg(curvature.delaunay.mollified > 0
                         ? QString(", edge lengths widened by %1 mean edges for faces of no area")
                               .arg(curvature.delaunay.mollified, 0, 'g', 2)
                         : QString()));
  else if (intrinsic)
    run.log("Laplacian over the mesh's own triangles: the intrinsic Delaunay triangulation needs every edge "
            "shared by at most two faces and an orientable surface");
  run.log(QString("Curvature signal G = <L V, n> = 2H on %1 vertices: min %2, max %3, mean %4; "
                  "colour ramp over [%5, %6]; %7 s")
              .arg(g.size()).arg(g.minCoeff()).arg(g.maxCoeff()).arg(g.mean())
              .arg(range.first).arg(range.second).arg(clock.seconds(), 0, 'f', 3));
  return true;
}

}  // namespace

FilterSpec curvature_signal_filter() {
  return {"HHT: Curvature Signal",
          "Computes the signal the HHT pipeline decomposes (step 2): G<sub>i</sub> = &lt;(L V)<sub>i</sub>, "
          "n<sub>i</sub>&gt;, the normal component of the cotangent Laplacian L = M<sup>-1</sup>C (mixed Voronoi "
          "areas M, Meyer et al. 2003) at each vertex, with area-weighted vertex normals n. "
          "<b>Convention: G = 2H</b>, twice the mean curvature: 2/r on a sphere of radius r with outward normals, "
          "negative in concave regions. By default L is taken over the intrinsic Delaunay triangulation "
          "(Bobenko and Springborn 2007; ours here, for slivers), with <i>intrinsicDelaunay</i> off over the "
          "mesh's own triangles: the paper's L, the quantity the HHT filters decompose and rebuild with.<br>"
          "Written into vertex quality and shown as a colour ramp over a robust percentile range.",
          MeshLabFilter::FilterClass(MeshLabFilter::Quality | MeshLabFilter::VertexColoring |
                                           MeshLabFilter::Normal),
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR,
          declare,
          apply};
}

}  // namespace hht_plugin
