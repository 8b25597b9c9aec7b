#include "mesh/uniform_laplacian.h"
#include "mesh/vertex_adjacency.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

// The row gain of (I - W)^2 is the squared norm of row i of the assembled L^2, on every vertex
// of an irregular mesh with a boundary; the work space comes back as it went in. Fails if a
// coefficient shared by two paths is counted apart, or the scratch is left dirty.
TEST(UniformLaplacian, SquaredRowGainIsTheSquaredRowOfLSquared) {
  const test::ArrayMesh m = test::load_data_mesh("elephant-with-holes");
  const int n = static_cast<int>(m.positions.rows());
  const VertexAdjacency adjacency = vertex_adjacency(m.faces, n);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> l2 = uniform_laplacian(adjacency) * uniform_laplacian(adjacency);
  std::vector<double> scratch(n, 0.0);
  std::vector<int> touched;
  for (int i = 0; i < n; ++i) {
    if (adjacency.valence(i) == 0) continue;
    EXPECT_NEAR(squared_laplacian_row_gain(adjacency, i, scratch, touched), l2.row(i).squaredNorm(), 1e-12) << i;
    ASSERT_TRUE(touched.empty());
  }
  for (double c : scratch) ASSERT_EQ(c, 0.0);
}

}  // namespace
}  // namespace hht
