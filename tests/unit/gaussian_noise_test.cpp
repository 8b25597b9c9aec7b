#include "evaluation/gaussian_noise.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hht {
namespace {

// The noise's part along the normals, in the noisy mesh's mean edge: sigma for noise along the
// normals and per coordinate, about sigma / sqrt 3 along random directions (a third of the
// variance), a little less where the noise lengthens the edges; nothing for no noise.
TEST(GaussianNoise, ItsPartAlongTheNormalsIsWhatTheFiltersRead) {
  const test::ArrayMesh s = test::sphere(4);
  EXPECT_EQ(noise_along_normals(s.positions, s.positions, s.faces), 0.0);
  const double lengthened = [&] {
    const Positions noisy = add_gaussian_noise(s.positions, s.faces, 10, NoiseDirection::Isotropic, 3);
    return mean_edge_length(noisy, s.faces) / mean_edge_length(s.positions, s.faces);
  }();
  EXPECT_GT(lengthened, 1.0);
  const struct {
    NoiseDirection direction;
    double expected;
  } cases[] = {{NoiseDirection::Normal, 0.1}, {NoiseDirection::Isotropic, 0.1 / lengthened},
               {NoiseDirection::Random, 0.1 / std::sqrt(3.0)}};
  for (const auto& c : cases) {
    const Positions noisy = add_gaussian_noise(s.positions, s.faces, 10, c.direction, 3);
    EXPECT_NEAR(noise_along_normals(s.positions, noisy, s.faces), c.expected, 0.05 * c.expected)
        << static_cast<int>(c.direction);
  }
}

// Impulsive noise: about the given share of the vertices moves, each as the full noise would move
// it; the others stay to the bit. A share of 1 is the Gaussian noise of old.
TEST(GaussianNoise, ImpulsiveNoiseMovesAShareOfTheVertices) {
  const test::ArrayMesh s = test::sphere(4);
  for (NoiseDirection d : {NoiseDirection::Normal, NoiseDirection::Random, NoiseDirection::Isotropic}) {
    const Positions all = add_gaussian_noise(s.positions, s.faces, 10, d, 3);
    EXPECT_EQ(add_gaussian_noise(s.positions, s.faces, 10, d, 3, 1.0), all);
    const Positions some = add_gaussian_noise(s.positions, s.faces, 10, d, 3, 0.2);
    int moved = 0;
    for (Eigen::Index v = 0; v < s.positions.rows(); ++v) {
      if (some.row(v) == s.positions.row(v)) continue;
      ++moved;
      EXPECT_EQ(some.row(v), all.row(v)) << v;
    }
    EXPECT_NEAR(moved, 0.2 * s.positions.rows(), 0.03 * s.positions.rows()) << static_cast<int>(d);
  }
}

}  // namespace
}  // namespace hht
