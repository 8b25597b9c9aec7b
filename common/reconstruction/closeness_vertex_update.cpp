#include "reconstruction/closeness_vertex_update.h"

#include "mesh/face_rings.h"
#include "util/parallel_for.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <vector>

namespace hht {

namespace {

// Where a face's centred vertices (rows of p) should go for the target normal n: onto the plane
// orthogonal to n, or, for a face turned against n, onto the best-fitting line in that plane.
Eigen::Matrix3d target_shape(const Eigen::Matrix3d& p, const Eigen::Vector3d& n) {
  const Eigen::Matrix3d in_plane = p - (p * n) * n.transpose();
  const Eigen::Vector3d current = (p.row(1) - p.row(0)).cross(p.row(2) - p.row(0)).transpose();
  if (current.dot(n) >= 0) return in_plane;
  // The line's direction: the principal axis of the projected vertices (it lies in the plane).
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(in_plane.transpose() * in_plane);
  const Eigen::Vector3d d = axes.eigenvectors().col(2);
  return (p * d) * d.transpose();
}

}  // namespace

bool fit_vertices_to_normals_with_closeness(const Positions& positions, const Faces& faces,
                                            const Positions& target_normals, double closeness_weight, int iterations,
                                            Positions& result, std::string& error) {
  const int n = static_cast<int>(positions.rows());
  const int m = static_cast<int>(faces.rows());
  if (target_normals.rows() != m || n == 0) {
    error = "one target normal per face, and at least one vertex, are needed";
    return false;
  }
  if (!(closeness_weight > 0) || iterations < 0) {
    error = "the closeness weight must be positive and the iterations at least 0";
    return false;
  }
  const double w = closeness_weight * m / n;

  // A^T A + w I, with A stacking the centring C = I - 1/3 of every face's three vertices (C^T C = C).
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * static_cast<size_t>(m) + n);
  for (int f = 0; f < m; ++f)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) entries.emplace_back(faces(f, j), faces(f, k), (j == k ? 1.0 : 0.0) - 1.0 / 3.0);
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, w);
  Eigen::SparseMatrix<double> system(n, n);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) {
    error = "the vertex update's linear system could not be factorised";
    return false;
  }

  const IndexLists around = vertex_faces(faces, n);
  const Eigen::MatrixX3d held = w * Eigen::MatrixX3d(positions);
  Eigen::MatrixX3d x = positions, rhs(n, 3);
  std::vector<Eigen::Matrix3d> shape(m);  // per face, rows = its corners' target offsets
  for (int it = 0; it < iterations; ++it) {
    parallel_for(0, m, [&](int first, int last) {
      for (int f = first; f < last; ++f) {
        Eigen::Matrix3d p;
        for (int k = 0; k < 3; ++k) p.row(k) = x.row(faces(f, k));
        p.rowwise() -= p.colwise().mean();
        shape[f] = target_shape(p, target_normals.row(f).transpose());
      }
    });
    // A^T B: the shapes are centred already, so C B_f = B_f and each corner adds its own row.
    parallel_for(0, n, [&](int first, int last) {
      for (int i = first; i < last; ++i) {
        Eigen::RowVector3d sum = held.row(i);
        for (int j = around.begin(i); j < around.end(i); ++j) {
          const int f = around.items[j];
          for (int k = 0; k < 3; ++k)
            if (faces(f, k) == i) sum += shape[f].row(k);
        }
        rhs.row(i) = sum;
      }
    });
    x = solver.solve(rhs);
    if (solver.info() != Eigen::Success) {
      error = "the vertex update's linear solve failed";
      return false;
    }
  }
  result = x;
  return true;
}

}  // namespace hht
