#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/nonlocal_means_denoise.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace hht {
namespace {

double diagonal(const Positions& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

TEST(NonLocalMeans, RemovesNormalNoiseOnATorus) {
  const test::ArrayMesh m = test::torus(3.0, 1.0, 96, 48);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Normal, 5);
  const Positions result = nonlocal_means_denoise(noisy, m.faces, NonLocalMeansOptions{});
  EXPECT_LT(mean_face_normal_error_degrees(result, m.positions, m.faces),
            mean_face_normal_error_degrees(noisy, m.positions, m.faces) / 4);
  EXPECT_LT(mean_distance_to_reference(result, m.positions, m.faces),
            0.75 * mean_distance_to_reference(noisy, m.positions, m.faces));
}

TEST(NonLocalMeans, SimilarityWeightsKeepCreases) {
  // Fandisk with 30% noise: the neighbourhood term must do better than the same average
  // without it (eta2 huge: a plain Gaussian average of the normal offsets).
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Normal, 7);
  NonLocalMeansOptions plain;
  plain.eta2 = 1e6;
  const double with = mean_face_normal_error_degrees(nonlocal_means_denoise(noisy, m.faces, {}), m.positions, m.faces);
  const double without = mean_face_normal_error_degrees(nonlocal_means_denoise(noisy, m.faces, plain), m.positions, m.faces);
  const double before = mean_face_normal_error_degrees(noisy, m.positions, m.faces);
  EXPECT_LT(with, 0.5 * before);
  EXPECT_LT(with, 0.9 * without) << "with " << with << " without " << without << " noisy " << before;
}

TEST(NonLocalMeans, ScaledMeshGivesScaledResult) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Random, 9);
  NonLocalMeansOptions o;
  o.iterations = 1;
  const Positions a = nonlocal_means_denoise(noisy, m.faces, o);
  EXPECT_GT((a - noisy).rowwise().norm().maxCoeff(), 1e-3 * diagonal(noisy));
  for (double s : {0.25, 37.0}) {
    const Positions b = nonlocal_means_denoise(noisy * s, m.faces, o);
    EXPECT_LT((b - a * s).rowwise().norm().maxCoeff(), 1e-9 * diagonal(b)) << "scale " << s;
  }
}

TEST(NonLocalMeans, BadInputComesBackUnchanged) {
  const test::ArrayMesh m = test::sphere(2);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Normal, 1);
  EXPECT_EQ(nonlocal_means_denoise(noisy, Faces(0, 3), {}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {3.0, 1.3, 1.0, 0}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {0.0, 1.3, 1.0, 1}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {3.0, -1.0, 1.0, 1}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {3.0, 1.3, 0.0, 1}), noisy);
  Positions broken = noisy;
  broken(3, 1) = std::numeric_limits<double>::quiet_NaN();
  const Positions back = nonlocal_means_denoise(broken, m.faces, {});
  EXPECT_TRUE(back.row(3).hasNaN());
  EXPECT_EQ(back.topRows(3), noisy.topRows(3));
  Faces bad = m.faces;
  bad(0, 0) = m.vertices();
  EXPECT_EQ(nonlocal_means_denoise(noisy, bad, {}), noisy);
  const Positions point = Positions::Ones(m.vertices(), 3);
  EXPECT_EQ(nonlocal_means_denoise(point, m.faces, {}), point);
}

}  // namespace
}  // namespace hht
