#include "mesh/crease_contrast.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

// A cube made of flat faces meeting at right angles has a high contrast; a sphere, bending the
// same everywhere, a low one; a plane none.
TEST(CreaseContrast, CreasesAgainstEvenBending) {
  const test::ArrayMesh cube = test::load_data_mesh("cube-meshed"), sphere = test::sphere(4);
  EXPECT_GT(crease_contrast(cube.positions, cube.faces), 20.0);
  EXPECT_LT(crease_contrast(sphere.positions, sphere.faces), 3.0);
  Positions plane(4, 3);
  plane << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  Faces two(2, 3);
  two << 0, 1, 2, 0, 2, 3;
  EXPECT_EQ(crease_contrast(plane, two), 0.0);
  Faces one(1, 3);
  one << 0, 1, 2;
  EXPECT_EQ(crease_contrast(plane, one), 0.0);  // no interior edge
}

// A crease is a line: the meshed cube's twelve edges keep their length in units of the mesh's
// breadth when every triangle is cut in four, then in sixteen, while their share of the edges falls
// below the contrast's 2% (docs/quality.md item 28).
TEST(CreaseLines, KeepTheirLengthAsTheMeshIsRefined) {
  test::ArrayMesh cube = test::load_data_mesh("cube-meshed");
  const double coarse = read_creases(dihedral_angles(cube.positions, cube.faces)).lines;
  EXPECT_GT(coarse, 3.0);
  for (int cuts = 1; cuts <= 2; ++cuts) {
    cube = test::midpoint_subdivision(cube);
    const CreaseReadings readings = read_creases(dihedral_angles(cube.positions, cube.faces));
    EXPECT_NEAR(readings.lines, coarse, 0.1 * coarse) << cuts;
    if (cuts == 2) {
      EXPECT_LT(readings.contrast, 9.0);
    }
  }
  const test::ArrayMesh sphere = test::sphere(4);
  EXPECT_EQ(read_creases(dihedral_angles(sphere.positions, sphere.faces)).lines, 0.0);
  EXPECT_EQ(read_creases({}).lines, 0.0);
}

// Sharp spots are not lines: spikes on a fine sphere make small clusters of sharp edges, each
// shorter than the shortest line counted.
TEST(CreaseLines, LeaveOutSharpSpots) {
  test::ArrayMesh sphere = test::sphere(6);
  for (int i = 0; i < sphere.vertices(); i += 1500) sphere.positions.row(i) *= 1.05;
  const std::vector<DihedralAngle> angles = dihedral_angles(sphere.positions, sphere.faces);
  int sharp = 0;
  for (const DihedralAngle& a : angles) sharp += a.radians > 0.3;
  EXPECT_GT(sharp, 200);  // the spikes' edges are far over the median
  EXPECT_EQ(read_creases(angles).lines, 0.0);
}

}  // namespace
}  // namespace hht
