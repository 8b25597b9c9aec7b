// Per-vertex unit normals: the sum of the incident faces' area vectors (area weighting),
// normalised. Oriented by the faces' winding; zero for vertices of no (or only zero-area) faces.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <vector>

namespace hht {

Positions area_weighted_vertex_normals(const Positions& positions, const Faces& faces);

// Those normals averaged over three rings (each sweep a vertex's and its neighbours' mean,
// normalised): the surface's normal where the noisy mesh's own normals are too rough, as the
// smoothing needs to split a move into its normal and tangential parts.
Positions smoothed_vertex_normals(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);

// The same sums, unnormalised (twice the incident area along the normal): what a face is
// folded against, in the flip guard and in the evaluation's count of faces turned over.
Positions summed_area_vectors(const Positions& positions, const Faces& faces);

// Per face, 1 where its area vector points against the sum of its corners' summed area vectors:
// a face folded over its neighbours (noise with a tangential part folds small triangles).
std::vector<unsigned char> folded_faces(const Positions& positions, const Faces& faces);

// Per-face unit normals by the winding; zero for zero-area faces.
Positions unit_face_normals(const Positions& positions, const Faces& faces);
Eigen::RowVector3d unit_face_normal(const Positions& positions, const Faces& faces, Eigen::Index f);

}  // namespace hht
