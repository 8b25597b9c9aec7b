// A Hamiltonian cycle through the vertices of a triangle mesh by the Ring Expander of
// Gurung, Luffel, Lindstrom and Rossignac ("LR", ACM TOG 30(4), 2011): a region of triangles
// is grown greedily, always as a topological disk whose boundary ring passes once through
// every vertex reached so far. The ring is the cycle: consecutive vertices on it are joined
// by a mesh edge, and it is built in time linear in the number of faces.
//
// The input needs no preparation: a mesh with holes gets one dummy vertex fanned to each
// boundary loop (the paper's Discussion) and the dummies are dropped from the result, which
// the dummy's fan allows only through a single boundary edge, so that the cycle still steps
// along mesh edges; several connected components get one cycle each, concatenated.
#pragma once

#include "mesh/corner_table.h"

#include <string>
#include <vector>

namespace hht {

struct CycleOptions {
  int seed = 0;        // 0: each component starts at its first face; otherwise a random face
  int tries = 1;       // seeds tried per component, keeping the cycle with fewest isolated vertices
  bool repair = true;  // attach isolated vertices by a local move (drop an ear, take two triangles)
};

struct HamiltonianCycle {
  std::vector<int> order;          // vertex indices in cycle order, components concatenated
  std::vector<int> segment_begin;  // where each component's cycle starts in `order`, then order.size()
  std::vector<int> position;       // per vertex: its index in `order`, or -1 when not on the cycle
  int isolated = 0;       // vertices of some face that the cycle missed
  int repaired = 0;       // isolated vertices attached by the local repair
  int unreferenced = 0;   // vertices of no face (never on the cycle)
  int holes = 0;          // boundary loops closed by a dummy vertex
  int components = 0;
  int inconsistent_edges = 0;  // edges whose two faces disagreed on orientation (fixed on a copy)
};

// Fails with a message, leaving `cycle` unspecified, on faces indexing missing vertices or
// repeating one, non-manifold edges or vertices, and non-orientable components.
bool hamiltonian_cycle(const Faces& faces, int vertex_count, const CycleOptions& options,
                       HamiltonianCycle& cycle, std::string& error);

}  // namespace hht
