// Per face, the faces sharing a vertex with it (itself included, sorted): the neighbourhood of
// the face-normal filters (guided and bilateral normal filtering, the adaptive smoothing's
// face-normal pass). Compressed rows, linear time.
#pragma once

#include "mesh/corner_table.h"

#include <vector>

namespace hht {

struct IndexLists {
  std::vector<int> start, items;  // list i is items[start[i] .. start[i + 1])
  int begin(int i) const { return start[i]; }
  int end(int i) const { return start[i + 1]; }
};

// Per vertex, the faces that use it (in face order).
IndexLists vertex_faces(const Faces& faces, int vertex_count);

// Face f's ring into `ring` (sorted, f included), from `around` = vertex_faces(faces, ...): for a
// sweep over the faces that needs one ring at a time and not the whole list's memory.
void face_ring(const Faces& faces, const IndexLists& around, Eigen::Index f, std::vector<int>& ring);

// Faces must index vertices in [0, vertex_count).
IndexLists face_rings(const Faces& faces, int vertex_count);

}  // namespace hht
