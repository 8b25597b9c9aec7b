// The uniform ("umbrella") Laplacian of a triangle mesh: (L V)_i = v_i - mean of the one-ring
// neighbours of i. Its weights depend on connectivity only, so unlike the cotangent Laplacian
// it stays well-behaved on slivers and obtuse triangles, and it also pulls tangential noise
// out (MeshLab's Laplacian and Taubin smoothers use it). Vertices of no face get a zero row.
#pragma once

#include "mesh/mesh_arrays.h"

#include <Eigen/Sparse>

#include <vector>

namespace hht {

// One-ring neighbours of each vertex, sorted, without repetitions.
std::vector<std::vector<int>> vertex_neighbours(const Faces& faces, int vertex_count);

// L = I - D^-1 A (n x n, not symmetric).
Eigen::SparseMatrix<double> uniform_laplacian(const std::vector<std::vector<int>>& neighbours);

}  // namespace hht
