// The surface a filter works on, made whole from what MeshLab holds: faces repeating another's
// three vertices left out, border vertices at the same position merged (border_weld.h: a triangle
// soup, a surface cut at seams), faces oriented against their neighbours turned
// (coherent_orientation.h), then vertices where several fans of faces meet split, one per fan
// (vertex_split.h), the faces of an edge of more than two paired sheet by sheet first, so that the
// faces left over get vertices of their own (a fin on a surface, two sheets through one edge). One
// corner table serves all of it unless the merge, the repeats or the orientation change the faces
// (0.5 s at 3.3M faces, half of it the walk over the fans; docs/quality.md items 42-44 and 48).
#pragma once

#include "mesh/border_weld.h"
#include "mesh/coherent_orientation.h"
#include "mesh/vertex_split.h"

#include <string>
#include <vector>

namespace hht {

// Which row of the filter's arrays each input vertex became. `row_of` empty: row i is vertex i;
// `copy_of`: the rows appended by the split, each the row it copies; `result_of` (with copies): for
// each row before them, the row whose result it takes: itself or a copy, one inside a surface
// before one on a border (the surface a fin stands on, not the fin), then the one with the most
// face area around it.
struct InputMap {
  std::vector<int> row_of;
  std::vector<int> copy_of;
  std::vector<int> result_of;
  bool identity() const { return row_of.empty() && copy_of.empty(); }
  int row(int vertex) const { return row_of.empty() ? vertex : row_of[vertex]; }
};

struct FilterInputReport {
  int repeated_faces = 0;       // faces with the same three vertices as another, left out
  int merged = 0;               // vertices merged into another
  int dropped_faces = 0;        // faces the merge left with no area
  std::string not_merged_why;   // border vertices on each other, left apart: why
  OrientationRepair orientation;  // done false with an empty why_not: edges of more than two faces, not checked
  int cut_edges = 0;            // edges of more than two faces, each side given vertices of its own
  int split = 0;                // vertices added by splitting non-manifold ones (and cut edges)
};

// Orients `positions` and `faces` in place and, with `mend`, leaves the repeated faces out and
// merges the seams first and splits the non-manifold vertices and edges last (edges of more than
// two faces are left as they are without `mend`, and where the merge refuses seams on such a mesh:
// the parts filtered apart would open at them); `map` says where each input vertex went.
void prepare_filter_input(Positions& positions, Faces& faces, bool mend, InputMap& map, FilterInputReport& report);

// A filter's result (one row per row of its arrays) as one row per input vertex: each vertex gets
// its row's, or that of one of the row's split copies (`result_of`).
template <class Matrix>
Matrix to_input_vertices(const Matrix& rows, const InputMap& map) {
  if (map.identity()) return rows;
  const Eigen::Index base = rows.rows() - static_cast<Eigen::Index>(map.copy_of.size());
  Matrix merged = rows.topRows(base);
  for (size_t r = 0; r < map.result_of.size(); ++r)
    if (map.result_of[r] != static_cast<int>(r)) merged.row(static_cast<Eigen::Index>(r)) = rows.row(map.result_of[r]);
  if (map.row_of.empty()) return merged;
  Matrix out(static_cast<Eigen::Index>(map.row_of.size()), rows.cols());
  for (size_t i = 0; i < map.row_of.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = merged.row(map.row_of[i]);
  return out;
}

}  // namespace hht
