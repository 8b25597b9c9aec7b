#include "signal/noise_estimate.h"

#include "cycle/cycle_signal.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/mesh_checks.h"
#include "mesh/uniform_laplacian.h"
#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>

namespace hht {

namespace {

std::vector<unsigned char> boundary_vertices(const Faces& faces, int n) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * faces.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::vector<unsigned char> boundary(n, 0);
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) boundary[edges[i].first] = boundary[edges[i].second] = 1;
    i = j;
  }
  return boundary;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

Eigen::VectorXd one_ring_heights(const Positions& positions, const Faces& faces) {
  const int n = static_cast<int>(positions.rows());
  const Positions normals = area_weighted_vertex_normals(positions, faces);
  const Positions offsets = uniform_laplacian(vertex_neighbours(faces, n)) * positions;
  Eigen::VectorXd h(n);
  for (int i = 0; i < n; ++i) h[i] = offsets.row(i).dot(normals.row(i));
  return h;
}

bool estimate_noise(const Positions& positions, const Faces& faces, const HamiltonianCycle& cycle,
                    const EmdOptions& emd_options, NoiseEstimate& out, std::string& error) {
  out = NoiseEstimate{};
  if (!check_triangle_mesh(positions, faces, error)) return false;
  const int n = static_cast<int>(positions.rows());
  out.mean_edge = mean_edge_length(positions, faces);
  const auto neighbours = vertex_neighbours(faces, n);
  const auto boundary = boundary_vertices(faces, n);
  const Eigen::VectorXd h = one_ring_heights(positions, faces);

  std::vector<double> finest;
  double inverse_valence = 0;
  int interior = 0;
  const auto segments = signals_along_cycle(cycle, h);
  for (size_t s = 0; s < segments.size(); ++s) {
    EmdOptions o = emd_options;
    o.max_imfs = 1;
    const EmdResult e = emd(segments[s], o);
    if (e.imfs.empty()) continue;
    for (size_t t = 0; t < segments[s].size(); ++t) {
      const int v = cycle.order[cycle.segment_begin[s] + static_cast<int>(t)];
      if (boundary[v] || neighbours[v].empty()) continue;
      finest.push_back(e.imfs[0][t]);
      inverse_valence += 1.0 / static_cast<double>(neighbours[v].size());
      ++interior;
    }
  }
  out.samples = static_cast<int>(finest.size());
  if (finest.empty()) return true;  // too small or too flat a signal: no noise measurable
  const double centre = median(finest);
  for (double& x : finest) x = std::abs(x - centre);
  const double spread = median(finest) / 0.6745;
  out.sigma = spread / std::sqrt(1.0 + inverse_valence / interior) / kImf1Share;
  return true;
}

}  // namespace hht
