#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/guided_normal_denoise.h"
#include "reconstruction/keep_untouched_vertices.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <string>

namespace hht {
namespace {

// Impulsive noise on fandisk, denoised by the guided filter over every vertex: putting back the
// vertices of exactly flat hinges (all of them untouched by the noise) and fitting the others
// lowers the normal error, and the kept vertices are the input's to the bit.
TEST(KeepUntouchedVertices, ImpulsiveNoiseKeepsWhatItLeftAlone) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 50, NoiseDirection::Normal, 7, 0.1);
  Positions denoised;
  std::string error;
  ASSERT_TRUE(guided_normal_denoise(noisy, m.faces, GuidedNormalDenoiseOptions{}, denoised, error)) << error;
  Positions kept = denoised;
  const int count = keep_untouched_vertices(noisy, m.faces, kept);
  EXPECT_GT(count, m.positions.rows() / 2);
  int at_input = 0;
  for (Eigen::Index v = 0; v < kept.rows(); ++v) {
    at_input += kept.row(v) == noisy.row(v);
    if (kept.row(v) == noisy.row(v)) {
      EXPECT_EQ(noisy.row(v), m.positions.row(v)) << v;  // only untouched ones
    }
  }
  EXPECT_GE(at_input, count);
  const double before = mean_face_normal_error_degrees(denoised, m.positions, m.faces);
  const double after = mean_face_normal_error_degrees(kept, m.positions, m.faces);
  EXPECT_LT(after, 0.7 * before) << before << " " << after;
}

// Gaussian noise leaves no hinge flat, and a clean CAD mesh reads no impulsive noise: nothing is
// kept and the result is left as it was.
TEST(KeepUntouchedVertices, NoImpulsiveNoiseNoChange) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  for (const Positions& input : {add_gaussian_noise(m.positions, m.faces, 10, NoiseDirection::Normal, 7), m.positions}) {
    Positions result = input;
    result.col(2).array() += 1e-3;
    const Positions before = result;
    EXPECT_EQ(keep_untouched_vertices(input, m.faces, result), 0);
    EXPECT_EQ(result, before);
  }
}

}  // namespace
}  // namespace hht
