// Spike removal: under impulsive noise read from scattered spikes (mesh/scattered_spikes.h), the
// vertices that stand off their one-ring are put back onto the surface their neighbours span, and
// every other vertex is left exactly where it is.
//
// Why: the noise left most vertices alone, so any smoothing of the whole mesh blunts a surface
// that needed nothing (cow with a tenth of its vertices moved: the adaptive smoothing 11.95
// degrees against the noisy input's 8.26, Taubin 13.50). In rounds, each vertex whose |height|
// (mesh/scattered_spikes.h) is the largest of its closed one-ring and over kRemovalScale times
// its two-ring's median is moved along its ring normal to its neighbours' mean height, as they
// read after the move (the height a smooth surface through them gives it), and its offset from
// their centroid across the normal is cut back to the two-ring's median offset (a move in a
// random direction, the authors' other impulsive model, has a part across; noise along the
// normals has none, and there this moves the vertex by less than the triangulation's own
// irregularity: camel with a tenth of its vertices moved in random directions 5.52 to 3.60
// degrees, along the normals 2.76 to 2.41, cow 5.05 to 5.04). A vertex whose offset across is the
// largest of its closed one-ring and over kRemovalScale times its two-ring's median is a spike
// too and gets the same cut-back (moved mostly along the surface, a vertex barely stands off in
// height: camel in random directions 3.60 to 2.70, dino with three tenths moved 15.67 to 9.04;
// along the normals it costs a little, bull at 10% 6.48 to 6.72). A round can only
// reveal spikes next to the ones it moved (a spike hides a moved neighbour's height), so the
// rounds stop when none is left or after kRemovalRounds. Where the rounds moved more than kSparseSpikes of the vertices, the
// noise is too dense for them alone (spikes next to spikes hide each other), and the filters go on
// to filter the despiked mesh as any noise. With a twentieth or a tenth of the vertices moved by
// half a mean edge the rounds move 1.8-8.0% of them (seven meshes, lab, seed 11), with three
// tenths 8.4-19%; dino at 30%: 10.77 degrees so, 17.48 despiked alone, 13.50 smoothed from the
// input. Ours, not the paper's (docs/quality.md item 26).
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <utility>

namespace hht {

constexpr double kRemovalScale = 4.0;
constexpr int kRemovalRounds = 30;
constexpr double kSparseSpikes = 0.08;

struct SpikeRemovalReport {
  int moved_vertices = 0;  // distinct vertices moved
  int rounds = 0;          // rounds that moved a vertex
  bool sparse = false;     // moved_vertices at most kSparseSpikes of the vertices: the result stands
};

Positions remove_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                        SpikeRemovalReport& report);

// Spikes too dense for the removal alone: `run(despiked, options, report)` filters the despiked
// mesh as any noise (its level read again; the removal off), and its report takes the place of
// `report`, the input's estimate kept as input_noise, the removal's report and stage times before
// its own. The smoothing and the denoiser share this (Options, Report: theirs).
template <class Options, class Report, class Run>
bool filter_despiked(const Positions& despiked, const Options& options, Report& report, const Run& run) {
  Options rest = options;
  rest.remove_scattered_spikes = false;
  Report filtered;
  if (!run(despiked, rest, filtered)) return false;
  filtered.stages.insert(filtered.stages.begin(), report.stages.begin(), report.stages.end());
  filtered.input_noise = report.noise;
  filtered.spike_removal = report.spike_removal;
  filtered.despiked_then_filtered = true;
  report = std::move(filtered);
  return true;
}

}  // namespace hht
