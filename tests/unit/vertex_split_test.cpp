#include "mesh/vertex_split.h"

#include "mesh/filter_input.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht::test {
namespace {

// Two spheres sharing one vertex (two fans meeting at it): the shared vertex is split, one fan
// moved to the copy, and the mesh is manifold; a result brought back averages the copies.
TEST(VertexSplit, GivesEachFanOfANonManifoldVertexItsOwnVertex) {
  const ArrayMesh both = touching_spheres(2);
  const int n = both.vertices();
  CornerTable table;
  int inconsistent = -1;
  std::string error;
  ASSERT_TRUE(build_corner_table(both.faces, n, table, inconsistent, error)) << error;
  ASSERT_EQ(inconsistent, 0);
  ASSERT_EQ(count_nonmanifold_vertices(table, n), 1);

  Faces faces = both.faces;
  VertexSplit split;
  EXPECT_EQ(split_nonmanifold_vertices(faces, table, n, split), 1);
  ASSERT_EQ(split.copy_of, std::vector<int>{0});
  ASSERT_TRUE(build_corner_table(faces, n + 1, table, inconsistent, error)) << error;
  EXPECT_EQ(count_nonmanifold_vertices(table, n + 1), 0);
  int on_copy = 0, on_zero = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      on_copy += faces(f, k) == n;
      on_zero += faces(f, k) == 0;
    }
  EXPECT_GT(on_copy, 0);
  EXPECT_GT(on_zero, 0);

  // Through the filters' preparation: the split reported, and the value of one of the two copies
  // (the spheres are mirror images: as much area around each) brought back.
  Positions p = both.positions;
  Faces g = both.faces;
  InputMap map;
  FilterInputReport report;
  prepare_filter_input(p, g, true, map, report);
  EXPECT_EQ(report.split, 1);
  ASSERT_EQ(p.rows(), n + 1);
  EXPECT_EQ(p.row(n), p.row(0));
  Eigen::VectorXd rows = Eigen::VectorXd::Zero(n + 1);
  rows[0] = 1;
  rows[n] = 3;
  const Eigen::VectorXd back = to_input_vertices(rows, map);
  ASSERT_EQ(back.size(), n);
  EXPECT_TRUE(back[0] == 1 || back[0] == 3) << back[0];
}

// A manifold mesh, holes included, has nothing to split.
TEST(VertexSplit, LeavesAManifoldMeshAlone) {
  for (const char* name : {"fandisk", "elephant-with-holes"}) {
    const ArrayMesh m = load_data_mesh(name);
    CornerTable table;
    int inconsistent = -1;
    std::string error;
    ASSERT_TRUE(build_corner_table(m.faces, m.vertices(), table, inconsistent, error)) << error;
    ASSERT_EQ(count_nonmanifold_vertices(table, m.vertices()), 0) << name;
    Faces faces = m.faces;
    VertexSplit split;
    EXPECT_EQ(split_nonmanifold_vertices(faces, table, m.vertices(), split), 0) << name;
    EXPECT_TRUE(faces == m.faces) << name;
  }
}

}  // namespace
}  // namespace hht::test
