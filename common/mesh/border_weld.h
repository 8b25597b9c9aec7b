// Border vertices that sit exactly where another border vertex sits, merged. Some exporters write
// every face with vertices of its own (a triangle soup), others cut a surface along its texture
// seams or split the vertices of a crease for flat shading; MeshLab keeps such vertices apart. To
// a filter the surface then falls apart at every such border: the noise estimate reads no
// interior vertex (a soup of Fandisk: "noise 0.0%", nothing done) and, given the noise, the
// smoothing shrinks each face on its own and opens gaps between them. Merged, the surface is
// whole again; the filter's result is given to every vertex of a merged group alike, so the seams
// stay closed (ours, docs/quality.md item 42).
#pragma once

#include "mesh/corner_table.h"
#include "mesh/mesh_arrays.h"

#include <string>
#include <vector>

namespace hht {

struct BorderWeld {
  Positions positions;         // one row per vertex after merging
  Faces faces;                 // over those rows; faces left with a repeated vertex (no area) dropped
  std::vector<int> welded_of;  // each input vertex's row in `positions`
  int merged = 0;              // input vertices merged into another
  int dropped_faces = 0;
};

// Merges the border vertices (on an edge of one face, of build_corner_table_cutting's table: an
// edge of more than two faces leaves the faces it cannot pair on a border) at identical positions.
// False, with `weld` empty, when none coincide (`why_not` empty), and when merging would leave no
// coherent orientation or parts joined at a vertex only (more non-manifold vertices than the input
// has, the vertices of edges of more than two faces not counted; `why_not` says which). Faces merged
// into an edge of more than two faces (a soup of a surface with a fin) are left for the table to pair.
bool weld_coincident_border_vertices(const Positions& positions, const Faces& faces, BorderWeld& weld,
                                     std::string& why_not);
// The same with `faces`' corner table already built (build_corner_table_cutting).
bool weld_coincident_border_vertices(const Positions& positions, const Faces& faces, const CornerTable& table,
                                     BorderWeld& weld, std::string& why_not);

}  // namespace hht
