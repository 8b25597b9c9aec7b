#include "reconstruction/cutoff_selection.h"

#include "mesh/breadth_first_patches.h"
#include "reconstruction/biharmonic_low_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace hht {

bool select_cutoff(const VertexAdjacency& full_adjacency, const Positions& full_positions, const Positions& full_normals,
                   const CutoffSelectionOptions& options, CutoffSelection& selection, std::string& error,
                   const std::function<void(double)>& progress) {
  selection = CutoffSelection{};
  const bool sample = full_adjacency.vertices() > options.sample_vertices;
  std::vector<int> kept;
  VertexAdjacency sampled_adjacency;
  Positions sampled_positions, sampled_normals;
  if (sample) {
    kept = breadth_first_patches(full_adjacency, options.sample_vertices, options.patches);
    sampled_adjacency = adjacency_among(full_adjacency, kept);
    sampled_positions = rows_at(full_positions, kept);
    sampled_normals = rows_at(full_normals, kept);
  }
  const VertexAdjacency& adjacency = sample ? sampled_adjacency : full_adjacency;
  const Positions& v = sample ? sampled_positions : full_positions;
  const Positions& normals = sample ? sampled_normals : full_normals;
  const int n = adjacency.vertices();
  selection.sampled_vertices = n;

  // Three Rademacher probes, fixed (a deterministic generator: the same choice on every run).
  Positions probes(n, 3);
  uint64_t state = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      probes(i, k) = (state >> 63) ? 1.0 : -1.0;
    }
  double trace_k = 0;
  for (int i = 0; i < n; ++i) trace_k += adjacency.valence(i);
  if (!(trace_k > 0)) {
    error = "no edge to choose the cut-off on";
    return false;
  }

  auto score = [&](double mu, double& g) {
    Positions x, a;
    BiharmonicLowPassReport report;
    if (!biharmonic_low_pass(adjacency, v, mu, options.first_order, options.max_error, x, report)) return false;
    selection.iterations += report.iterations;
    if (!biharmonic_low_pass(adjacency, probes, mu, options.first_order, options.max_error, a, report)) return false;
    selection.iterations += report.iterations;
    Eigen::VectorXd removed(n);
    for (int i = 0; i < n; ++i) removed[i] = normals.row(i).dot(x.row(i) - v.row(i));
    double d = 0, trace_ka = 0;
    for (int i = 0; i < n; ++i)
      for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) {
        if (*j < i) continue;
        d += std::pow(removed[i] - removed[*j], 2);
        trace_ka += (probes.row(i) - probes.row(*j)).dot(a.row(i) - a.row(*j)) / 3;
      }
    const double kept_fraction = 1 - trace_ka / trace_k, s2 = options.noise_sigma * options.noise_sigma;
    if (options.noise_sigma > 0) g = d - s2 * trace_k + 2 * s2 * trace_ka;
    else g = kept_fraction > 0 ? d / (kept_fraction * kept_fraction) : HUGE_VAL;
    return true;
  };

  const int grid = 1 + static_cast<int>(std::floor(std::log(options.mu_largest / options.mu_smallest) / std::log(options.step)));
  int best = 0, rises = 0;
  for (int k = 0; k < grid && rises < 2; ++k) {
    const double mu = options.mu_largest / std::pow(options.step, k);
    double g;
    if (!score(mu, g)) {
      error = "the cut-off selection's solve did not converge";
      return false;
    }
    selection.curve.push_back({mu, g});
    if (g < selection.curve[best].score) {
      best = k;
      rises = 0;
    } else if (k > best) {
      ++rises;
    }
    if (progress) progress(static_cast<double>(k + 1) / grid);
  }
  selection.mu = selection.curve[best].mu;
  // Parabola through the minimum and its two neighbours, in log mu (uniform spacing there).
  if (best > 0 && best + 1 < static_cast<int>(selection.curve.size())) {
    const double left = selection.curve[best - 1].score, mid = selection.curve[best].score,
                 right = selection.curve[best + 1].score;
    const double curvature = left - 2 * mid + right;
    if (curvature > 0) {
      const double offset = std::clamp(0.5 * (left - right) / curvature, -0.5, 0.5);  // in grid steps, + = smaller mu
      selection.mu *= std::pow(options.step, -offset);
    }
  }
  return true;
}

}  // namespace hht
