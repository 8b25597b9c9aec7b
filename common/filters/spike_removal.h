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
// height: camel in random directions 3.60 to 2.70, dino with three tenths moved 15.67 to 9.04).
// That second test also takes the triangulation's own widest offsets on an irregular mesh and
// moves those untouched vertices along the surface (homer with a twentieth moved along the
// normals: the RMS distance to the clean mesh 17.8 against the noisy input's 15.4), so it runs
// only where the first round's height spikes stand off across as well: the median over them of
// their offset across over their two-ring's median is about 1 where the noise moved them along
// the normals (0.81-1.29 in 45 of 51 cases: 21 organic meshes with a twentieth and three tenths
// of their vertices moved, nine of them a tenth too, lab mode `RS`; up to 1.64, and one with too
// few spikes to tell) and 1.32-9.3 in random directions (all but one, 1.26); over kAcrossRatio it
// runs, and where too few spikes tell, too. A misread costs little: along the normals the
// removal then does what it did before this reading (homer, the case above: 10.1 when read
// right), in random directions it misses the vertices moved mostly along the surface (cow with a
// twentieth moved, 3.39 against 3.57 degrees through the smoothing). A round can only reveal
// spikes next to the ones it moved (a spike hides a moved neighbour's height), so the rounds stop
// when none is left or after kRemovalRounds. Where the rounds moved more than kSparseSpikes of
// the vertices, the noise is too dense for them alone (spikes next to spikes hide each other), and
// the filters go on to filter the despiked mesh as any noise. With a twentieth or a tenth of the
// vertices moved by half a mean edge the rounds move 1.8-8.0% of them (seven meshes, lab, seed 11),
// with three tenths 8.4-19%; dino at 30%: 10.77 degrees so, 17.48 despiked alone, 13.50 smoothed
// from the input. Ours, not the paper's (docs/quality.md item 26).
#pragma once

#include "cycle/hamiltonian_cycle.h"
#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"
#include "signal/noise_estimate.h"
#include "util/stage_clock.h"

#include <string>
#include <utility>

namespace hht {

constexpr double kRemovalScale = 4.0;
constexpr int kRemovalRounds = 30;
constexpr double kSparseSpikes = 0.08;
constexpr double kAcrossRatio = 1.3;

struct SpikeRemovalReport {
  int moved_vertices = 0;   // distinct vertices moved
  int rounds = 0;           // rounds that moved a vertex
  bool sparse = false;      // moved_vertices at most kSparseSpikes of the vertices: the result stands
  bool across = true;       // the spikes read as moved across the normal too: the second test ran
  double across_ratio = 0;  // the first round's median ratio behind `across` (0: too few spikes to tell)
};

Positions remove_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                        SpikeRemovalReport& report);

// The noise level the removal left (sigma / mean edge), from `despiked`, the despiked mesh's
// estimate, and `input`, the input's: what the rounds could not put back (spikes next to spikes,
// each put back only part of the way) sits on a share of the vertices, so the estimate's MAD reads
// it low (mech-holes-shark with three tenths of its vertices moved along the normals: 0.022 mean
// edges against 0.095 left), and the finest IMF's RMS reads it nearer (0.052). That reading, kept
// between the MAD's and the input's estimate (docs/quality.md item 27).
double despiked_noise(const NoiseEstimate& despiked, const NoiseEstimate& input);

// Spikes too dense for the removal alone: `run(despiked, options, report)` filters the despiked
// mesh as any noise at despiked_noise's level (given to it; the removal off), and its report takes
// the place of `report`, with the despiked mesh's estimate as its noise, the input's kept as
// input_noise, the removal's report and stage times before its own. The smoothing and the
// denoiser share this (Options, Report: theirs; `cycle` the input's, for the estimate).
template <class Options, class Report, class Run>
bool filter_despiked(const Positions& despiked, const Faces& faces, const HamiltonianCycle& cycle, const Options& options,
                     Report& report, std::string& error, const Run& run) {
  StageClock clock(report.stages);
  NoiseEstimate left;
  if (!estimate_noise(despiked, faces, cycle, options.emd, left, error)) return false;
  clock.done("noise left by the removal");
  Options rest = options;
  rest.remove_scattered_spikes = false;
  rest.noise = despiked_noise(left, report.noise);
  Report filtered;
  if (!run(despiked, rest, filtered)) return false;
  filtered.stages.insert(filtered.stages.begin(), report.stages.begin(), report.stages.end());
  filtered.noise = left;
  filtered.input_noise = report.noise;
  filtered.spike_removal = report.spike_removal;
  filtered.despiked_then_filtered = true;
  report = std::move(filtered);
  return true;
}

}  // namespace hht
