#include "signal/noise_estimate.h"

#include "cycle/cycle_signal.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/flat_hinge_spikes.h"
#include "mesh/hinge_heights.h"
#include "mesh/mesh_checks.h"
#include "mesh/vertex_adjacency.h"
#include "util/parallel_for.h"
#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>

namespace hht {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double median_absolute_deviation(std::vector<double> v) {
  const double centre = median(v);
  for (double& x : v) x = std::abs(x - centre);
  return median(std::move(v));
}

}  // namespace

double folded_normal_quantile(double q) {
  double low = 0, high = 10;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (std::erf(mid / std::sqrt(2.0)) < q ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

bool NoiseEstimate::rests_on_few_samples() const { return samples > 0 && samples < kFewImfSamples; }

bool may_be_surface_detail(const NoiseEstimate& estimate) {
  return !estimate.capped() && !estimate.impulsive() && estimate.relative() >= kNoiseFree && estimate.relative() <= kCleanDetailReads;
}

Eigen::VectorXd one_ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  const int n = static_cast<int>(positions.rows());
  const Positions normals = area_weighted_vertex_normals(positions, faces);
  Eigen::VectorXd h = Eigen::VectorXd::Zero(n);
  parallel_for(0, n, [&](int first, int last) {
    for (int i = first; i < last; ++i) {
      if (adjacency.valence(i) == 0) continue;
      Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
      for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) mean += positions.row(*j);
      h[i] = (positions.row(i) - mean / adjacency.valence(i)).dot(normals.row(i));
    }
  });
  return h;
}

bool estimate_noise(const Positions& positions, const Faces& faces, const HamiltonianCycle& cycle,
                    const EmdOptions& emd_options, NoiseEstimate& out, std::string& error) {
  out = NoiseEstimate{};
  if (!check_triangle_mesh(positions, faces, error)) return false;
  const int n = static_cast<int>(positions.rows());
  out.mean_edge = mean_edge_length(positions, faces);
  const VertexAdjacency adjacency = vertex_adjacency(faces, n);
  const Eigen::VectorXd h = one_ring_heights(positions, faces, adjacency);

  std::vector<double> finest, second;
  double inverse_valence = 0;
  int interior = 0;
  const auto segments = signals_along_cycle(cycle, h);
  for (size_t s = 0; s < segments.size(); ++s) {
    EmdOptions o = emd_options;
    o.max_imfs = 2;
    const EmdResult e = emd(segments[s], o);
    if (e.imfs.empty()) continue;
    for (size_t t = 0; t < segments[s].size(); ++t) {
      const int v = cycle.order[cycle.segment_begin[s] + static_cast<int>(t)];
      if (adjacency.boundary[v] || adjacency.valence(v) == 0) continue;
      finest.push_back(e.imfs[0][t]);
      if (e.imfs.size() > 1) second.push_back(e.imfs[1][t]);
      inverse_valence += 1.0 / static_cast<double>(adjacency.valence(v));
      ++interior;
    }
  }
  out.samples = static_cast<int>(finest.size());
  if (finest.empty()) return true;  // too small or too flat a signal: no noise measurable
  const double centre = median(finest);
  double squares = 0;
  for (double x : finest) squares += (x - centre) * (x - centre);
  // the height noise's standard deviation over sigma (see the header)
  const double height_per_sigma = std::sqrt(1.0 + inverse_valence / interior);
  out.imf_rms_sigma = std::sqrt(squares / static_cast<double>(finest.size())) / height_per_sigma / kImf1Share;
  const double spread = median_absolute_deviation(finest) / 0.6745;
  out.imf_sigma = out.sigma = spread / height_per_sigma / kImf1Share;
  const double second_spread = second.empty() ? 0 : median_absolute_deviation(second) / 0.6745;
  const double detail = kDetailImfRatio * second_spread, noise_left = 1 - std::pow(kDetailImfRatio * kNoiseImf2Share, 2);
  // at most IMF 1's own reading: an IMF 2 quieter than noise alone leaves it (short segments have none)
  out.surely_noise_sigma = std::min(spread, std::sqrt(std::max(0.0, spread * spread - detail * detail) / noise_left)) /
                           height_per_sigma / kImf1Share;

  std::vector<double> hinges = hinge_heights(positions, faces, adjacency);
  if (static_cast<int>(hinges.size()) < kMinHinges) return true;
  for (double& x : hinges) x = std::abs(x);
  const auto at = hinges.begin() + static_cast<std::ptrdiff_t>(kHingeQuantile * static_cast<double>(hinges.size() - 1));
  std::nth_element(hinges.begin(), at, hinges.end());
  out.hinge_sigma = *at / folded_normal_quantile(kHingeQuantile);
  out.spikes = flat_hinge_spikes(positions, faces, adjacency);
  squares = 0;
  for (size_t v = 0; v < out.spikes.role.size(); ++v)
    if (out.spikes.role[v] == kSpike) squares += h(static_cast<Eigen::Index>(v)) * h(static_cast<Eigen::Index>(v));
  out.spikes.role.clear();
  out.spike_sigma = out.spikes.spikes > 0 ? std::sqrt(squares / out.spikes.spikes) : 0;
  out.scattered = scattered_spikes(positions, faces, adjacency);
  if (out.spikes.impulsive()) out.sigma = std::max(out.imf_sigma, std::sqrt(out.spikes.share()) * out.spike_sigma);
  else out.sigma = std::min(out.imf_sigma, kFlatHingeBound * out.hinge_sigma);
  return true;
}

}  // namespace hht
