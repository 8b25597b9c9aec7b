// MeshLab-side helpers shared by the filters: reading the current mesh into arrays, showing
// a per-vertex scalar as quality with a colour ramp, and timing stages for the log.
#pragma once

#include "cycle/cycle_decomposition.h"
#include "filters/noise_adaptive_smoothing.h"
#include "mesh/filter_input.h"
#include "mesh/mesh_arrays.h"
#include "signal/noise_estimate.h"
#include "util/stage_clock.h"

#include "meshlab_api.h"

#include <Eigen/Core>

#include <chrono>
#include <functional>
#include <string>

namespace hht_plugin {

// Arrays of `m`'s live vertices and faces; fails with a message on an empty or broken mesh.
bool read_triangle_mesh(const CMeshO& m, hht::Positions& positions, hht::Faces& faces, QString& error);

// read_triangle_mesh for a filter that works on the mesh: its arrays prepared by
// hht::prepare_filter_input (seams merged, faces against their neighbours turned, non-manifold
// vertices split one per fan; `map` says where each mesh vertex went). The mesh itself is left as
// it is. Says in `log` what was merged, turned and split.
bool read_mesh_to_filter(const CMeshO& m, hht::Positions& positions, hht::Faces& faces, QString& error,
                         const std::function<void(const QString&)>& log, hht::InputMap& map);

// The error of a filter that stopped before touching the mesh: "Nothing was changed: <why>.".
QString nothing_changed(const std::string& why);

// A library filter run on the mesh's arrays: fills `result` (one row per vertex) or returns
// false with the reason.
using PositionsWork = std::function<bool(hht::Positions& result, std::string& error)>;

// The one exit of every filter that moves vertices: runs `work`, refuses a result that is not
// finite or moved a vertex farther than hht::kMaxMoveDiagonals bounding-box diagonals
// (hht::check_result_positions), and only then writes it into the mesh, box and normals
// updated. On false the mesh is exactly as it was and `error` is "Nothing was changed: ...".
// With `map` (read_mesh_to_filter's) the result goes back to the mesh's vertices (hht::to_input_vertices).
bool move_vertices_checked(MeshModel& model, const hht::Positions& positions, hht::Positions& result,
                           const PositionsWork& work, QString& error, const hht::InputMap& map = {});

// Refuses a parameter outside [low, high] (NaN included) with a message naming it and the range
// ("Nothing was changed: <what> must lie in [low, high]<why>, not <value>.").
bool check_range(const QString& what, double value, double low, double high, QString& error,
                 const QString& why = QString());

// Writes `values` (one per live vertex) into vertex quality and colours the mesh by a ramp
// over their [percent, 100 - percent] percentile range, returned in `range`. Refuses values
// that are not finite in single precision (MeshLab's quality), leaving the mesh as it was.
// With `map` (read_mesh_to_filter's), `values` are one per row of the filter's arrays and go back
// to the mesh's vertices (hht::to_input_vertices).
bool show_as_quality(MeshModel& model, const Eigen::VectorXd& values, double percent,
                     std::pair<double, double>& range, QString& error, const hht::InputMap& map = {});

// The live vertices' quality, one per row of the filter's arrays (`rows` of them): a merged row
// takes its first vertex's, a split fan's row its vertex's.
Eigen::VectorXd quality_on_rows(const CMeshO& m, const hht::InputMap& map, Eigen::Index rows);

// "  times (s): cycle 0.012, emd 0.003, ..., total 0.085"
QString stage_times_line(const std::vector<hht::StageTime>& stages);

// How the noise level was read: "estimated from the finest IMF" or, when the flat hinges capped
// it, both readings and what the cap means.
QString noise_estimate_text(const hht::NoiseEstimate& estimate);

// The log line of the vertices impulsive noise left alone, kept by the filter (empty when none).
QString untouched_vertices_line(int kept);

// The log line of the spike removal (filters/spike_removal.h): what it moved, or that the noise was
// too dense for it alone and the despiked mesh was filtered at `despiked_sigma` (empty when it did
// not run).
QString spike_removal_line(bool removed, const hht::SpikeRemovalReport& report, int vertices, double despiked_sigma);

// How the adaptive smoothing was finished (steps 3 and 4b): "  finish chosen by recorrupted risk
// among 4: slides along the surface by Taubin's smoothing, face-normal pass kept (its risk 2.1%
// below that of the capped slides without the pass)", or that the risks could not be scored.
QString smoothing_finish_line(const hht::NoiseAdaptiveSmoothingReport& report);
// The smoothing's tangential cap when the input holds less tangential noise than isotropic noise
// (share below 1; tangential_noise.h); empty otherwise.
QString tangential_share_line(double share);

// One line per IMF: "    IMF k: s sifts, frequency f, energy e%".
QStringList imf_summary_lines(const std::vector<hht::ImfSummary>& imfs);

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  double lap() {
    const double s = seconds();
    start_ = std::chrono::steady_clock::now();
    return s;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace hht_plugin
