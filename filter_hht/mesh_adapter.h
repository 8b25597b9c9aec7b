// MeshLab-side helpers shared by the filters: reading the current mesh into arrays, showing
// a per-vertex scalar as quality with a colour ramp, and timing stages for the log.
#pragma once

#include "cycle/cycle_decomposition.h"
#include "mesh/mesh_arrays.h"
#include "util/stage_clock.h"

#include "meshlab_api.h"

#include <Eigen/Core>

#include <chrono>

namespace hht_plugin {

// Arrays of `m`'s live vertices and faces; fails with a message on an empty or broken mesh.
bool read_triangle_mesh(const CMeshO& m, hht::Positions& positions, hht::Faces& faces, QString& error);

// The error of a filter that stopped before touching the mesh: "Nothing was changed: <why>.".
QString nothing_changed(const std::string& why);

// New positions (one per live vertex) into the mesh, with its bounding box and normals updated.
void move_vertices(MeshModel& model, const hht::Positions& positions);

// Writes `values` (one per live vertex) into vertex quality and colours the mesh by a ramp
// over their [percent, 100 - percent] percentile range, returned.
std::pair<double, double> show_as_quality(MeshModel& model, const Eigen::VectorXd& values, double percent);

// "  times (s): cycle 0.012, emd 0.003, ..., total 0.085"
QString stage_times_line(const std::vector<hht::StageTime>& stages);

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
