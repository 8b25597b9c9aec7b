// Faces oriented against their neighbours, turned to agree with them. Scans and CAD exports
// (STL in particular) often hold faces whose vertex order runs the other way from their
// neighbours'; every normal the filters compute then points in and out at random, vertex normals
// cancel, and the smoothing and the denoisers fail on an otherwise smooth surface (libcgal-demo's
// blobby-shuffled at 10% noise through smooth.mlx: E_a 14.32 degrees, 3.15 on blobby, the same
// surface oriented; docs/quality.md item 42). Each connected component keeps the orientation most of its
// faces have, so a coherently oriented mesh is left exactly as it is.
#pragma once

#include "mesh/corner_table.h"

#include <string>

namespace hht {

struct OrientationRepair {
  bool done = false;     // false: the faces were left as they were (`why_not` says why)
  std::string why_not;   // non-manifold edges, faces repeating a vertex, or a non-orientable part
  int flipped = 0;       // faces whose vertex order was reversed
  int components = 0;    // connected components (across shared edges) with any of them
};

// Reverses the vertex order of the faces that disagree with the orientation most faces of their
// connected component have. Leaves `faces` as they were when no coherent orientation exists or
// the mesh has edges shared by more than two faces.
OrientationRepair orient_as_most_faces(Faces& faces, int vertex_count);
// The same with `faces`' corner table and its count of inconsistent edges already built
// (build_corner_table), which costs as much as the rest (0.27 s at 3.3M faces).
OrientationRepair orient_as_most_faces(Faces& faces, const CornerTable& table, int inconsistent_edges);

}  // namespace hht
