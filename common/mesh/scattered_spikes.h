// Scattered spikes: vertices that stand off their one-ring far beyond the heights around them,
// on any surface (flat_hinge_spikes.h needs exactly flat parts; this does not).
//
// Why: impulsive noise (a share of the vertices moved, the others left where they were: a scan's
// outliers) on a mesh without exactly flat parts (organic meshes, CAD exports whose planes are
// flat only to their coordinates' rounding) reaches the noise estimate only through the MAD of a
// mix of moved and unmoved vertices, and the smoothing that estimate sets blunts the untouched
// surface more than it takes the spikes out (cow with a tenth of its vertices moved: E_a 11.95
// against the noisy input's 8.26; docs/quality.md item 26). A moved vertex stands off a ring of
// unmoved ones: its height over them is many times the heights around it, while each neighbour's
// height holds only a valence-th of the move. Gaussian noise moves every vertex, so heights many
// times the local median with neighbours far below are rare; a clean surface's own detail makes a
// few (a horn's tip), not a share. Ours, not the paper's.
#pragma once

#include "mesh/face_rings.h"
#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <Eigen/Core>
#include <vector>

namespace hht {

// Each vertex's height over its one-ring: <v_i - c_i, m_i>, c_i the neighbours' mean and m_i the
// normal of the one-ring's fan with v_i replaced by c_i (so a spike does not tilt its own normal).
struct RingHeights {
  Eigen::VectorXd height;  // 0 where the vertex has no neighbour
  Positions normal;        // unit; 0 rows where the fan has no area
  Positions centroid;      // c_i (the vertex itself where it has no neighbour)
};
RingHeights ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);
// The same with the faces around each vertex given (mesh/face_rings.h's vertex_faces), and one
// vertex's entry recomputed in `ring` after its one-ring moved: the same sums in the same order.
RingHeights ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                         const IndexLists& around);
void update_ring_height(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                        const IndexLists& around, int v, RingHeights& ring);

// The quantile q of |height| over the two-ring of `v`, `v` left out: the local scale a spike is
// measured in.
struct TwoRingScratch {
  std::vector<int> ring;
  std::vector<double> values;
};
double two_ring_height_quantile(const Eigen::VectorXd& height, const VertexAdjacency& adjacency, int v, double q,
                                TwoRingScratch& scratch);

// A spike stands off its ring by kSpikeStandOff of its mean edge to the ring at least: on an exact
// plane the rounding of the coordinates makes every scale tiny, and tiny heights are no spikes.
constexpr double kSpikeStandOff = 1e-2;
double mean_ring_edge(const Positions& positions, const VertexAdjacency& adjacency, int v);

struct ScatteredSpikes {
  int interior = 0;  // vertices off the boundary with three neighbours or more
  int spikes = 0;    // of those, |height| over kScatteredSpikeScale times its two-ring's
                     // kScatteredSpikeQuantile quantile and over kScatteredSpikeOverNeighbours
                     // times every neighbour's
  double share() const { return interior > 0 ? static_cast<double>(spikes) / interior : 0; }
  bool impulsive() const;  // kMinScatteredSpikes and kScatteredSpikeShare
};

// The reading's thresholds (numpy, seed 11; docs/quality.md item 26). Gaussian noise in random
// directions (the paper's model) has heavier-tailed heights than along the normals: read against
// the two-ring's median and twice the neighbours, 20-30% of it gave 0.005-0.0067 on bunny00,
// camel, diplodocus, mushroom and mech-holes-shark, as much as a twentieth of the vertices moved
// gives on bones or elephant. Against the upper quartile and three times the neighbours it gives
// at most 0.0009 there, clean meshes 0.0014 (cow, b9_mesh), and a tenth of the vertices moved by
// half a mean edge 0.0036-0.0275 on twelve meshes (a twentieth 0.0019-0.0246).
constexpr double kScatteredSpikeScale = 5.0;
constexpr double kScatteredSpikeQuantile = 0.75;
constexpr double kScatteredSpikeOverNeighbours = 3.0;
constexpr int kMinScatteredSpikes = 10;
constexpr double kScatteredSpikeShare = 0.003;

ScatteredSpikes scattered_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);

}  // namespace hht
