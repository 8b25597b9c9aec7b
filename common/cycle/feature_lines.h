// Feature lines: the feature vertices of detect_sharp_features linked, along mesh edges, into
// ordered vertex paths that meet at corners (paper sec. 4.3, Fig. 4d). Each line becomes its
// own 1D signal in the divide-and-conquer EMD; corners are handled apart.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/sharp_features.h"

#include <vector>

namespace hht {

struct FeatureLines {
  // Each line is an ordered vertex path, consecutive vertices joined by a mesh edge. An open
  // line runs between two ends, each a corner (included as the line's first / last vertex)
  // or a free end; a closed loop passes no corner and does not repeat its first vertex.
  std::vector<std::vector<int>> lines;
  std::vector<char> closed;         // per line: 1 for a closed loop
  std::vector<int> corners;         // vertices where three or more lines meet, or typed Corner
  std::vector<int> corner_valence;  // per corner: line ends at it (a line with both ends there counts 2)
  std::vector<int> line_of_vertex;  // per vertex: its line, -1 for corners and vertices on no line
};

// Links the feature vertices (type != None) through the mesh edges between them. Where three
// feature vertices form a face, one edge is not followed: the one opposite a corner, else
// opposite the centre of a cluster of such faces, else the longest; so a corner or a turn is
// not short-cut, and a vertex bumping out beside a line becomes a spur. Mesh boundary edges
// are always followed. A vertex with three or more linked neighbours, or typed Corner, ends
// the lines at it. Lines with fewer than `min_line_length` vertices are dropped unless both
// ends are corners (spurs, bits of noise, tiny loops), repeatedly, so a junction left with two
// lines joins them into one; a typed Corner left with no line stays in `corners` with
// valence 0. Deterministic: lines are traced from corners and ends in vertex order, loops
// last. Empty output when `type` does not match the vertices or a face indexes outside them.
FeatureLines link_feature_lines(const Positions& positions, const Faces& faces, const std::vector<FeatureType>& type,
                                int min_line_length = 3);

}  // namespace hht
