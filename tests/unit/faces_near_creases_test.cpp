#include "mesh/faces_near_creases.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace hht {
namespace {

// On the meshed cube only the faces touching its twelve edges are near a crease; a sphere's
// gentle bends and a plane have none.
TEST(FacesNearCreases, TheCubesEdgesAndNothingElse) {
  const test::ArrayMesh cube = test::load_data_mesh("cube-meshed");
  const std::vector<unsigned char> near = faces_near_creases(dihedral_angles(cube.positions, cube.faces), cube.faces, cube.positions.rows(), 30);
  ASSERT_EQ(near.size(), static_cast<size_t>(cube.faces.rows()));
  const Eigen::RowVector3d low = cube.positions.colwise().minCoeff(), high = cube.positions.colwise().maxCoeff();
  const double tolerance = 1e-6 * (high - low).norm();
  const auto on_an_edge = [&](int v) {  // two coordinates at the box's bounds
    int bounds = 0;
    for (int k = 0; k < 3; ++k)
      bounds += std::abs(cube.positions(v, k) - low[k]) < tolerance || std::abs(cube.positions(v, k) - high[k]) < tolerance;
    return bounds >= 2;
  };
  for (Eigen::Index f = 0; f < cube.faces.rows(); ++f)
    EXPECT_EQ(near[f] != 0, on_an_edge(cube.faces(f, 0)) || on_an_edge(cube.faces(f, 1)) || on_an_edge(cube.faces(f, 2))) << f;
  EXPECT_GT(std::count(near.begin(), near.end(), 1), 0);
  EXPECT_LT(std::count(near.begin(), near.end(), 1), cube.faces.rows());

  const test::ArrayMesh sphere = test::sphere(4);
  const std::vector<unsigned char> none = faces_near_creases(dihedral_angles(sphere.positions, sphere.faces), sphere.faces, sphere.positions.rows(), 30);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 0), sphere.faces.rows());
}

// A fold of 40 degrees between two triangles is a crease at 30 and none at 50; an edge of one
// face and a face of zero area make none.
TEST(FacesNearCreases, TheAngleDecidesAndBoundariesAreNoCreases) {
  const double a = 40 * M_PI / 180;
  Positions p(4, 3);
  p << 0, 0, 0, 0, 1, 0, -1, 0.5, 0, std::cos(a), 0.5, std::sin(a);
  Faces two(2, 3);
  two << 0, 1, 2, 1, 0, 3;
  EXPECT_EQ(faces_near_creases(dihedral_angles(p, two), two, 4, 30), (std::vector<unsigned char>{1, 1}));
  EXPECT_EQ(faces_near_creases(dihedral_angles(p, two), two, 4, 50), (std::vector<unsigned char>{0, 0}));
  Faces one(1, 3);
  one << 0, 1, 2;
  EXPECT_EQ(faces_near_creases(dihedral_angles(p, one), one, 4, 1), (std::vector<unsigned char>{0}));
  Positions flat = p;
  flat.row(3) = flat.row(0);  // the second face has no area
  EXPECT_EQ(faces_near_creases(dihedral_angles(flat, two), two, 4, 1), (std::vector<unsigned char>{0, 0}));
}

}  // namespace
}  // namespace hht
