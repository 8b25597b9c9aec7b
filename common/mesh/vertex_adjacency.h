// The one-ring of every vertex in one flat array (compressed rows: no allocation per vertex,
// so building it and sweeping over it stay linear and cache-friendly on millions of vertices),
// and which vertices lie on a boundary edge (an edge of one face only).
#pragma once

#include "mesh/mesh_arrays.h"

#include <vector>

namespace hht {

struct VertexAdjacency {
  std::vector<int> offsets;             // n + 1; the neighbours of i are [offsets[i], offsets[i+1])
  std::vector<int> neighbours;          // sorted per vertex, without repetitions
  std::vector<unsigned char> boundary;  // 1: on an edge that only one face has

  int vertices() const { return static_cast<int>(offsets.size()) - 1; }
  int valence(int i) const { return offsets[i + 1] - offsets[i]; }
  const int* begin(int i) const { return neighbours.data() + offsets[i]; }
  const int* end(int i) const { return neighbours.data() + offsets[i + 1]; }
};

// Faces must index vertices in [0, vertex_count).
VertexAdjacency vertex_adjacency(const Faces& faces, int vertex_count);

}  // namespace hht
