#include "mesh/crease_contrast.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace hht {

namespace {

constexpr double kFlat = 0.01;  // radians (0.57 degrees); the corpus's smoothed medians are 2-11 degrees

// The median angle, at least kFlat (a clean CAD part is mostly exactly flat).
double floored_median(std::vector<double> angles) {
  const auto middle = angles.begin() + static_cast<std::ptrdiff_t>((angles.size() - 1) / 2);
  std::nth_element(angles.begin(), middle, angles.end());
  return std::max(*middle, kFlat);
}

std::vector<double> radians(const std::vector<DihedralAngle>& dihedral) {
  std::vector<double> angles;
  angles.reserve(dihedral.size());
  for (const DihedralAngle& d : dihedral) angles.push_back(d.radians);
  return angles;
}

}  // namespace

double crease_contrast(const std::vector<DihedralAngle>& dihedral) {
  std::vector<double> angles = radians(dihedral);
  if (angles.empty()) return 0;
  const size_t high = static_cast<size_t>(0.98 * static_cast<double>(angles.size() - 1));
  std::nth_element(angles.begin(), angles.begin() + static_cast<std::ptrdiff_t>(high), angles.end());
  const double upper = angles[high];
  return upper / floored_median(std::move(angles));
}

double crease_contrast(const Positions& positions, const Faces& faces) {
  return crease_contrast(dihedral_angles(positions, faces));
}

double crease_line_length(const std::vector<DihedralAngle>& dihedral) {
  if (dihedral.empty()) return 0;
  const double sharp = kCreaseLineContrast * floored_median(radians(dihedral));
  // Chains: the crease edges' vertices joined by union-find, each chain counted by its edges.
  std::unordered_map<int, int> parent;
  auto find = [&](int v) {
    int root = v;
    while (parent[root] != root) root = parent[root];
    while (parent[v] != root) v = std::exchange(parent[v], root);
    return root;
  };
  std::vector<int> crease_edges_first_vertex;
  for (const DihedralAngle& d : dihedral) {
    if (!(d.radians > sharp)) continue;
    parent.try_emplace(d.a, d.a);
    parent.try_emplace(d.b, d.b);
    parent[find(d.a)] = find(d.b);
    crease_edges_first_vertex.push_back(d.a);
  }
  std::unordered_map<int, int> chain_edges;
  for (int v : crease_edges_first_vertex) ++chain_edges[find(v)];
  const double breadth = std::sqrt(static_cast<double>(dihedral.size()));
  const double on_lines = std::accumulate(chain_edges.begin(), chain_edges.end(), 0.0, [&](double sum, const auto& chain) {
    return chain.second >= kShortestCreaseLine * breadth ? sum + chain.second : sum;
  });
  return on_lines / breadth;
}

}  // namespace hht
