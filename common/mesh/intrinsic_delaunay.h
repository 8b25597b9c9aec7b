// The cotangent Laplacian of the intrinsic Delaunay triangulation (Bobenko and Springborn 2007;
// Fisher et al. 2007): the mesh's edges flipped, as geodesics on the surface itself, until the two
// angles facing each edge sum to at most pi. The surface and its vertices stay as they are; only
// the triangles the weights come from change. Every weight is then >= 0, and a
// sliver's huge or negative cotangents no longer reach L (bull: 5% of its faces have an angle
// under 9 degrees). A mesh already Delaunay (on a border: no angle over 90 degrees facing a border
// edge) keeps its own triangles, so its L is the extrinsic one.
//
// Faces of no area (a needle, a vertex on its opposite edge) have no angles to flip by; their
// edge lengths are first mollified (Sharp and Crane 2020): every length grows by the least delta
// that leaves each triangle's inequality a margin of kMollifyMargin mean edges. A mesh with borders
// is flipped on its tufted cover (Sharp and Crane 2020), so that its border edges' weights are >= 0 too.
#pragma once

#include "mesh/cotangent_laplacian.h"

namespace hht {

constexpr double kMollifyMargin = 1e-4;

struct IntrinsicDelaunayReport {
  bool intrinsic = false;  // false: the mesh's own triangles were used (see the header of the .cpp)
  bool tufted_cover = false;  // the mesh has borders: flipped on its tufted cover (two sheets; see the .cpp)
  int flips = 0;              // on the tufted cover, an interior edge flipped in both sheets counts twice
  double mollified = 0;    // delta, in mean edge lengths
};

// Which triangles a cotangent Laplacian is taken over. The mesh's own: the paper's L, the one the
// filters decompose and rebuild with. The intrinsic Delaunay ones: G 2-3 times closer to the true
// curvature on irregular triangles, but no better as the filters' L (docs/quality.md item 45).
enum class LaplacianTriangles { Mesh, IntrinsicDelaunay };

// Meshes whose corner table cannot be built (an edge of more than two faces, a face repeating a
// vertex) or that cannot be oriented get extrinsic_cotangent_laplacian; `report` says which.
CotangentLaplacian intrinsic_delaunay_laplacian(const Positions& positions, const Faces& faces,
                                                IntrinsicDelaunayReport* report = nullptr);

CotangentLaplacian cotangent_laplacian(const Positions& positions, const Faces& faces, LaplacianTriangles triangles,
                                       IntrinsicDelaunayReport* report = nullptr);

}  // namespace hht
