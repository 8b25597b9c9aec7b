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

}  // namespace
}  // namespace hht
