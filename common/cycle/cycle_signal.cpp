#include "cycle/cycle_signal.h"

namespace hht {

std::vector<std::vector<double>> signals_along_cycle(const HamiltonianCycle& cycle, const Eigen::VectorXd& values) {
  std::vector<std::vector<double>> out;
  for (size_t s = 0; s + 1 < cycle.segment_begin.size(); ++s) {
    std::vector<double> signal;
    signal.reserve(cycle.segment_begin[s + 1] - cycle.segment_begin[s]);
    for (int i = cycle.segment_begin[s]; i < cycle.segment_begin[s + 1]; ++i) signal.push_back(values[cycle.order[i]]);
    out.push_back(std::move(signal));
  }
  return out;
}

Eigen::VectorXd values_on_vertices(const HamiltonianCycle& cycle, const std::vector<std::vector<double>>& segments,
                                   const Faces& faces, const Eigen::VectorXd& off_cycle) {
  Eigen::VectorXd values = off_cycle;
  for (size_t s = 0; s < segments.size(); ++s)
    for (size_t j = 0; j < segments[s].size(); ++j) values[cycle.order[cycle.segment_begin[s] + j]] = segments[s][j];
  if (cycle.isolated == 0) return values;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(values.size());
  Eigen::VectorXi count = Eigen::VectorXi::Zero(values.size());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      // each interior edge is seen twice, once per face: the mean is unaffected
      if (cycle.position[a] < 0 && cycle.position[b] >= 0) { sum[a] += values[b]; ++count[a]; }
      if (cycle.position[b] < 0 && cycle.position[a] >= 0) { sum[b] += values[a]; ++count[b]; }
    }
  for (Eigen::Index v = 0; v < values.size(); ++v)
    if (cycle.position[v] < 0 && count[v] > 0) values[v] = sum[v] / count[v];
  return values;
}

}  // namespace hht
