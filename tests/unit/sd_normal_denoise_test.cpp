#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/sd_normal_denoise.h"
#include "mesh/uniform_laplacian.h"
#include "mesh/vertex_adjacency.h"
#include "mesh/vertex_normals.h"
#include "test_meshes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace hht {
namespace {

Positions denoise(const Positions& p, const Faces& f, const SdNormalDenoiseOptions& o = {}) {
  Positions result;
  std::string error;
  EXPECT_TRUE(sd_normal_denoise(p, f, o, result, error)) << error;
  return result;
}

double rms_move(const Positions& a, const Positions& b) { return std::sqrt((a - b).rowwise().squaredNorm().mean()); }

// Uniform Laplacian smoothing (steps of half the umbrella vector) stopped where its RMS move from
// the input equals `move`: the last step is taken only in part, so the moves match exactly.
Positions laplacian_of_equal_move(const Positions& p, const Faces& f, double move) {
  const Eigen::SparseMatrix<double> L = uniform_laplacian(vertex_adjacency(f, static_cast<int>(p.rows())));
  Positions before = p;
  for (int step = 0; step < 10000; ++step) {
    const Positions after = before - 0.5 * Positions(L * before);
    if (rms_move(after, p) < move) {
      before = after;
      continue;
    }
    double lo = 0, hi = 1;
    for (int k = 0; k < 60; ++k) {
      const double t = 0.5 * (lo + hi);
      (rms_move((1 - t) * before + t * after, p) < move ? lo : hi) = t;
    }
    return (1 - lo) * before + lo * after;
  }
  return before;
}

// A mesh with sharp creases and noise along the normals (10 and 20% of the mean edge): the SD
// denoiser's result has a much lower E_a than the input, and than a Laplacian smoothing that
// moves the vertices as far. With the normal filter replaced by the identity the vertex update
// leaves the noisy mesh where it is, and both comparisons fail.
TEST(SdNormalDenoise, DenoisesCreasesBetterThanLaplacianOfEqualMove) {
  for (const char* name : {"cube-meshed", "fandisk"})
    for (double percent : {10.0, 20.0}) {
      SCOPED_TRACE(std::string(name) + " " + std::to_string(percent));
      const test::ArrayMesh m = test::load_data_mesh(name);
      const Positions noisy = add_gaussian_noise(m.positions, m.faces, percent, NoiseDirection::Normal, 7);
      const Positions sd = denoise(noisy, m.faces);
      const double before = mean_face_normal_error_degrees(noisy, m.positions, m.faces);
      const double after = mean_face_normal_error_degrees(sd, m.positions, m.faces);
      const double smoothed =
          mean_face_normal_error_degrees(laplacian_of_equal_move(noisy, m.faces, rms_move(sd, noisy)), m.positions, m.faces);
      EXPECT_LT(after, 0.5 * before);
      EXPECT_LT(after, 0.7 * smoothed);
    }
}

// The filtered normals alone are closer to the clean mesh's than the noisy ones are.
TEST(SdNormalDenoise, FilteredNormalsAreCloserToTheCleanOnes) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 15, NoiseDirection::Normal, 5);
  Positions filtered;
  std::string error;
  ASSERT_TRUE(sd_filter_face_normals(noisy, m.faces, {}, filtered, error)) << error;
  const Positions clean = unit_face_normals(m.positions, m.faces), raw = unit_face_normals(noisy, m.faces);
  auto mean_angle = [&](const Positions& n) {
    double sum = 0;
    for (Eigen::Index f = 0; f < n.rows(); ++f) sum += std::acos(std::clamp(n.row(f).dot(clean.row(f)), -1.0, 1.0));
    return sum / n.rows() * 180 / M_PI;
  };
  EXPECT_LT(mean_angle(filtered), 0.5 * mean_angle(raw));
}

// A tilted plane whose vertices are jittered within it stays that plane: its normals are all
// equal already, so neither step has anything to change.
TEST(SdNormalDenoise, PlaneStaysAPlane) {
  test::ArrayMesh m = test::grid(15, 12);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (Eigen::Index i = 0; i < m.positions.rows(); ++i) m.positions.row(i) += Eigen::RowVector3d(jitter(rng), jitter(rng), 0);
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0.5).normalized())).toRotationMatrix();
  const Positions tilted = m.positions * turn.transpose();
  const Eigen::RowVector3d normal = (turn * Eigen::Vector3d::UnitZ()).transpose();
  const Positions out = denoise(tilted, m.faces);
  EXPECT_LT((out * normal.transpose()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((out - tilted).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(SdNormalDenoise, NoOuterIterationIsTheIdentity) {
  const test::ArrayMesh m = test::sphere(2);
  SdNormalDenoiseOptions none;
  none.outer_iterations = 0;
  EXPECT_EQ(denoise(m.positions, m.faces, none), m.positions);
}

// Broken input and options out of range are refused with a message, the output untouched.
TEST(SdNormalDenoise, RefusesBrokenInputAndLeavesTheOutputAlone) {
  const test::ArrayMesh m = test::sphere(2);
  const Positions sentinel = Positions::Constant(3, 3, 7.0);
  auto refused = [&](const Positions& p, const Faces& f, const SdNormalDenoiseOptions& o) {
    Positions out = sentinel, normals = sentinel;
    std::string error, normals_error;
    const bool denoised = sd_normal_denoise(p, f, o, out, error);
    const bool filtered = sd_filter_face_normals(p, f, o, normals, normals_error);
    return !denoised && !error.empty() && out == sentinel && !filtered && !normals_error.empty() && normals == sentinel;
  };
  EXPECT_TRUE(refused(m.positions, Faces(0, 3), {}));
  Positions nan = m.positions;
  nan(4, 1) = std::nan("");
  EXPECT_TRUE(refused(nan, m.faces, {}));
  Faces out_of_range = m.faces;
  out_of_range(3, 2) = m.vertices() + 5;
  EXPECT_TRUE(refused(m.positions, out_of_range, {}));
  Faces non_manifold(3, 3);  // one edge shared by three faces
  non_manifold << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  EXPECT_TRUE(refused(Positions::Random(5, 3), non_manifold, {}));
  Faces lone(1, 3);  // no neighbouring faces
  lone << 0, 1, 2;
  EXPECT_TRUE(refused(Positions::Random(3, 3), lone, {}));
  for (int k = 0; k < 4; ++k) {
    SdNormalDenoiseOptions bad;
    (k == 0 ? bad.lambda : k == 1 ? bad.eta : k == 2 ? bad.nu : bad.closeness_weight) = 0;
    EXPECT_TRUE(refused(m.positions, m.faces, bad)) << k;
  }
  SdNormalDenoiseOptions no_filter;
  no_filter.filter_iterations = 0;
  EXPECT_TRUE(refused(m.positions, m.faces, no_filter));
}

}  // namespace
}  // namespace hht
