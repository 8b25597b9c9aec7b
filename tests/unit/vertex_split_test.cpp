#include "mesh/vertex_split.h"

#include "mesh/filter_input.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht::test {
namespace {

// Two spheres sharing one vertex (two cones touching at a tip): the shared vertex is split, the
// second sphere's fan moved to the copy, and the mesh is manifold; a result brought back averages
// the copies.
TEST(VertexSplit, GivesEachFanOfANonManifoldVertexItsOwnVertex) {
  const ArrayMesh a = sphere(2);
  ArrayMesh both = disjoint_union(a, a);
  const int n = a.vertices();
  // Shift the second sphere so that its vertex 0 sits on the first's vertex 0, then join them there.
  const Eigen::RowVector3d shift = a.positions.row(0) * 2;
  for (int i = n; i < 2 * n; ++i) both.positions.row(i) = -both.positions.row(i) + shift;
  for (Eigen::Index f = a.faces.rows(); f < both.faces.rows(); ++f) {
    std::swap(both.faces(f, 1), both.faces(f, 2));  // the mirror turned the faces inside out
    for (int k = 0; k < 3; ++k)
      if (both.faces(f, k) == n) both.faces(f, k) = 0;
  }
  CornerTable table;
  int inconsistent = -1;
  std::string error;
  ASSERT_TRUE(build_corner_table(both.faces, 2 * n, table, inconsistent, error)) << error;
  ASSERT_EQ(inconsistent, 0);
  ASSERT_EQ(count_nonmanifold_vertices(table, 2 * n), 1);

  Faces faces = both.faces;
  VertexSplit split;
  EXPECT_EQ(split_nonmanifold_vertices(faces, table, 2 * n, split), 1);
  ASSERT_EQ(split.copy_of, std::vector<int>{0});
  ASSERT_TRUE(build_corner_table(faces, 2 * n + 1, table, inconsistent, error)) << error;
  EXPECT_EQ(count_nonmanifold_vertices(table, 2 * n + 1), 0);
  int on_copy = 0, on_zero = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      on_copy += faces(f, k) == 2 * n;
      on_zero += faces(f, k) == 0;
    }
  EXPECT_GT(on_copy, 0);
  EXPECT_GT(on_zero, 0);

  // Through the filters' preparation: the split reported, and values of the copies averaged back.
  Positions p = both.positions;
  Faces g = both.faces;
  InputMap map;
  FilterInputReport report;
  prepare_filter_input(p, g, true, map, report);
  EXPECT_EQ(report.split, 1);
  ASSERT_EQ(p.rows(), 2 * n + 1);
  EXPECT_EQ(p.row(2 * n), p.row(0));
  Eigen::VectorXd rows = Eigen::VectorXd::Zero(2 * n + 1);
  rows[0] = 1;
  rows[2 * n] = 3;
  const Eigen::VectorXd back = to_input_vertices(rows, map);
  ASSERT_EQ(back.size(), 2 * n);
  EXPECT_EQ(back[0], 2);
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
