// Spikes among flat hinges: vertices that no exactly flat hinge touches while every neighbour of
// theirs is touched by one.
//
// Why: impulsive noise (a share of the vertices moved, the others left where they were: the
// outliers of a scan, the "impulsive" model of the denoising literature) leaves the untouched
// parts of a CAD mesh exactly flat (its planar faces, its cylinders' rulings), so the low
// quantile of |hinge height| that caps the noise estimate (signal/noise_estimate.h) reads no
// noise at all and the filters leave the mesh as it is. A moved vertex breaks every hinge it
// belongs to, while its unmoved neighbours keep flat hinges of their own. On a clean mesh a
// vertex next to flat hinges belongs to one itself (a crease vertex to those of its sides, a
// corner to the hinges across its faces' far edges), and Gaussian noise leaves no hinge flat.
// A clean vertex that touches no flat hinge next to flat ones lies on a gently curved strip
// between them (fandisk's: its hinges bend by at most 0.006 of their edge, half of them); a
// spike stands off by a sizeable part of an edge. So among the vertices whose neighbours all
// touch a flat hinge, the share touching none whose hinges bend by kSpikeBend of their edge or
// more (half of them at least) grows with the share of vertices the impulsive noise moved,
// and is about 0 on a clean mesh.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <vector>

namespace hht {

struct FlatHingeSpikes {
  std::vector<unsigned char> role;  // per vertex: kOnFlatHinge, kSpike or 0
  int surrounded = 0;  // interior vertices whose neighbours all touch a flat hinge
  int spikes = 0;      // of those, the vertices that touch none and whose hinges bend
  double share() const { return surrounded > 0 ? static_cast<double>(spikes) / surrounded : 0; }
  bool impulsive() const;  // spikes enough to read impulsive noise (kMinSpikes, kSpikeShare)
};

// Flat: |height| within kHingeFlatness of the hinge's edge length, plus kCoordinateRounding of the
// coordinates' magnitude (exports keep 6-7 digits). A flat hinge touches a corner only if
// the other three span a plane (twice their triangle's area at least kSpanningCorners of its
// longest edge squared): three corners on a line hold every position of the fourth.
constexpr double kHingeFlatness = 1e-5;
constexpr double kCoordinateRounding = 1e-6;
constexpr double kSpanningCorners = 0.01;
constexpr unsigned char kOnFlatHinge = 1, kSpike = 2;

// Impulsive noise: at least kMinSpikes spikes, a share of kSpikeShare or more. Clean meshes read
// 0.012 at most (libcgal-demo's 170 meshes: three_peaks 1 of 86, fandisk_large 44 of 10,212);
// a twentieth to three tenths of the vertices moved read 0.028-0.2 (docs/quality.md, item 25).
constexpr int kMinSpikes = 5;
constexpr double kSpikeShare = 0.025;
constexpr double kSpikeBend = 1e-2;

// Flat hinges count only where they stand out from hinges bent by less than the allowance by
// chance: far from the origin for its size a mesh's coordinates round to a sizeable part of an
// edge, and Gaussian noise then leaves hinges within that allowance (4.5e4 mean edges from the
// origin, a fifth of elephant's at 10% noise), about as many as bend by one to two allowances.
// Exactly flat hinges crowd below it: they stand out when the hinges bent by one to two allowances
// number at most kChanceFlatRatio of those within one (docs/quality.md item 48). Further out, where
// the allowance passes the noise's own bend, nearly every hinge lies within it and none stands out
// as a spike.
constexpr double kChanceFlatRatio = 0.5;

// `adjacency` is vertex_adjacency() of the same faces. Boundary vertices are left out.
FlatHingeSpikes flat_hinge_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);

}  // namespace hht
