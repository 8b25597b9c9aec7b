#include "mesh_adapter.h"

#include "mesh/filter_input.h"
#include "mesh/mesh_checks.h"
#include "mesh/value_range.h"
#include "reconstruction/keep_untouched_vertices.h"

#include <vcg/complex/algorithms/update/color.h>

#include <cmath>
#include <set>
#include <limits>

namespace hht_plugin {

bool read_triangle_mesh(const CMeshO& m, hht::Positions& positions, hht::Faces& faces, QString& error) {
  hht::mesh_to_arrays(m, positions, faces);
  std::string message;
  if (!hht::check_triangle_mesh(positions, faces, message)) {
    error = nothing_changed(message);
    return false;
  }
  return true;
}

bool read_mesh_to_filter(const CMeshO& m, hht::Positions& positions, hht::Faces& faces, QString& error,
                         const std::function<void(const QString&)>& log, hht::InputMap& map) {
  if (!read_triangle_mesh(m, positions, faces, error)) return false;
  const Eigen::Index vertices = positions.rows();
  hht::FilterInputReport report;
  hht::prepare_filter_input(positions, faces, true, map, report);
  if (report.repeated_faces > 0)
    log(QString("Repeated faces: %1 of %2 faces have the same three vertices as another: the filter worked without "
                "the repeats, which add no surface; the mesh keeps them (Cleaning and Repairing > Remove Duplicate "
                "Faces removes them for good)")
            .arg(report.repeated_faces).arg(m.FN()));
  if (report.merged > 0)
    log(QString("Seams: %1 of %2 vertices sat exactly on another at a border (faces not joined there, as in a "
                "triangle soup or a mesh cut at texture seams): the filter worked on them merged%3 and gives each "
                "copy the same result, so the seams stay closed (Cleaning and Repairing > Merge Close Vertices joins "
                "them for good)")
            .arg(report.merged).arg(vertices)
            .arg(report.dropped_faces > 0
                     ? QString(", without the %1 faces that merging left with no area").arg(report.dropped_faces)
                     : QString()));
  else if (!report.not_merged_why.empty())
    log(QString("Seams: border vertices sit on each other but were left apart: %1")
            .arg(QString::fromStdString(report.not_merged_why)));
  const hht::OrientationRepair& repair = report.orientation;
  if (repair.flipped > 0)
    log(QString("Orientation: %1 of %2 faces (in %3 connected part%4) ran against their neighbours' orientation: the "
                "filter worked on them turned to agree, the mesh's own faces are left as they were (Normals, Curvatures "
                "and Orientation > Re-Orient all faces coherentely turns them for good)")
            .arg(repair.flipped).arg(faces.rows()).arg(repair.components).arg(repair.components == 1 ? "" : "s"));
  else if (!repair.done && !repair.why_not.empty())
    log(QString("Orientation: the faces could not be checked: %1").arg(QString::fromStdString(repair.why_not)));
  if (report.cut_edges > 0) {
    log(QString("Non-manifold: %1 shared by more than two faces (a fin on the surface, sheets meeting along an edge)"
                ": the filter worked on each side of them apart, on copies of their vertices (%2 more), "
                "and gives each vertex the result of its copy inside the surface, so the mesh stays as "
                "connected as it was (Cleaning and Repairing > Repair non Manifold Edges makes it manifold for good, by "
                "removing faces)")
            .arg(report.cut_edges == 1 ? QString("1 edge") : QString("%1 edges").arg(report.cut_edges))
            .arg(report.split));
  } else if (report.split > 0) {
    const int split_vertices = static_cast<int>(std::set<int>(map.copy_of.begin(), map.copy_of.end()).size());
    log(QString("Non-manifold: %1 where several fans of faces meet: the filter worked on one copy per fan (%2 more) "
                "and gives each the result of the copy with the most area around it, so the mesh stays as connected "
                "as it was (Cleaning and Repairing > Repair non Manifold Vertices by splitting splits them for good)")
            .arg(split_vertices == 1 ? QString("1 vertex") : QString("%1 vertices").arg(split_vertices))
            .arg(report.split));
  }
  return true;
}

QString nothing_changed(const std::string& why) {
  return QString::fromStdString("Nothing was changed: " + why + ".");
}

bool move_vertices_checked(MeshModel& model, const hht::Positions& positions, hht::Positions& result,
                           const PositionsWork& work, QString& error, const hht::InputMap& map) {
  std::string message;
  if (!work(result, message) || !hht::check_result_positions(positions, result, message)) {
    error = nothing_changed(message);
    return false;
  }
  hht::set_vertex_positions(model.cm, hht::to_input_vertices(result, map));
  update_box_and_normals(model);
  return true;
}

bool check_range(const QString& what, double value, double low, double high, QString& error, const QString& why) {
  if (value >= low && value <= high) return true;
  error = QString("Nothing was changed: %1 must lie in [%2, %3]%4, not %5.").arg(what).arg(low).arg(high).arg(why).arg(value);
  return false;
}

Eigen::VectorXd quality_on_rows(const CMeshO& m, const hht::InputMap& map, Eigen::Index rows) {
  Eigen::VectorXd out = Eigen::VectorXd::Constant(rows, std::numeric_limits<double>::quiet_NaN());
  int i = 0;
  for (const auto& v : m.vert) {
    if (v.IsD()) continue;
    const Eigen::Index row = map.row(i++);
    if (std::isnan(out[row])) out[row] = v.cQ();
  }
  const Eigen::Index base = rows - static_cast<Eigen::Index>(map.copy_of.size());
  for (size_t k = 0; k < map.copy_of.size(); ++k) out[base + static_cast<Eigen::Index>(k)] = out[map.copy_of[k]];
  return out;
}

bool show_as_quality(MeshModel& model, const Eigen::VectorXd& row_values, double percent,
                     std::pair<double, double>& range, QString& error, const hht::InputMap& map) {
  const Eigen::VectorXd values = hht::to_input_vertices(row_values, map);
  const double largest = std::numeric_limits<float>::max();
  Eigen::Index bad = 0;
  for (double value : values) bad += std::abs(value) <= largest ? 0 : 1;  // NaN counts too
  if (bad > 0) {
    error = nothing_changed("the result has " + std::to_string(bad) +
                            " vertices with a value that is NaN, infinite or beyond single precision");
    return false;
  }
  model.updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  hht::set_vertex_quality(model.cm, values);
  range = hht::percentile_range(values, percent);
  vcg::tri::UpdateColor<CMeshO>::PerVertexQualityRamp(model.cm, static_cast<float>(range.first),
                                                      static_cast<float>(range.second));
  return true;
}

QString stage_times_line(const std::vector<hht::StageTime>& stages) {
  QString line = "  times (s):";
  double total = 0;
  for (const auto& s : stages) {
    line += QString(" %1 %2,").arg(s.stage).arg(s.seconds, 0, 'f', 3);
    total += s.seconds;
  }
  return line + QString(" total %1").arg(total, 0, 'f', 3);
}

QString smoothing_finish_line(const hht::NoiseAdaptiveSmoothingReport& report) {
  const QString chosen = QString("slides along the surface %1, face-normal pass %2")
                             .arg(report.taubin_slide ? "by Taubin's smoothing" : "capped")
                             .arg(report.face_normal_pass ? "kept" : "left out");
  if (report.finishes_scored < 2) return "  finish: " + chosen;
  if (!report.finish_risk_scored)
    return "  finish: " + chosen + " (the finishes' risks could not be scored: a copy's smoothing did not converge)";
  return QString("  finish chosen by recorrupted risk among %1: %2 (%3)")
      .arg(report.finishes_scored)
      .arg(chosen)
      .arg(report.finish_risk_change < 0
               ? QString("its risk %1% below that of the capped slides without the pass")
                     .arg(-100 * report.finish_risk_change, 0, 'g', 2)
               : QString("the lowest risk"));
}

QString tangential_share_line(double share) {
  if (!(share < 1)) return {};
  return QString("  slides along the surface capped at %1% of what isotropic noise of that sigma allows: the input's "
                 "tangential offsets hold no more%2")
      .arg(100 * share, 0, 'f', 0)
      .arg(share < 0.5 ? " (noise mostly along the normals)" : "");
}

namespace {

QString estimate_source_text(const hht::NoiseEstimate& e) {
  if (hht::may_be_surface_detail(e))
    return QString("estimated from the finest IMF; clean meshes read up to %1% from their own detail at the scale of "
                   "their edges, which no estimate tells from noise; the noise is at least %2% (a lower bound: what the "
                   "finest IMF holds beyond the most such detail the second IMF allows): if this mesh had little or "
                   "no noise, undo and give noisePercent")
        .arg(100 * hht::kCleanDetailReads, 0, 'f', 0)
        .arg(100 * e.surely_noise_sigma / e.mean_edge, 0, 'f', 1);
  if (e.scattered_impulsive())
    return QString("estimated: impulsive noise, %1 vertices stand off their one-rings far beyond the heights around "
                   "them (%2% of the vertices); the finest IMF read %3%")
        .arg(e.scattered.spikes).arg(100 * e.scattered.share(), 0, 'f', 2).arg(100 * e.imf_sigma / e.mean_edge, 0, 'f', 1);
  if (e.impulsive())
    return QString("estimated: impulsive noise, %1 vertices stand off exactly flat surroundings (%2% of the vertices "
                   "amid them): the flat hinges read the part the noise left alone and do not cap the estimate; the "
                   "finest IMF read %3%, the spikes %4%")
        .arg(e.spikes.spikes).arg(100 * e.spikes.share(), 0, 'f', 1).arg(100 * e.imf_sigma / e.mean_edge, 0, 'f', 1)
        .arg(100 * std::sqrt(e.spikes.share()) * e.spike_sigma / e.mean_edge, 0, 'f', 1);
  if (!e.capped()) return "estimated from the finest IMF";
  return QString("estimated: the finest IMF read %1%, capped at %2 x the flat hinges' %3%: exactly flat parts, "
                 "so the IMF read the triangulation, not noise%4")
      .arg(100 * e.imf_sigma / e.mean_edge, 0, 'f', 1).arg(hht::kFlatHingeBound)
      .arg(100 * e.hinge_sigma / e.mean_edge, 0, 'f', 2)
      .arg(e.relative() < hht::kNoiseFree ? "; the mesh reads as noise-free and is left as it is (so does a noisy mesh "
                                            "cut into flat pieces afterwards, as Midpoint subdivision cuts each face "
                                            "into four)"
                                          : "");
}

}  // namespace

QString noise_estimate_text(const hht::NoiseEstimate& e) {
  if (!e.rests_on_few_samples()) return estimate_source_text(e);
  return QString("%1; read over only %2 vertices (the others lie on a boundary or in pieces too short for EMD), so "
                 "it may be far off: if the result is too weak or too strong, undo and give noisePercent")
      .arg(estimate_source_text(e))
      .arg(e.samples);
}

QString untouched_vertices_line(int kept) {
  if (kept == 0) return QString();
  return QString("  impulsive noise: %1 vertices on exactly flat hinges, which the noise left alone, kept as they were; "
                 "the others fitted to the result's face normals (%2 iterations)")
      .arg(kept).arg(hht::kUntouchedFitIterations);
}

QString spike_removal_line(bool removed, const hht::SpikeRemovalReport& r, int vertices, double despiked_sigma) {
  if (r.moved_vertices == 0) return QString();
  const QString direction = r.across ? QString("moved across the surface too: offsets along it cut back")
                                     : QString("moved along the normals (offset across over usual %1): offsets along "
                                               "the surface kept").arg(r.across_ratio, 0, 'f', 2);
  if (removed)
    return QString("  impulsive noise: %1 spikes put back onto their neighbours' surface in %2 rounds (%3); every other "
                   "vertex left exactly as it was (if the whole surface is noisy too, apply the filter again: without "
                   "the spikes it reads that noise and filters it)")
        .arg(r.moved_vertices).arg(r.rounds).arg(direction);
  return QString("  impulsive noise too dense for the spike removal alone (it moved %1 of %2 vertices, over %3%; %4): "
                 "the despiked mesh filtered as any noise, at the level of what it left: sigma %5% of the mean edge, read "
                 "from the finest IMF's RMS, as that noise sits on a share of the vertices")
      .arg(r.moved_vertices).arg(vertices).arg(100 * hht::kSparseSpikes, 0, 'f', 0).arg(direction)
      .arg(100 * despiked_sigma, 0, 'f', 1);
}

QStringList imf_summary_lines(const std::vector<hht::ImfSummary>& imfs) {
  QStringList lines;
  for (size_t k = 0; k < imfs.size(); ++k)
    lines << QString("    IMF %1: %2 sifts, frequency %3, energy %4%")
                 .arg(k + 1).arg(imfs[k].sifts).arg(imfs[k].mean_frequency, 0, 'f', 4)
                 .arg(100.0 * imfs[k].energy_share, 0, 'f', 2);
  return lines;
}

}  // namespace hht_plugin
