// Non-manifold vertices split into one vertex per fan of faces. A scan or an export often has a
// few vertices where two fans of faces meet (two cones touching at a tip, two boundary loops
// through one vertex); the filters built on the Hamiltonian cycle or on guided normal filtering
// need a manifold and refused such a mesh whole. Split, each fan gets a vertex of its own at the
// same place; the vertex takes the result of one copy (InputMap::result_of in filter_input.h), so
// the mesh stays as connected as it was (ours, docs/quality.md items 43 and 44).
#pragma once

#include "mesh/corner_table.h"
#include "mesh/mesh_arrays.h"

#include <vector>

namespace hht {

struct VertexSplit {
  std::vector<int> copy_of;  // for each new vertex (appended after the input's), the vertex it copies
};

// `faces` must be coherently oriented, `table` their corner table. Every fan but the first of each
// vertex gets a new vertex index (vertex_count, vertex_count + 1, ...), its faces moved to it;
// `split.copy_of` says which vertex each copies. Returns the number of new vertices (0: `faces` as
// they were).
int split_nonmanifold_vertices(Faces& faces, const CornerTable& table, int vertex_count, VertexSplit& split);

}  // namespace hht
