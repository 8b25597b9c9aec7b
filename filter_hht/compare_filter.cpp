// "HHT: Compare to Reference": denoising quality of the current layer against a ground truth.
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "evaluation/denoise_metrics.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument& document, RichParameterList& p) {
  const MeshModel* reference = document.mm();
  for (const MeshModel* m : layers(document))
    if (m != document.mm()) reference = m;  // another layer, when there is one
  p.addParam(mesh_parameter("reference", reference, document, "Reference (ground truth)",
                      "The noise-free mesh, with the same vertices and faces in the same order as the current layer."));
  p.addParam(RichEnum("perVertex", 0, QStringList{"Distance to the reference surface", "Normal error (degrees)"},
                      "Per-vertex error into quality",
                      "Written into the current layer's vertex quality, with a colour ramp: the distance of each vertex "
                      "to the reference surface, or the mean angle between its faces' normals and the reference's."));
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  MeshModel* reference = chosen_mesh(run.parameters, "reference", run.document);
  if (!reference) {
    run.error = "Nothing was changed: choose a reference layer.";
    return false;
  }
  hht::Positions result, truth;
  hht::Faces faces, truth_faces;
  if (!read_triangle_mesh(model.cm, result, faces, run.error) ||
      !read_triangle_mesh(reference->cm, truth, truth_faces, run.error))
    return false;
  if (result.rows() != truth.rows() || faces != truth_faces) {
    run.error = QString("Nothing was changed: the reference must have the same connectivity (%1 vertices, %2 faces here; "
                        "%3 and %4 in the reference, or faces in another order).")
                    .arg(result.rows()).arg(faces.rows()).arg(truth.rows()).arg(truth_faces.rows());
    return false;
  }
  run.report(20, "Face normal error");
  const double ea = hht::mean_face_normal_error_degrees(result, truth, faces);
  run.report(50, "Distance to the reference surface");
  const double ev = hht::mean_distance_to_reference(result, truth, faces);
  const bool by_distance = run.parameters.getEnum("perVertex") == 0;
  const Eigen::VectorXd per_vertex = by_distance ? hht::vertex_distance_to_reference(result, truth, faces)
                                                 : hht::vertex_normal_error_degrees(result, truth, faces);
  std::pair<double, double> range;
  if (!show_as_quality(model, per_vertex, 0.0, range, run.error)) return false;
  run.log(QString("Compared '%1' with the reference '%2' (%3 vertices, %4 faces):")
              .arg(model.label()).arg(reference->label()).arg(result.rows()).arg(faces.rows()));
  run.log(QString("  E_a = %1 degrees (mean over faces of the angle between result and reference face normals)").arg(ea, 0, 'f', 4));
  run.log(QString("  E_v = %1 (mean over vertices of the distance to the reference surface / its bounding-box diagonal)")
              .arg(ev, 0, 'e', 4));
  run.log(QString("  quality = %1").arg(by_distance ? "distance to the reference surface" : "normal error in degrees"));
  return true;
}

}  // namespace

FilterSpec compare_filter() {
  return {"HHT: Compare to Reference",
          "Measures a denoised mesh (the current layer) against its ground truth (another layer with the same "
          "connectivity), as the denoising papers do:<br>"
          "<b>E_a</b>: mean over faces of the angle, in degrees, between the result's and the reference's face normals;"
          "<br><b>E_v</b>: mean over the result's vertices of the distance to the reference surface (closest point on "
          "any reference triangle), divided by the reference's bounding-box diagonal.<br>"
          "Writes a per-vertex error into quality for a colour map.",
          MeshLabFilter::Measure,
          MeshLabFilter::FIXED,
          MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR,
          declare,
          apply};
}

}  // namespace hht_plugin
