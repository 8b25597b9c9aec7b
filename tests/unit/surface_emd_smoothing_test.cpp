#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/surface_emd_smoothing.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <limits>

namespace hht {
namespace {

TEST(SurfaceEmdSmoothing, TheThirdResidueSmoothsANoisySphere) {
  const test::ArrayMesh m = test::sphere(4);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Random, 7);
  SurfaceEmdSmoothingOptions options;
  Positions result;
  SurfaceEmdSmoothingReport report;
  std::string error;
  ASSERT_TRUE(surface_emd_smoothing(noisy, m.faces, options, result, report, error)) << error;
  EXPECT_EQ(report.residue_used, 3);
  EXPECT_LT(mean_face_normal_error_degrees(result, m.positions, m.faces),
            0.5 * mean_face_normal_error_degrees(noisy, m.positions, m.faces));
  // Residue 0 is the signal itself: the mesh comes back.
  options.residue = 0;
  ASSERT_TRUE(surface_emd_smoothing(noisy, m.faces, options, result, report, error)) << error;
  EXPECT_LT((result - noisy).rowwise().norm().maxCoeff(), 1e-6 * mean_edge_length(noisy, m.faces));
}

TEST(SurfaceEmdSmoothing, FeatureCentricKeepsFandisksCreases) {
  // The paper's Fig. 10b / 10d: the surface EMD's third residue blurs Fandisk; with the feature
  // vertices kept out of the fitting the creases survive.
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Random, 7);
  SurfaceEmdSmoothingOptions plain, centric;
  centric.feature_centric = true;
  Positions a, b;
  SurfaceEmdSmoothingReport ra, rb;
  std::string error;
  ASSERT_TRUE(surface_emd_smoothing(noisy, m.faces, plain, a, ra, error)) << error;
  ASSERT_TRUE(surface_emd_smoothing(noisy, m.faces, centric, b, rb, error)) << error;
  EXPECT_EQ(ra.feature_vertices, 0);
  EXPECT_GT(rb.feature_vertices, 500);
  const double noisy_error = mean_face_normal_error_degrees(noisy, m.positions, m.faces);
  const double plain_error = mean_face_normal_error_degrees(a, m.positions, m.faces);
  const double centric_error = mean_face_normal_error_degrees(b, m.positions, m.faces);
  EXPECT_GT(plain_error, noisy_error);  // "seriously smoothed", as the paper says of [26]
  EXPECT_LT(centric_error, noisy_error);
  EXPECT_LT(centric_error, 0.5 * plain_error);
}

TEST(SurfaceEmdSmoothing, BadInputFailsWithAMessage) {
  const test::ArrayMesh m = test::sphere(2);
  Positions result;
  SurfaceEmdSmoothingReport report;
  std::string error;
  EXPECT_FALSE(surface_emd_smoothing(m.positions, Faces(0, 3), {}, result, report, error));
  EXPECT_FALSE(error.empty());
  Positions broken = m.positions;
  broken(1, 2) = std::numeric_limits<double>::quiet_NaN();
  error.clear();
  EXPECT_FALSE(surface_emd_smoothing(broken, m.faces, {}, result, report, error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace hht
