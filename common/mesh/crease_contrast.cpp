#include "mesh/crease_contrast.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace hht {

namespace {

constexpr double kFlat = 0.01;  // radians (0.57 degrees); the corpus's smoothed medians are 2-11 degrees

}  // namespace

CreaseReadings read_creases(const std::vector<DihedralAngle>& dihedral) {
  CreaseReadings readings;
  if (dihedral.empty()) return readings;
  std::vector<double> angles;
  angles.reserve(dihedral.size());
  for (const DihedralAngle& d : dihedral) angles.push_back(d.radians);
  const size_t high = static_cast<size_t>(0.98 * static_cast<double>(angles.size() - 1));
  std::nth_element(angles.begin(), angles.begin() + static_cast<std::ptrdiff_t>(high), angles.end());
  // The elements before `high` are the smaller ones: the median is among them.
  const size_t middle = (angles.size() - 1) / 2;
  std::nth_element(angles.begin(), angles.begin() + static_cast<std::ptrdiff_t>(middle), angles.begin() + static_cast<std::ptrdiff_t>(high));
  const double median = std::max(angles[middle], kFlat);
  readings.contrast = angles[high] / median;

  // Chains: the crease edges' vertices joined by union-find, each chain counted by its edges.
  const double sharp = kCreaseLineContrast * median;
  std::unordered_map<int, int> parent;
  auto find = [&](int v) {
    int root = v;
    while (parent[root] != root) root = parent[root];
    while (parent[v] != root) v = std::exchange(parent[v], root);
    return root;
  };
  std::vector<int> crease_edge_vertex;  // one end of each crease edge
  for (const DihedralAngle& d : dihedral) {
    if (!(d.radians > sharp)) continue;
    parent.try_emplace(d.a, d.a);
    parent.try_emplace(d.b, d.b);
    parent[find(d.a)] = find(d.b);
    crease_edge_vertex.push_back(d.a);
  }
  std::unordered_map<int, int> chain_edges;
  for (int v : crease_edge_vertex) ++chain_edges[find(v)];
  const double breadth = std::sqrt(static_cast<double>(dihedral.size()));
  const double on_lines = std::accumulate(chain_edges.begin(), chain_edges.end(), 0.0, [&](double sum, const auto& chain) {
    return chain.second >= kShortestCreaseLine * breadth ? sum + chain.second : sum;
  });
  readings.lines = on_lines / breadth;
  return readings;
}

double crease_contrast(const Positions& positions, const Faces& faces) {
  return read_creases(dihedral_angles(positions, faces)).contrast;
}

}  // namespace hht
