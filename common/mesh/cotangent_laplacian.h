// The cotangent Laplacian of a triangle mesh, in the form L = M^-1 C of the paper's eq. 10:
// C is the symmetric positive semi-definite matrix with C_ij = -(cot a_ij + cot b_ij)/2 and
// C_ii = -sum_j C_ij, M the diagonal of mixed Voronoi areas (Meyer et al. 2003). Then
// (L V)_i = 1/(2 A_i) sum_j (cot a_ij + cot b_ij)(v_i - v_j) = 2 H_i n_i (H > 0 on a convex
// surface with outward normals).
#pragma once

#include "mesh/mesh_arrays.h"

#include <Eigen/Sparse>

namespace hht {

// C and M of a triangulation, one entry per corner: the corner facing the edge (pairs(k, 0),
// pairs(k, 1)) couples them with half its cotangent, weights[k]. The triangulation is the mesh's
// own (extrinsic_cotangent_laplacian) or its intrinsic Delaunay one (intrinsic_delaunay.h).
struct CotangentLaplacian {
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> pairs;
  Eigen::VectorXd weights;
  Eigen::VectorXd areas;  // the diagonal of M; vertices of no face get 0
};

// Cotangent of the angle at each corner (row f, column k: the corner of faces(f, k)).
// Zero-area faces get bounded cotangents instead of infinities.
Positions corner_cotangents(const Positions& positions, const Faces& faces);

// Corner k's share of a triangle's mixed Voronoi area (Meyer et al. 2003), from the squared lengths
// of the edges facing its corners, their cotangents and its area: the Voronoi region
// (|e_kj|^2 cot l + |e_kl|^2 cot j) / 8 in a non-obtuse triangle, else half the area at the obtuse
// corner and a quarter at the others.
double mixed_voronoi_share(const double squared[3], const double cot[3], double area, int k);

// Mixed Voronoi area per vertex: Voronoi area in non-obtuse triangles, half the triangle's
// area at an obtuse corner and a quarter at the others. Vertices of no face get 0.
Eigen::VectorXd mixed_voronoi_areas(const Positions& positions, const Faces& faces);

// C and M over the mesh's own triangles.
CotangentLaplacian extrinsic_cotangent_laplacian(const Positions& positions, const Faces& faces);

// C, assembled (n x n).
Eigen::SparseMatrix<double> cotangent_matrix(const CotangentLaplacian& laplacian, int vertex_count);

// C * positions without assembling C.
Positions cotangent_matrix_times(const CotangentLaplacian& laplacian, const Positions& positions);

}  // namespace hht
