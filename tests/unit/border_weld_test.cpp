#include "mesh/border_weld.h"

#include "mesh/breadth_first_patches.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht::test {
namespace {

// Every face with three vertices of its own, as a triangle soup is written.
ArrayMesh soup_of(const ArrayMesh& m) {
  ArrayMesh s;
  s.positions.resize(3 * m.faces.rows(), 3);
  s.faces.resize(m.faces.rows(), 3);
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      s.positions.row(3 * f + k) = m.positions.row(m.faces(f, k));
      s.faces(f, k) = static_cast<int>(3 * f + k);
    }
  return s;
}

// A soup of a closed sphere is the sphere again: each position once, the faces over them in the
// sphere's own connectivity, and a result spread back gives every copy its vertex's value.
TEST(BorderWeld, MakesASoupWholeAgain) {
  const ArrayMesh m = sphere(3);
  const ArrayMesh s = soup_of(m);
  BorderWeld weld;
  std::string why_not;
  ASSERT_TRUE(weld_coincident_border_vertices(s.positions, s.faces, weld, why_not)) << why_not;
  EXPECT_EQ(weld.positions.rows(), m.positions.rows());
  EXPECT_EQ(weld.merged, static_cast<int>(s.positions.rows() - m.positions.rows()));
  EXPECT_EQ(weld.dropped_faces, 0);
  ASSERT_EQ(weld.faces.rows(), m.faces.rows());
  CornerTable table;
  int inconsistent = -1;
  ASSERT_TRUE(build_corner_table(weld.faces, static_cast<int>(weld.positions.rows()), table, inconsistent, why_not));
  for (int c = 0; c < table.corners(); ++c) EXPECT_GE(table.opposite[c], 0) << "a closed surface has no border";
  for (Eigen::Index f = 0; f < s.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(weld.positions.row(weld.faces(f, k)), s.positions.row(s.faces(f, k)));
  const Positions back = rows_at(weld.positions, weld.welded_of);
  EXPECT_TRUE(back == s.positions);
}

// A grid (borders, none of its vertices on another) and a closed sphere (no borders) are left
// alone with nothing to say.
TEST(BorderWeld, LeavesAJoinedMeshAlone) {
  for (const ArrayMesh& m : {grid(6, 5), sphere(2)}) {
    BorderWeld weld;
    std::string why_not;
    EXPECT_FALSE(weld_coincident_border_vertices(m.positions, m.faces, weld, why_not));
    EXPECT_TRUE(why_not.empty()) << why_not;
    EXPECT_TRUE(weld.welded_of.empty());
  }
}

// Merging that would make the surface worse is refused with the reason: two soups touching at a
// corner only (a vertex joining two fans). Three faces of a soup on one edge are merged into an edge
// of three faces: the corner table pairs two of them and leaves the third a border (item 44), and the
// vertices of that edge, whose faces come apart there anyway, do not count as joining parts.
TEST(BorderWeld, RefusesToJoinPartsAtAVertexOnly) {
  ArrayMesh fin;
  fin.positions.resize(9, 3);
  fin.positions << 0, 0, 0, 1, 0, 0, 0, 1, 0,  //
      0, 0, 0, 1, 0, 0, 0, -1, 0,               //
      0, 0, 0, 1, 0, 0, 0, 0, 1;
  fin.faces.resize(3, 3);
  fin.faces << 0, 1, 2, 4, 3, 5, 6, 7, 8;
  BorderWeld weld;
  std::string why_not;
  ASSERT_TRUE(weld_coincident_border_vertices(fin.positions, fin.faces, weld, why_not)) << why_not;
  EXPECT_EQ(weld.merged, 4);
  EXPECT_EQ(weld.positions.rows(), 5);
  CornerTable table;
  int inconsistent = 0, cut = 0;
  ASSERT_TRUE(build_corner_table_cutting(weld.faces, weld.positions, table, inconsistent, cut, why_not));
  EXPECT_EQ(cut, 1);

  ArrayMesh bow;
  bow.positions.resize(6, 3);
  bow.positions << 0, 0, 0, 1, 0, 0, 0, 1, 0,  //
      0, 0, 0, -1, 0, 0, 0, -1, 0;
  bow.faces.resize(2, 3);
  bow.faces << 0, 1, 2, 3, 4, 5;
  EXPECT_FALSE(weld_coincident_border_vertices(bow.positions, bow.faces, weld, why_not));
  EXPECT_NE(why_not.find("single vertex"), std::string::npos) << why_not;
}

}  // namespace
}  // namespace hht::test
