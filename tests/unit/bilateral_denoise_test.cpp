#include "filters/bilateral_denoise.h"
#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hht {
namespace {

double diagonal(const Positions& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

TEST(Bilateral, RemovesNormalNoiseOnASphere) {
  const test::ArrayMesh m = test::sphere(4);
  const double l = mean_edge_length(m.positions, m.faces);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Normal, 3);
  const Positions result = bilateral_denoise(noisy, m.faces, BilateralOptions{});

  const Eigen::ArrayXd r_noisy = noisy.rowwise().norm().array(), r = result.rowwise().norm().array();
  auto spread = [](const Eigen::ArrayXd& x) { return std::sqrt((x - x.mean()).square().mean()); };
  EXPECT_LT(spread(r), spread(r_noisy) / 4);
  // Bilateral filtering shrinks curved surfaces (h ~ -t^2 / 2R per pass, t ~ l); that, not
  // left-over noise, is most of what remains of the distance to the clean sphere.
  EXPECT_GT(r.mean(), 1.0 - 0.3 * l);
  EXPECT_LT(mean_face_normal_error_degrees(result, m.positions, m.faces),
            mean_face_normal_error_degrees(noisy, m.positions, m.faces) / 4);
}

TEST(Bilateral, RemovesNormalNoiseOnATorus) {
  const test::ArrayMesh m = test::torus(3.0, 1.0, 96, 48);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Normal, 5);
  const Positions result = bilateral_denoise(noisy, m.faces, BilateralOptions{});
  EXPECT_LT(mean_face_normal_error_degrees(result, m.positions, m.faces),
            mean_face_normal_error_degrees(noisy, m.positions, m.faces) / 4);
  EXPECT_LT(mean_distance_to_reference(result, m.positions, m.faces),
            0.75 * mean_distance_to_reference(noisy, m.positions, m.faces));
}

TEST(Bilateral, KeepsTheCubesEdgesAndCorners) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");  // the cube [-1, 1]^3
  const double l = mean_edge_length(m.positions, m.faces);
  const Positions result = bilateral_denoise(m.positions, m.faces, BilateralOptions{});
  double corner_move = 0, edge_move = 0;
  for (int i = 0; i < m.vertices(); ++i) {
    const Eigen::Array3d a = m.positions.row(i).array().abs();
    const int planes = (a > 1 - 1e-9).count();
    const double move = (result.row(i) - m.positions.row(i)).norm() / l;
    if (planes == 3) corner_move = std::max(corner_move, move);
    // Edge vertices away from the corners, where the edge is locally straight.
    if (planes == 2 && (a < 1 - 3 * l).any()) edge_move = std::max(edge_move, move);
  }
  // The range weight stops the faces on either side of an edge from averaging into each
  // other; at a corner every neighbour is on the inside, so it rounds a little.
  EXPECT_LT(edge_move, 0.1);
  EXPECT_LT(corner_move, 1.0);
  EXPECT_LT(mean_face_normal_error_degrees(result, m.positions, m.faces), 3.0);
}

TEST(Bilateral, ScaledMeshGivesScaledResult) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Random, 9);
  const BilateralOptions o{0.4, 0.05, 3};
  const Positions a = bilateral_denoise(noisy, m.faces, o);
  EXPECT_GT((a - noisy).rowwise().norm().maxCoeff(), 1e-3 * diagonal(noisy));
  for (double s : {0.25, 37.0}) {
    const Positions b = bilateral_denoise(noisy * s, m.faces, o);
    EXPECT_LT((b - a * s).rowwise().norm().maxCoeff(), 1e-9 * diagonal(b)) << "scale " << s;
  }
}

TEST(Bilateral, BadInputComesBackUnchanged) {
  const test::ArrayMesh m = test::sphere(2);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Normal, 1);
  EXPECT_EQ(bilateral_denoise(noisy, Faces(0, 3), BilateralOptions{}), noisy);
  EXPECT_EQ(bilateral_denoise(noisy, m.faces, BilateralOptions{0.4, 0.15, 0}), noisy);
  EXPECT_EQ(bilateral_denoise(noisy, m.faces, BilateralOptions{0.0, 0.15, 5}), noisy);
  EXPECT_EQ(bilateral_denoise(noisy, m.faces, BilateralOptions{0.4, -1.0, 5}), noisy);
  Positions broken = noisy;
  broken(3, 1) = std::numeric_limits<double>::quiet_NaN();
  const Positions back = bilateral_denoise(broken, m.faces, BilateralOptions{});
  EXPECT_TRUE(back.row(3).hasNaN());
  EXPECT_EQ(back.topRows(3), noisy.topRows(3));
  const Positions point = Positions::Ones(m.vertices(), 3);
  EXPECT_EQ(bilateral_denoise(point, m.faces, BilateralOptions{}), point);
}

TEST(Bilateral, VertexOfNoFaceStaysPut) {
  test::ArrayMesh m = test::sphere(3);
  m.positions.conservativeResize(m.vertices() + 1, 3);
  m.positions.row(m.vertices() - 1) << 0.1, 0.2, 0.3;  // inside the sphere, in no face
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Normal, 2);
  const Positions result = bilateral_denoise(noisy, m.faces, BilateralOptions{});
  EXPECT_EQ(result.bottomRows(1), noisy.bottomRows(1));
  EXPECT_GT((result - noisy).rowwise().norm().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace hht
