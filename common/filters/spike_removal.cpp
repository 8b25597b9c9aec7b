#include "filters/spike_removal.h"

#include "mesh/scattered_spikes.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {

namespace {
constexpr unsigned char kOffAlong = 1, kOffAcross = 2;  // how a spike stands off its ring

// Whether the first round's height spikes stand off across the normal too: the median over them
// of their offset across over their two-ring's median one, against kAcrossRatio. Too few spikes
// to tell: across, as a move in any direction needs.
bool moves_across(const std::vector<unsigned char>& spike, const Eigen::VectorXd& across_length,
                  const VertexAdjacency& adjacency, double& median_ratio) {
  std::vector<double> ratios;
  TwoRingScratch scratch;
  for (int v = 0; v < adjacency.vertices(); ++v) {
    if (spike[static_cast<size_t>(v)] != kOffAlong) continue;
    const double usual = two_ring_height_quantile(across_length, adjacency, v, 0.5, scratch);
    if (usual > 0) ratios.push_back(across_length[v] / usual);
  }
  median_ratio = 0;
  if (static_cast<int>(ratios.size()) < kMinScatteredSpikes) return true;
  const auto mid = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), mid, ratios.end());
  median_ratio = *mid;
  return median_ratio > kAcrossRatio;
}
}  // namespace

Positions remove_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                        SpikeRemovalReport& report) {
  report = SpikeRemovalReport{};
  const int n = adjacency.vertices();
  Positions out = positions;
  std::vector<unsigned char> moved(static_cast<size_t>(n), 0), spike(static_cast<size_t>(n), 0),
      off_across(static_cast<size_t>(n), 0);
  // A vertex's test reads the positions within three rings of it: after the first round only the
  // vertices that near a move can change their answer (the others are skipped, the same result).
  std::vector<unsigned char> active(static_cast<size_t>(n), 1);
  std::vector<int> front, next, touched;
  const IndexLists around = vertex_faces(faces, n);
  RingHeights ring = ring_heights(out, faces, adjacency, around);
  const Eigen::VectorXd& h = ring.height;
  // Each vertex's offset from its ring's centroid across the normal: the triangulation's own
  // irregularity, plus a moved vertex's move across the normal.
  Positions across(n, 3);
  Eigen::VectorXd across_length(n);
  const auto update_across = [&](int v) {
    across.row(v) = (out.row(v) - ring.centroid.row(v)) - h[v] * ring.normal.row(v);
    across_length[v] = across.row(v).norm();
  };
  parallel_for(0, n, [&](int first, int last) {
    for (int v = first; v < last; ++v) update_across(v);
  });
  for (int round = 0; round < kRemovalRounds; ++round) {
    parallel_for(0, n, [&](int first, int last) {
      TwoRingScratch scratch;
      for (int v = first; v < last; ++v) {
        spike[static_cast<size_t>(v)] = 0;
        if (!active[static_cast<size_t>(v)] || adjacency.valence(v) < 3 || adjacency.boundary[static_cast<size_t>(v)]) continue;
        const double a = std::abs(h[v]);
        bool highest = a > kSpikeStandOff * mean_ring_edge(out, adjacency, v);
        for (const int* j = adjacency.begin(v); j != adjacency.end(v) && highest; ++j) highest = a >= std::abs(h[*j]);
        if (highest) {
          // Exactly flat surroundings (scale 0) are flat_hinge_spikes.h's: a CAD part's corners stand so.
          const double scale = two_ring_height_quantile(h, adjacency, v, 0.5, scratch);
          spike[static_cast<size_t>(v)] = scale > 0 && a > kRemovalScale * scale ? kOffAlong : 0;
        }
      }
    });
    if (round == 0) report.across = moves_across(spike, across_length, adjacency, report.across_ratio);
    // Or across the normal: moved in a random direction, a vertex may stand off its ring's
    // centroid mostly along the surface; the same test on its offset across the normal, for the
    // vertices no spike found above touches (a spike shifts its neighbours' centroids).
    if (report.across) parallel_for(0, n, [&](int first, int last) {
      TwoRingScratch scratch;
      for (int v = first; v < last; ++v) {
        off_across[static_cast<size_t>(v)] = 0;
        if (!active[static_cast<size_t>(v)] || spike[static_cast<size_t>(v)] || adjacency.valence(v) < 3 || adjacency.boundary[static_cast<size_t>(v)]) continue;
        const double t = across_length[v];
        bool widest = t > kSpikeStandOff * mean_ring_edge(out, adjacency, v);
        for (const int* j = adjacency.begin(v); j != adjacency.end(v) && widest; ++j)
          widest = t >= across_length[*j] && spike[static_cast<size_t>(*j)] != kOffAlong;
        if (!widest) continue;
        const double scale = two_ring_height_quantile(across_length, adjacency, v, 0.5, scratch);
        off_across[static_cast<size_t>(v)] = scale > 0 && t > kRemovalScale * scale;
      }
    });
    for (size_t v = 0; v < spike.size(); ++v)
      if (off_across[v]) spike[v] = kOffAcross;
    int count = 0;
    TwoRingScratch scratch;
    front.clear();
    for (int v = 0; v < n; ++v) {
      if (!spike[static_cast<size_t>(v)]) continue;
      front.push_back(v);
      // Each neighbour's height holds 1 / its valence of v's move, against it: the move that
      // leaves v at its neighbours' mean height after the move.
      double mean = 0, share = 0;
      for (const int* j = adjacency.begin(v); j != adjacency.end(v); ++j) {
        mean += h[*j];
        share += 1.0 / adjacency.valence(*j);
      }
      mean /= adjacency.valence(v);
      share /= adjacency.valence(v);
      if (spike[static_cast<size_t>(v)] == kOffAlong) out.row(v) += (mean - h[v]) / (1 + share) * ring.normal.row(v);
      // A move across the normal too (noise in random directions): the offset across cut back to
      // the two-ring's median one.
      const double usual = two_ring_height_quantile(across_length, adjacency, v, 0.5, scratch);
      if (across_length[v] > usual) out.row(v) -= (1 - usual / across_length[v]) * across.row(v);
      report.moved_vertices += !moved[static_cast<size_t>(v)];
      moved[static_cast<size_t>(v)] = 1;
      ++count;
    }
    if (count == 0) break;
    ++report.rounds;
    std::fill(active.begin(), active.end(), 0);
    for (int v : front) active[static_cast<size_t>(v)] = 1;
    touched = front;
    for (int ring_step = 0; ring_step < 3; ++ring_step) {
      next.clear();
      for (int v : front)
        for (const int* j = adjacency.begin(v); j != adjacency.end(v); ++j)
          if (!active[static_cast<size_t>(*j)]) {
            active[static_cast<size_t>(*j)] = 1;
            next.push_back(*j);
          }
      if (ring_step == 0) touched.insert(touched.end(), next.begin(), next.end());
      front.swap(next);
    }
    // The moves changed the ring heights and offsets of the moved vertices and their neighbours
    // only (recounting all of them each round: 8.2 s against 2.7 s at 1.66M vertices, docs/benchmarks.md).
    parallel_for(0, static_cast<int>(touched.size()), [&](int first, int last) {
      for (int t = first; t < last; ++t) update_ring_height(out, faces, adjacency, around, touched[static_cast<size_t>(t)], ring);
    });
    parallel_for(0, static_cast<int>(touched.size()), [&](int first, int last) {
      for (int t = first; t < last; ++t) update_across(touched[static_cast<size_t>(t)]);
    });
  }
  report.sparse = report.moved_vertices <= kSparseSpikes * n;
  return out;
}

double despiked_noise(const NoiseEstimate& despiked, const NoiseEstimate& input) {
  if (!(despiked.mean_edge > 0)) return input.relative();
  return std::clamp(despiked.imf_rms_sigma / despiked.mean_edge, despiked.relative(),
                    std::max(despiked.relative(), input.relative()));
}

}  // namespace hht
