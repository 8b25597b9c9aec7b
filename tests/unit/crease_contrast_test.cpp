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

}  // namespace
}  // namespace hht
