#include "mesh/mean_curvature.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace hht {
namespace {

MeanCurvature curvature(const test::ArrayMesh& m) {
  MeanCurvature h;
  std::string error;
  EXPECT_TRUE(mean_curvature(m.positions, m.faces, h, error)) << error;
  return h;
}

double median(Eigen::VectorXd v) {
  std::nth_element(v.data(), v.data() + v.size() / 2, v.data() + v.size());
  return v[v.size() / 2];
}

TEST(MeanCurvature, SphereGivesTwiceTheInverseRadius) {
  for (double r : {1.0, 3.0}) {
    const MeanCurvature h = curvature(test::sphere(5, r));
    EXPECT_NEAR(median(h.signal) * r, 2.0, 0.02) << "r = " << r;
    EXPECT_NEAR(h.signal.minCoeff() * r, 2.0, 0.06);
    EXPECT_NEAR(h.signal.maxCoeff() * r, 2.0, 0.06);
  }
}

TEST(MeanCurvature, ScaleInvariantTimesLength) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  test::ArrayMesh scaled = m;
  scaled.positions *= 7.5;
  const MeanCurvature a = curvature(m), b = curvature(scaled);
  ASSERT_EQ(a.signal.size(), b.signal.size());
  const double tol = 1e-9 * a.signal.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < a.signal.size(); ++i) ASSERT_NEAR(b.signal[i] * 7.5, a.signal[i], tol) << i;
}

TEST(MeanCurvature, FlippedNormalsFlipTheSign) {
  test::ArrayMesh m = test::sphere(4);
  const MeanCurvature out = curvature(m);
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f) std::swap(m.faces(f, 1), m.faces(f, 2));
  const MeanCurvature in = curvature(m);
  EXPECT_TRUE(in.signal.isApprox(-out.signal, 1e-12));
}

TEST(MeanCurvature, PlaneIsZeroInside) {
  // a flat grid: interior vertices have G = 0 exactly (up to rounding)
  test::ArrayMesh m;
  const int n = 10;
  m.positions.resize(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m.positions.row(i * n + j) << i, j + 0.3 * i, 0;
  m.faces.resize(2 * (n - 1) * (n - 1), 3);
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      m.faces.row(f++) << i * n + j, (i + 1) * n + j, i * n + j + 1;
      m.faces.row(f++) << (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1;
    }
  const MeanCurvature h = curvature(m);
  for (int i = 1; i + 1 < n; ++i)
    for (int j = 1; j + 1 < n; ++j) EXPECT_NEAR(h.signal[i * n + j], 0.0, 1e-12);
}

TEST(MeanCurvature, DegenerateFacesStayFinite) {
  test::ArrayMesh m = test::sphere(3);
  m.positions.row(m.faces(0, 0)) = m.positions.row(m.faces(0, 1));  // a zero-area face
  const MeanCurvature h = curvature(m);
  EXPECT_TRUE(h.signal.allFinite());
}

TEST(MeanCurvature, NaNCoordinatesAreRejected) {
  test::ArrayMesh m = test::sphere(2);
  m.positions(4, 1) = std::nan("");
  MeanCurvature h;
  std::string error;
  EXPECT_FALSE(mean_curvature(m.positions, m.faces, h, error));
  EXPECT_NE(error.find("NaN"), std::string::npos);
}

}  // namespace
}  // namespace hht
