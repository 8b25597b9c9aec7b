#include "mesh/intrinsic_delaunay.h"
#include "mesh/mean_curvature.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>

namespace hht {
namespace {

double mean_edge(const test::ArrayMesh& m) {
  double sum = 0;
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (m.positions.row(m.faces(f, k)) - m.positions.row(m.faces(f, (k + 1) % 3))).norm();
  return sum / (3.0 * m.faces.rows());
}

Eigen::MatrixXd dense(const CotangentLaplacian& l, int n) { return Eigen::MatrixXd(cotangent_matrix(l, n)); }

// The summed weight of each vertex pair (both corners facing an edge), the pair's entry -C_ij.
std::map<std::pair<int, int>, double> pair_weights(const CotangentLaplacian& l) {
  std::map<std::pair<int, int>, double> w;
  for (Eigen::Index e = 0; e < l.weights.size(); ++e)
    w[{std::min(l.pairs(e, 0), l.pairs(e, 1)), std::max(l.pairs(e, 0), l.pairs(e, 1))}] += l.weights[e];
  return w;
}

// Flipped on its tufted cover (a mesh with borders), `m` keeps no vertex pair of negative weight
// (loops, whose weight cancels, aside) and its own area.
void expect_no_negative_weight_on_the_cover(const test::ArrayMesh& m) {
  IntrinsicDelaunayReport report;
  const CotangentLaplacian l = intrinsic_delaunay_laplacian(m.positions, m.faces, &report);
  EXPECT_TRUE(report.intrinsic);
  EXPECT_TRUE(report.tufted_cover);
  int negative = 0;
  for (const auto& [pair, w] : pair_weights(l)) negative += pair.first != pair.second && w < -1e-9 ? 1 : 0;
  EXPECT_EQ(negative, 0);
  EXPECT_NEAR(l.areas.sum(), mixed_voronoi_areas(m.positions, m.faces).sum(), 1e-9 * l.areas.sum());
}

// A jittered grid in the plane, each square split along the diagonal whose opposite angles sum to
// more than pi (`delaunay` false) or less (true). Flat, so its intrinsic Delaunay triangulation is
// the planar Delaunay one: per square, the other diagonal.
test::ArrayMesh jittered_grid(int size, bool delaunay) {
  test::ArrayMesh m = test::grid(size, size);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  for (int i = 0; i < m.vertices(); ++i) m.positions.row(i) += Eigen::RowVector3d(jitter(rng), jitter(rng), 0);
  const auto angle = [&](int at, int a, int b) {
    const Eigen::RowVector3d u = m.positions.row(a) - m.positions.row(at), v = m.positions.row(b) - m.positions.row(at);
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  int f = 0;
  for (int j = 0; j + 1 < size; ++j)
    for (int i = 0; i + 1 < size; ++i) {
      const int a = j * size + i, b = a + 1, c = a + size, d = c + 1;
      // diagonal a-d is faced by the corners at b and c
      const bool ad_delaunay = angle(b, a, d) + angle(c, a, d) <= M_PI;
      if (ad_delaunay == delaunay) {
        m.faces.row(f++) << a, b, d;
        m.faces.row(f++) << a, d, c;
      } else {
        m.faces.row(f++) << a, b, c;
        m.faces.row(f++) << b, d, c;
      }
    }
  return m;
}

TEST(IntrinsicDelaunay, AFlatMeshGetsItsPlanarDelaunayTriangulationsLaplacian) {
  const test::ArrayMesh wrong = jittered_grid(12, false), right = jittered_grid(12, true);
  IntrinsicDelaunayReport report;
  const CotangentLaplacian l = intrinsic_delaunay_laplacian(wrong.positions, wrong.faces, &report);
  EXPECT_TRUE(report.intrinsic);
  EXPECT_EQ(report.mollified, 0.0);
  EXPECT_GE(report.flips, 100);  // most of the 121 squares
  const CotangentLaplacian expected = extrinsic_cotangent_laplacian(right.positions, right.faces);
  const int n = wrong.vertices();
  EXPECT_LT((dense(l, n) - dense(expected, n)).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((l.areas - expected.areas).cwiseAbs().maxCoeff(), 1e-9);
  // the mesh's own weights differ: some are negative
  const CotangentLaplacian own = extrinsic_cotangent_laplacian(wrong.positions, wrong.faces);
  EXPECT_GT((dense(own, n) - dense(expected, n)).cwiseAbs().maxCoeff(), 0.1);
}

TEST(IntrinsicDelaunay, ADelaunayMeshKeepsItsOwnTriangles) {
  const test::ArrayMesh m = test::sphere(4);
  IntrinsicDelaunayReport report;
  const CotangentLaplacian l = intrinsic_delaunay_laplacian(m.positions, m.faces, &report);
  EXPECT_TRUE(report.intrinsic);
  EXPECT_EQ(report.flips, 0);
  const CotangentLaplacian own = extrinsic_cotangent_laplacian(m.positions, m.faces);
  EXPECT_LT((dense(l, m.vertices()) - dense(own, m.vertices())).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((l.areas - own.areas).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(IntrinsicDelaunay, InteriorWeightsAreNonNegativeOnARealMesh) {
  // bull: 5% of its faces have an angle under 9 degrees; closed, so every edge is interior
  const test::ArrayMesh m = test::load_data_mesh("bull");
  IntrinsicDelaunayReport report;
  const CotangentLaplacian l = intrinsic_delaunay_laplacian(m.positions, m.faces, &report);
  ASSERT_TRUE(report.intrinsic);
  int negative = 0;
  for (const auto& [pair, w] : pair_weights(l)) negative += w < -1e-9 ? 1 : 0;
  EXPECT_EQ(negative, 0);
  int own_negative = 0;
  for (const auto& [pair, w] : pair_weights(extrinsic_cotangent_laplacian(m.positions, m.faces)))
    own_negative += w < -1e-9 ? 1 : 0;
  EXPECT_GT(own_negative, 100);
  // the same surface: the total area is the mesh's
  EXPECT_NEAR(l.areas.sum(), mixed_voronoi_areas(m.positions, m.faces).sum(), 1e-9 * l.areas.sum());
}

// On a mesh with holes the flips run on the tufted cover, so an obtuse angle facing a border edge
// is flipped away too: elephant-with-holes has 83 vertex pairs of negative weight over its own
// triangles (74 after flipping only its interior edges), none on the cover; its area is its own.
TEST(IntrinsicDelaunay, BorderWeightsAreNonNegativeOnTheTuftedCover) {
  const test::ArrayMesh m = test::load_data_mesh("elephant-with-holes");
  expect_no_negative_weight_on_the_cover(m);
  int own_negative = 0;
  for (const auto& [pair, w] : pair_weights(extrinsic_cotangent_laplacian(m.positions, m.faces)))
    own_negative += w < -1e-9 ? 1 : 0;
  EXPECT_GT(own_negative, 50);

  // One obtuse triangle: its cover is a pillow of two, whose border edge flips into a loop at the
  // obtuse corner; the two other pairs keep positive weights, the obtuse pair none.
  test::ArrayMesh triangle;
  triangle.positions.resize(3, 3);
  triangle.positions << 0, 0, 0, 1, 0, 0, 0.5, 0.1, 0;
  triangle.faces.resize(1, 3);
  triangle.faces << 0, 1, 2;
  const auto w = pair_weights(intrinsic_delaunay_laplacian(triangle.positions, triangle.faces));
  EXPECT_LT(pair_weights(extrinsic_cotangent_laplacian(triangle.positions, triangle.faces)).at({0, 1}), 0.0);
  EXPECT_EQ(w.count({0, 1}), 0u);
  EXPECT_GT(w.at({0, 2}), 0.0);
  EXPECT_GT(w.at({1, 2}), 0.0);
}

// On the cover, flips make triangles with a vertex twice, and a flip can then meet its two
// triangles' outer sides glued to each other (libcgal-demo's boeing, a CAD export with borders, twice):
// those sides move to the flipped triangles together and stay glued. Left to their old corners, the
// table loses a side's length on one side, which the check at the end catches and the mesh's own
// triangles (with their negative weights) are taken instead.
TEST(IntrinsicDelaunay, SidesGluedToEachOtherStayGluedThroughAFlip) {
  expect_no_negative_weight_on_the_cover(test::load_data_mesh("boeing"));
}

TEST(IntrinsicDelaunay, CurvatureOfAnIrregularSphereIsCloserToTheTruth) {
  // a sphere's vertices slid along it by 0.2 mean edges: irregular triangles on the same sphere
  test::ArrayMesh m = test::sphere(4);
  const double h = mean_edge(m);
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, 1);
  for (int i = 0; i < m.vertices(); ++i)
    m.positions.row(i) = (m.positions.row(i) + 0.2 * h * Eigen::RowVector3d(g(rng), g(rng), g(rng))).normalized();
  double error[2];
  for (int k = 0; k < 2; ++k) {
    MeanCurvature c;
    std::string message;
    ASSERT_TRUE(mean_curvature(m.positions, m.faces, c, message,
                               k == 0 ? LaplacianTriangles::Mesh : LaplacianTriangles::IntrinsicDelaunay));
    error[k] = std::sqrt((c.signal.array() - 2.0).square().mean());  // G = 2 / r
  }
  std::cout << "RMS error of G: the mesh's triangles " << error[0] << ", intrinsic Delaunay " << error[1] << "\n";
  EXPECT_LT(error[1], 0.5 * error[0]);  // measured 0.15 against 0.42
}

TEST(IntrinsicDelaunay, ScaledMeshGivesTheSameWeights) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const CotangentLaplacian a = intrinsic_delaunay_laplacian(m.positions, m.faces);
  const CotangentLaplacian b = intrinsic_delaunay_laplacian(m.positions * 0.02, m.faces);
  ASSERT_EQ(a.pairs, b.pairs);
  EXPECT_LT((a.weights - b.weights).cwiseAbs().maxCoeff(), 1e-9 * a.weights.cwiseAbs().maxCoeff());
  EXPECT_LT((b.areas - 0.0004 * a.areas).cwiseAbs().maxCoeff(), 1e-9 * b.areas.maxCoeff());
}

TEST(IntrinsicDelaunay, AFaceOfNoAreaGetsFiniteWeights) {
  // A vertex C on the border edge AB: the face (C, A, B) has no area, its angle at C is 180 degrees,
  // and no flip takes AB away (laid out against its mirror on the cover, the quad is flat, not
  // convex). Its own cotangents are only bounded (1e8).
  test::ArrayMesh m;
  m.positions.resize(4, 3);
  m.positions << 0, 0, 0, 2, 0, 0, 1, 0, 0, 1, 1, 0;  // A, B, C, D
  m.faces.resize(3, 3);
  m.faces << 0, 2, 3, 2, 1, 3, 2, 0, 1;
  IntrinsicDelaunayReport report;
  const CotangentLaplacian l = intrinsic_delaunay_laplacian(m.positions, m.faces, &report);
  EXPECT_TRUE(report.intrinsic);
  EXPECT_GT(report.mollified, 0.0);
  EXPECT_LE(report.mollified, 2 * kMollifyMargin);
  EXPECT_LT(l.weights.cwiseAbs().maxCoeff(), 1e3);
  EXPECT_GT(extrinsic_cotangent_laplacian(m.positions, m.faces).weights.cwiseAbs().maxCoeff(), 1e6);
  EXPECT_GT(l.areas.minCoeff(), 0.0);

  // Inside a surface such faces are flipped away; G stays finite.
  test::ArrayMesh sphere = test::sphere(3);
  for (Eigen::Index f : {0, 40, 80, 120, 160, 200})
    sphere.positions.row(sphere.faces(f, 2)) =
        0.5 * (sphere.positions.row(sphere.faces(f, 0)) + sphere.positions.row(sphere.faces(f, 1)));
  MeanCurvature c;
  std::string message;
  ASSERT_TRUE(mean_curvature(sphere.positions, sphere.faces, c, message, LaplacianTriangles::IntrinsicDelaunay));
  EXPECT_TRUE(c.signal.allFinite());
  EXPECT_LT(intrinsic_delaunay_laplacian(sphere.positions, sphere.faces).weights.cwiseAbs().maxCoeff(), 1e3);
}

TEST(IntrinsicDelaunay, OrientationDoesNotMatterAndANonManifoldMeshKeepsItsOwnTriangles) {
  test::ArrayMesh m = test::flip_random_edges(test::sphere(3), 100, 7);
  test::ArrayMesh mixed = m;
  for (Eigen::Index f = 0; f < mixed.faces.rows(); f += 3) std::swap(mixed.faces(f, 1), mixed.faces(f, 2));
  IntrinsicDelaunayReport a, b;
  const CotangentLaplacian la = intrinsic_delaunay_laplacian(m.positions, m.faces, &a);
  const CotangentLaplacian lb = intrinsic_delaunay_laplacian(mixed.positions, mixed.faces, &b);
  EXPECT_TRUE(a.intrinsic && b.intrinsic);
  EXPECT_GT(a.flips, 0);
  EXPECT_LT((dense(la, m.vertices()) - dense(lb, m.vertices())).cwiseAbs().maxCoeff(), 1e-9);

  const test::ArrayMesh fin = test::finned_sphere(3, 4);
  IntrinsicDelaunayReport c;
  const CotangentLaplacian lf = intrinsic_delaunay_laplacian(fin.positions, fin.faces, &c);
  EXPECT_FALSE(c.intrinsic);
  const CotangentLaplacian own = extrinsic_cotangent_laplacian(fin.positions, fin.faces);
  EXPECT_EQ(lf.weights, own.weights);
}

}  // namespace
}  // namespace hht
