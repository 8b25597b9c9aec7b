// The uniform ("umbrella") Laplacian of a triangle mesh: (L V)_i = v_i - mean of the one-ring
// neighbours of i. Its weights depend on connectivity only, so unlike the cotangent Laplacian
// it stays well-behaved on slivers and obtuse triangles, and it also pulls tangential noise
// out (MeshLab's Laplacian and Taubin smoothers use it). Vertices of no face get a zero row.
// L = D^-1 K with K = D - A the symmetric graph Laplacian (D the valences, A the adjacency),
// which lets solvers apply L and L^T from the adjacency alone, without a matrix.
#pragma once

#include "mesh/vertex_adjacency.h"

#include <Eigen/Sparse>

#include <vector>

namespace hht {

// L = I - D^-1 A (n x n, not symmetric).
Eigen::SparseMatrix<double> uniform_laplacian(const VertexAdjacency& adjacency);

// out = K y (rows are points; on two threads for large meshes).
void apply_graph_laplacian(const VertexAdjacency& adjacency, const Positions& y, Positions& out);

// The sum of the squared coefficients of row i of L^2 = (I - W)^2, W the neighbour average:
// the variance unit white noise gives vertex i's second difference. `scratch` (one zero per
// vertex) and `touched` are work space, handed back as they came.
double squared_laplacian_row_gain(const VertexAdjacency& adjacency, int i, std::vector<double>& scratch,
                                  std::vector<int>& touched);

}  // namespace hht
