#include "evaluation/gaussian_noise.h"
#include "mesh/uniform_laplacian.h"
#include "mesh/vertex_adjacency.h"
#include "reconstruction/biharmonic_low_pass.h"
#include "test_meshes.h"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <map>
#include <set>

namespace hht {
namespace {

// The flat adjacency against a plain per-face construction, and its boundary flags against the
// edges met once, on a mesh with holes and an unreferenced vertex.
TEST(VertexAdjacency, MatchesTheFacesOneRingsAndBoundary) {
  test::ArrayMesh m = test::remove_faces(test::load_data_mesh("fandisk"), 7);
  m.positions.conservativeResize(m.positions.rows() + 1, 3);
  m.positions.row(m.positions.rows() - 1).setZero();
  const int n = static_cast<int>(m.positions.rows());
  std::vector<std::set<int>> rings(n);
  std::map<std::pair<int, int>, int> edge_faces;
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.faces(f, k), b = m.faces(f, (k + 1) % 3);
      rings[a].insert(b);
      rings[b].insert(a);
      ++edge_faces[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<unsigned char> boundary(n, 0);
  int boundary_count = 0;
  for (const auto& [edge, count] : edge_faces)
    if (count == 1) boundary[edge.first] = boundary[edge.second] = 1;
  const VertexAdjacency adjacency = vertex_adjacency(m.faces, n);
  ASSERT_EQ(adjacency.vertices(), n);
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(std::vector<int>(adjacency.begin(i), adjacency.end(i)), std::vector<int>(rings[i].begin(), rings[i].end()));
    EXPECT_EQ(adjacency.boundary[i], boundary[i]) << i;
    boundary_count += boundary[i];
  }
  EXPECT_GT(boundary_count, 0);
  EXPECT_EQ(adjacency.valence(n - 1), 0);
}

// The low-pass by a direct factorisation of ((L^2)^T L^2 + g mu^2 L^T L + mu^4 I) x = mu^4 v.
Positions direct_low_pass(const VertexAdjacency& adjacency, const Positions& v, double mu, double first_order) {
  const Eigen::SparseMatrix<double> l = uniform_laplacian(adjacency);
  const Eigen::SparseMatrix<double> l2 = l * l;
  const double mu4 = std::pow(mu, 4);
  Eigen::SparseMatrix<double> a = Eigen::SparseMatrix<double>(Eigen::SparseMatrix<double>(l2.transpose()) * l2) +
                                  first_order * mu * mu * Eigen::SparseMatrix<double>(l.transpose()) * l;
  for (int i = 0; i < adjacency.vertices(); ++i) a.coeffRef(i, i) += mu4;
  return Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(a).solve(Positions(mu4 * v));
}

// The matrix-free solve against a direct factorisation of
// ((L^2)^T L^2 + g mu^2 L^T L + mu^4 I) x = mu^4 v, with and without the first-order term g, on an
// irregular mesh with holes: the true error stays within the bound it stops at.
TEST(BiharmonicLowPass, MatchesADirectSolveWithinItsBound) {
  const test::ArrayMesh m = test::remove_faces(test::flip_random_edges(test::sphere(4), 2000, 3), 9);
  const Positions v = add_gaussian_noise(m.positions, m.faces, 30, NoiseDirection::Isotropic, 8);
  const VertexAdjacency adjacency = vertex_adjacency(m.faces, static_cast<int>(v.rows()));
  for (double first_order : {0.0, 1.0})
  for (double mu : {0.3, 0.8}) {
    const Positions expected = direct_low_pass(adjacency, v, mu, first_order);
    for (double max_error : {1e-3, 1e-7}) {
      Positions x;
      BiharmonicLowPassReport report;
      ASSERT_TRUE(biharmonic_low_pass(adjacency, v, mu, first_order, max_error, x, report));
      EXPECT_GT(report.iterations, 0);
      EXPECT_LE(report.error_bound, max_error);
      EXPECT_LE((x - expected).norm(), max_error) << mu << " " << first_order;
      EXPECT_GT((v - expected).norm(), 100 * max_error);  // the solution is not the start
    }
  }
}

// The preconditioner: plain conjugate gradients need O(1 / mu^2) iterations (the system's
// condition number is about 16 / mu^4), the preconditioned ones about as many at any strength.
// On an irregular mesh (valences 3 to 12 after the flips) with holes and a vertex of no face, a
// filter 16 times stronger (mu 0.1 against 0.4) costs at most a few more iterations; without
// the preconditioner it costs over ten times as many.
TEST(BiharmonicLowPass, StrongerFiltersTakeAboutAsManyIterations) {
  test::ArrayMesh m = test::remove_faces(test::flip_random_edges(test::sphere(5), 8000, 4), 11);
  m.positions.conservativeResize(m.positions.rows() + 1, 3);
  m.positions.row(m.positions.rows() - 1) = Eigen::RowVector3d(0.1, 0.2, 0.3);
  const Positions v = add_gaussian_noise(m.positions, m.faces, 30, NoiseDirection::Isotropic, 5);
  const VertexAdjacency adjacency = vertex_adjacency(m.faces, static_cast<int>(v.rows()));
  int iterations[2] = {0, 0};
  int k = 0;
  for (double mu : {0.4, 0.1}) {
    Positions x;
    BiharmonicLowPassReport report;
    ASSERT_TRUE(biharmonic_low_pass(adjacency, v, mu, 1.0, 1e-6, x, report));
    EXPECT_EQ(x.row(x.rows() - 1), v.row(v.rows() - 1));  // the vertex of no face stays
    iterations[k++] = report.iterations;
  }
  EXPECT_LE(iterations[1], iterations[0] + 8) << iterations[0];
  EXPECT_LE(iterations[1], 40);
}

// A cut-off four times stronger than any the filters choose (their strongest is about 0.008),
// beyond what the preconditioner's largest degree fits: the solve still converges to the direct
// solution (in 39 iterations; plain conjugate gradients stop at the cap of 500 far short of it).
TEST(BiharmonicLowPass, AnExtremeCutOffStillConverges) {
  const test::ArrayMesh m = test::remove_faces(test::flip_random_edges(test::sphere(3), 500, 4), 11);
  const Positions v = add_gaussian_noise(m.positions, m.faces, 30, NoiseDirection::Isotropic, 5);
  const VertexAdjacency adjacency = vertex_adjacency(m.faces, static_cast<int>(v.rows()));
  const double mu = 0.002;
  const Positions expected = direct_low_pass(adjacency, v, mu, 1.0);
  Positions x;
  BiharmonicLowPassReport report;
  ASSERT_TRUE(biharmonic_low_pass(adjacency, v, mu, 1.0, 1e-4, x, report));
  EXPECT_LE((x - expected).norm(), 1e-4) << report.iterations;
}

}  // namespace
}  // namespace hht
