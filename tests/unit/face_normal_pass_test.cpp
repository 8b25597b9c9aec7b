#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "reconstruction/face_normal_pass.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

// Noise along the normals of a fine sphere: one pass lowers the normal error by a third or more
// and moves the vertices less than the noise did.
TEST(FaceNormalPass, LowersTheNormalErrorOfANoisySphere) {
  const test::ArrayMesh s = test::sphere(4);
  const Positions noisy = add_gaussian_noise(s.positions, s.faces, 10, NoiseDirection::Normal, 9);
  const Positions passed = face_normal_pass(noisy, s.faces);
  const double before = mean_face_normal_error_degrees(noisy, s.positions, s.faces);
  EXPECT_LT(mean_face_normal_error_degrees(passed, s.positions, s.faces), 0.67 * before);
  const double noise_rms = std::sqrt((noisy - s.positions).rowwise().squaredNorm().mean());
  EXPECT_LT(std::sqrt((passed - noisy).rowwise().squaredNorm().mean()), noise_rms);
}

// A plane is a fixed point: every face's neighbours share its normal.
TEST(FaceNormalPass, LeavesAPlaneAsItIs) {
  Positions p(9, 3);
  for (int i = 0; i < 9; ++i) p.row(i) << i % 3, 0.7 * (i / 3) + 0.1 * (i % 2), 2.0;
  Faces f(8, 3);
  int r = 0;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      const int a = 3 * y + x;
      f.row(r++) << a, a + 1, a + 4;
      f.row(r++) << a, a + 4, a + 3;
    }
  EXPECT_LT((face_normal_pass(p, f) - p).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace hht
