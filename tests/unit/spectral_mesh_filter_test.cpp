#include "gaussian_noise.h"
#include "spectral_mesh_filter.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

double diagonal(const Positions& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

// Mean angle (radians) between the normals of faces sharing an edge: a roughness measure.
double mean_dihedral(const Positions& p, const Faces& f) {
  CornerTable t;
  int inconsistent = 0;
  std::string error;
  build_corner_table(f, static_cast<int>(p.rows()), t, inconsistent, error);
  auto normal = [&](int face) {
    const Eigen::RowVector3d a = p.row(f(face, 0));
    return Eigen::RowVector3d((p.row(f(face, 1)) - a).cross(p.row(f(face, 2)) - a).normalized());
  };
  double sum = 0;
  int count = 0;
  for (int c = 0; c < t.corners(); ++c) {
    if (t.opposite[c] < c) continue;
    sum += std::acos(std::clamp(normal(c / 3).dot(normal(t.opposite[c] / 3)), -1.0, 1.0));
    ++count;
  }
  return sum / count;
}

Positions run(const Positions& p, const Faces& f, const SpectralMeshFilterOptions& o, SpectralMeshFilterReport* out = nullptr) {
  Positions result;
  SpectralMeshFilterReport report;
  std::string error;
  EXPECT_TRUE(spectral_mesh_filter(p, f, o, result, report, error)) << error;
  if (out) *out = report;
  return result;
}

TEST(SpectralMeshFilter, GainOneIsAnExactRoundTrip) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  for (int cycles : {1, 3}) {
    SpectralMeshFilterOptions o;
    o.gain = 1.0;
    o.cycles = cycles;
    const Positions r = run(m.positions, m.faces, o);
    EXPECT_LT((r - m.positions).rowwise().norm().maxCoeff(), 1e-9 * diagonal(m.positions)) << cycles << " cycles";
  }
}

TEST(SpectralMeshFilter, ScaledMeshGivesScaledResult) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  SpectralMeshFilterOptions o;  // default: remove frequencies above 0.1
  const Positions a = run(m.positions, m.faces, o);
  EXPECT_GT((a - m.positions).rowwise().norm().maxCoeff(), 1e-3 * diagonal(m.positions));
  // A power of two scales every intermediate exactly: the same decisions, the same result.
  const Positions b = run(m.positions * 0.25, m.faces, o);
  EXPECT_LT((b - a * 0.25).rowwise().norm().maxCoeff(), 1e-9 * diagonal(b));
  // Any other scale rounds differently, and a sample whose frequency sits on the cut-off can
  // fall on the other side: still the scaled result up to such single-sample decisions.
  const Positions c = run(m.positions * 0.02, m.faces, o);
  EXPECT_LT((c - a * 0.02).rowwise().norm().maxCoeff(), 1e-5 * diagonal(c));
}

TEST(SpectralMeshFilter, LowPassSmoothsAndHighBoostEnhances) {
  const test::ArrayMesh m = test::torus(3.0, 1.0, 96, 48);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Normal, 4);
  SpectralMeshFilterOptions smooth;
  smooth.band = {0.05, 0.5, false};
  smooth.gain = 0.0;
  smooth.cycles = 4;
  smooth.reconstruction.lambda = 0.1;
  SpectralMeshFilterReport report;
  const double rough = mean_dihedral(noisy, m.faces);
  EXPECT_LT(mean_dihedral(run(noisy, m.faces, smooth, &report), m.faces), 0.7 * rough);
  EXPECT_GE(report.imfs.size(), 4u);
  EXPECT_GT(report.signal_change_rms, 0.0);

  SpectralMeshFilterOptions enhance;
  enhance.band = {0.1, 0.5, false};
  enhance.gain = 3.0;
  EXPECT_GT(mean_dihedral(run(noisy, m.faces, enhance), m.faces), 1.3 * rough);
}

TEST(SpectralMeshFilter, CoarseToFineSeries) {
  const test::ArrayMesh m = test::torus(3.0, 1.0, 96, 48);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Normal, 4);
  SpectralMeshFilterOptions o;
  o.keep_coarsest = true;
  o.coarsest = 100;  // more than there are IMFs: everything kept, the input comes back
  const Positions all = run(noisy, m.faces, o);
  EXPECT_LT((all - noisy).rowwise().norm().maxCoeff(), 1e-9 * diagonal(noisy));
  // fewer IMFs kept: smoother, step by step
  o.reconstruction.lambda = 0.1;
  double last = mean_dihedral(noisy, m.faces);
  for (int k : {3, 1}) {
    o.coarsest = k;
    const double rough = mean_dihedral(run(noisy, m.faces, o), m.faces);
    EXPECT_LT(rough, last) << k << " coarsest IMFs";
    last = rough;
  }
}

TEST(SpectralMeshFilter, SeveralComponentsAndHoles) {
  const test::ArrayMesh m = test::disjoint_union(test::remove_faces(test::sphere(4), 97), test::torus(3, 1, 48, 24));
  SpectralMeshFilterOptions o;
  o.gain = 1.0;
  SpectralMeshFilterReport report;
  const Positions r = run(m.positions, m.faces, o, &report);
  EXPECT_EQ(report.cycle.components, 2);
  EXPECT_LT((r - m.positions).rowwise().norm().maxCoeff(), 1e-9 * diagonal(m.positions));
}

TEST(SpectralMeshFilter, BadInputFailsWithAMessage) {
  test::ArrayMesh m = test::sphere(2);
  Positions r;
  SpectralMeshFilterReport report;
  std::string error;
  Faces none(0, 3);
  EXPECT_FALSE(spectral_mesh_filter(m.positions, none, {}, r, report, error));
  EXPECT_NE(error.find("no faces"), std::string::npos);
  m.positions(0, 0) = std::nan("");
  EXPECT_FALSE(spectral_mesh_filter(m.positions, m.faces, {}, r, report, error));
  EXPECT_NE(error.find("NaN"), std::string::npos);
}

TEST(GaussianNoise, MeasuredSigmaMatchesTheRequest) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const double edge = mean_edge_length(m.positions, m.faces);
  for (auto direction : {NoiseDirection::Random, NoiseDirection::Normal}) {
    const Positions noisy = add_gaussian_noise(m.positions, m.faces, 5.0, direction, 7);
    const double rms = std::sqrt((noisy - m.positions).rowwise().squaredNorm().mean());
    EXPECT_NEAR(rms / edge, 0.05, 0.05 * 0.03);  // 6475 samples: RMS within 3%
  }
  EXPECT_TRUE(add_gaussian_noise(m.positions, m.faces, 5.0, NoiseDirection::Random, 7)
                  .isApprox(add_gaussian_noise(m.positions, m.faces, 5.0, NoiseDirection::Random, 7)));
}

}  // namespace
}  // namespace hht
