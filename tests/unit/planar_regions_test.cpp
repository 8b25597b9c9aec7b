#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/planar_regions.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace hht {
namespace {

// The meshed cube with slight bumps along the normals (1% of the mean edge, each face within a
// few degrees of its side's plane, as the guided filter leaves a part's flat faces): its six
// sides are found and made flat, creases included, so the normal error falls to a small part
// of what it was. With the vertex update left out (the input returned) it stays where it was.
TEST(PlanarRegions, MakesTheSidesOfABumpyCubeFlat) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  const Positions bumpy = add_gaussian_noise(m.positions, m.faces, 1, NoiseDirection::Normal, 11);
  Positions flat;
  PlanarRegionReport report;
  std::string error;
  ASSERT_TRUE(flatten_planar_regions(bumpy, m.faces, {}, flat, report, error)) << error;
  EXPECT_EQ(report.regions, 6);
  EXPECT_GT(report.faces, 0.9 * m.faces.rows());  // measured 1696 of 1728: a few faces lie more than 3 degrees off
  const double before = mean_face_normal_error_degrees(bumpy, m.positions, m.faces);
  const double after = mean_face_normal_error_degrees(flat, m.positions, m.faces);
  EXPECT_GT(before, 0.5);
  EXPECT_LT(after, 0.2 * before);
}

// A grid bent into a shallow arc (its normals turn by 12 degrees from end to end): every region
// of faces within 3 degrees of its seed bends by more than a degree, so nothing is made flat and
// the result is the input, bit for bit. Fails if the bend test is left out.
TEST(PlanarRegions, LeavesAGentlyCurvedSurfaceAsItIs) {
  test::ArrayMesh m = test::grid(40, 40);
  const double radius = 39 / (12 * M_PI / 180);
  for (Eigen::Index i = 0; i < m.positions.rows(); ++i) {
    const double angle = (m.positions(i, 0) - 19.5) / radius;
    m.positions(i, 0) = radius * std::sin(angle);
    m.positions(i, 2) = radius * (std::cos(angle) - 1);
  }
  Positions out;
  PlanarRegionReport report;
  std::string error;
  ASSERT_TRUE(flatten_planar_regions(m.positions, m.faces, {}, out, report, error)) << error;
  EXPECT_EQ(report.regions, 0);
  EXPECT_EQ(out, m.positions);
}

// A flat grid with a bump in its middle: the grid around it is a region (and a plane), the bump
// is not part of it and keeps its height.
TEST(PlanarRegions, KeepsABumpOnAPlane) {
  test::ArrayMesh m = test::grid(30, 30);
  const int middle = 15 * 30 + 15;
  m.positions(middle, 2) = 2.0;
  Positions out;
  PlanarRegionReport report;
  std::string error;
  ASSERT_TRUE(flatten_planar_regions(m.positions, m.faces, {}, out, report, error)) << error;
  EXPECT_EQ(report.regions, 1);
  EXPECT_EQ(report.faces, m.faces.rows() - 6);
  EXPECT_NEAR(out(middle, 2), 2.0, 1e-9);
  EXPECT_LT((out - m.positions).cwiseAbs().maxCoeff(), 1e-9);
}

// A flat grid with a low bump over its whole extent (under half a degree of slope): one region,
// a plane. Sun et al.'s update takes such a bump down by a few percent an iteration, so the fit
// goes on in steps until it settles (item 37): under a third of the bump's height is left (0.26
// measured). Fails with the fit stopped after its first step of 20 iterations (0.87 left).
TEST(PlanarRegions, FlattensALowBumpAcrossARegion) {
  const int side = 30;
  test::ArrayMesh m = test::grid(side, side);
  const double half = (side - 1) / 2.0, height = 0.1;
  for (Eigen::Index i = 0; i < m.positions.rows(); ++i)
    m.positions(i, 2) = height * std::cos(M_PI / 2 * (m.positions(i, 0) - half) / half) *
                        std::cos(M_PI / 2 * (m.positions(i, 1) - half) / half);
  Positions out;
  PlanarRegionReport report;
  std::string error;
  ASSERT_TRUE(flatten_planar_regions(m.positions, m.faces, {}, out, report, error)) << error;
  EXPECT_EQ(report.regions, 1);
  EXPECT_GT(report.fit_iterations, 20);
  const Eigen::VectorXd z = out.col(2);
  EXPECT_LT(z.maxCoeff() - z.minCoeff(), height / 3);
}

// A non-manifold edge is refused with a message and the output left as it was.
TEST(PlanarRegions, RefusesANonManifoldEdge) {
  Positions p(5, 3);
  p << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
  Faces f(3, 3);
  f << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  const Positions sentinel = Positions::Constant(2, 3, 7.0);
  Positions out = sentinel;
  PlanarRegionReport report;
  std::string error;
  EXPECT_FALSE(flatten_planar_regions(p, f, {}, out, report, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(out, sentinel);
}

}  // namespace
}  // namespace hht
