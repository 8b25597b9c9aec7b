#include "mesh/filter_input.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht::test {
namespace {

// A soup of a sphere (every face with vertices of its own) with every other face reversed comes
// out as the sphere: positions merged, faces over them oriented as the first face, each input
// vertex mapped to its row; without merging only the orientation could be checked, and a soup has
// none to check. A coherent closed mesh goes through untouched.
TEST(FilterInput, MakesASoupWithFacesAgainstTheirNeighboursOneOrientedSurface) {
  const ArrayMesh m = sphere(2);
  const int nf = static_cast<int>(m.faces.rows());
  Positions soup(3 * nf, 3);
  Faces faces(nf, 3);
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) soup.row(3 * f + k) = m.positions.row(m.faces(f, k));
    faces.row(f) << 3 * f, 3 * f + (f % 2 ? 2 : 1), 3 * f + (f % 2 ? 1 : 2);
  }
  Positions p = soup;
  Faces g = faces;
  InputMap map;
  FilterInputReport report;
  prepare_filter_input(p, g, true, map, report);
  EXPECT_EQ(p.rows(), m.positions.rows());
  EXPECT_EQ(report.merged, 3 * nf - m.positions.rows());
  EXPECT_EQ(report.orientation.flipped, nf / 2);
  ASSERT_EQ(map.row_of.size(), static_cast<size_t>(3 * nf));
  for (int i = 0; i < 3 * nf; ++i) EXPECT_EQ(p.row(map.row(i)), soup.row(i));
  CornerTable table;
  int inconsistent = -1;
  std::string error;
  ASSERT_TRUE(build_corner_table(g, static_cast<int>(p.rows()), table, inconsistent, error)) << error;
  EXPECT_EQ(inconsistent, 0);

  p = soup;
  g = faces;
  prepare_filter_input(p, g, false, map, report);
  EXPECT_TRUE(map.identity());
  EXPECT_EQ(report.merged, 0);
  EXPECT_EQ(report.orientation.flipped, 0) << "a soup's faces have no neighbours to disagree with";

  p = m.positions;
  g = m.faces;
  prepare_filter_input(p, g, true, map, report);
  EXPECT_TRUE(map.identity());
  EXPECT_TRUE(p == m.positions && g == m.faces);
}

}  // namespace
}  // namespace hht::test
