#include "evaluation/gaussian_noise.h"
#include "filters/spectral_mesh_filter.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <set>

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

// The filter's result, composed here from the stages by hand: the cycle (seed + 7919 k for the
// k-th), G read in cycle order, EMD and spectra per component, the band's gain (or the coarsest
// IMFs), vertices off the cycle changed by the one-ring mean of their neighbours' change, the
// average over cycles, the least-squares rebuild. A break in the wiring (band, gain, seeds,
// mapping back, averaging) makes the two differ.
Eigen::VectorXd composed_signal(const test::ArrayMesh& m, const SpectralMeshFilterOptions& o) {
  MeanCurvature h;
  std::string error;
  EXPECT_TRUE(mean_curvature(m.positions, m.faces, h, error)) << error;
  const Eigen::VectorXd& g = h.signal;
  std::vector<std::set<int>> ring(m.vertices());
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) ring[m.faces(f, k)].insert({m.faces(f, (k + 1) % 3), m.faces(f, (k + 2) % 3)});
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(m.vertices());
  for (int k = 0; k < o.cycles; ++k) {
    CycleOptions seeded = o.cycle;
    seeded.seed = o.cycle.seed + 7919 * k;
    HamiltonianCycle cycle;
    EXPECT_TRUE(hamiltonian_cycle(m.faces, m.vertices(), seeded, cycle, error)) << error;
    Eigen::VectorXd change = Eigen::VectorXd::Zero(m.vertices());
    for (int s = 0; s < cycle.components; ++s) {
      std::vector<double> signal;
      for (int i = cycle.segment_begin[s]; i < cycle.segment_begin[s + 1]; ++i) signal.push_back(g[cycle.order[i]]);
      const EmdResult e = emd(signal, o.emd);
      const std::vector<double> out = o.keep_coarsest ? keep_coarsest(e, o.coarsest)
                                                      : filter_by_frequency(e, hilbert_spectra(e.imfs, SignalBoundary::Periodic),
                                                                            o.band, o.gain);
      for (size_t j = 0; j < signal.size(); ++j) change[cycle.order[cycle.segment_begin[s] + j]] = out[j] - signal[j];
    }
    for (int v = 0; v < m.vertices(); ++v) {
      if (cycle.position[v] >= 0) continue;
      double mean = 0;
      int count = 0;
      for (int u : ring[v])
        if (cycle.position[u] >= 0) {
          mean += change[u];
          ++count;
        }
      if (count) change[v] = mean / count;
    }
    sum += g + change;
  }
  return sum / o.cycles;
}

void expect_composed_result(const test::ArrayMesh& m, const SpectralMeshFilterOptions& o) {
  SpectralMeshFilterReport report;
  const Positions result = run(m.positions, m.faces, o, &report);
  const Eigen::VectorXd expected = composed_signal(m, o);
  MeanCurvature h;
  std::string error;
  ASSERT_TRUE(mean_curvature(m.positions, m.faces, h, error));
  const double change_rms = std::sqrt((expected - h.signal).squaredNorm() / m.vertices());
  EXPECT_GT(change_rms, 1e-3 * h.signal.cwiseAbs().maxCoeff()) << "the options must change the signal";
  EXPECT_NEAR(report.signal_change_rms, change_rms, 1e-9 * change_rms);
  Positions rebuilt;
  ReconstructionReport rebuild;
  ASSERT_TRUE(reconstruct_positions(m.positions, m.faces, h, expected, o.reconstruction, rebuilt, rebuild, error)) << error;
  EXPECT_LT((result - rebuilt).rowwise().norm().maxCoeff(), 1e-9 * diagonal(m.positions));
  EXPECT_GT((result - m.positions).rowwise().norm().maxCoeff(), 1e-4 * diagonal(m.positions));
}

TEST(SpectralMeshFilter, EveryBandAndGainIsTheComposedPipeline) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const FrequencyBand bands[] = {{0.1, 0.5, false}, {0.0, 0.02, false}, {0.02, 0.1, false}, {0.02, 0.1, true}};
  for (const FrequencyBand& band : bands) {
    for (double gain : {0.0, 2.0}) {
      SCOPED_TRACE(testing::Message() << band.low << " " << band.high << " " << band.outside << " gain " << gain);
      SpectralMeshFilterOptions o;
      o.band = band;
      o.gain = gain;
      expect_composed_result(m, o);
    }
  }
}

TEST(SpectralMeshFilter, CyclesSeedsAndCoarsestAreTheComposedPipeline) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  SpectralMeshFilterOptions o;
  o.cycles = 3;
  o.cycle.seed = 5;
  o.gain = 0.5;
  o.emd.max_imfs = 3;
  o.reconstruction.lambda = 0.1;
  expect_composed_result(m, o);
  SpectralMeshFilterOptions coarse;
  coarse.keep_coarsest = true;
  for (int k : {0, 2}) {
    coarse.coarsest = k;
    expect_composed_result(m, coarse);
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
  o.gain = 0.5;
  o.band = {0.05, 0.5, false};
  SpectralMeshFilterReport report;
  run(m.positions, m.faces, o, &report);
  EXPECT_EQ(report.cycle.components, 2);
  expect_composed_result(m, o);
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

// Faces of no area (libcgal-demo's mpi.off, polygons of up to ten sides, leaves six once MeshLab
// triangulates it; here a sphere with six made so) give cotangent weights that make the rebuild's
// system near singular. The enhancement fails there, and its message names the cause the user can
// remove.
TEST(SpectralMeshFilter, NamesTheDegenerateFacesThatStallTheRebuild) {
  test::ArrayMesh m = test::sphere(3);
  // Faces of no area: a few vertices moved onto the midpoints of an opposite edge.
  for (Eigen::Index f : {0, 40, 80, 120, 160, 200}) {
    const int c = m.faces(f, 2);
    m.positions.row(c) = 0.5 * (m.positions.row(m.faces(f, 0)) + m.positions.row(m.faces(f, 1)));
  }
  SpectralMeshFilterOptions o;  // enhance.mlx
  o.gain = 2;
  o.reconstruction.lambda = 0.1;
  Positions r;
  SpectralMeshFilterReport report;
  std::string error;
  ASSERT_FALSE(spectral_mesh_filter(m.positions, m.faces, o, r, report, error));
  EXPECT_NE(error.find("conjugate gradients stopped"), std::string::npos) << error;
  EXPECT_NE(error.find("degenerate faces"), std::string::npos) << error;
  EXPECT_NE(error.find("Remove Zero Area Faces"), std::string::npos) << error;
  // A well-shaped mesh whose solve stalls (too few iterations allowed) gets no such hint.
  const test::ArrayMesh sphere = test::sphere(3);
  o.reconstruction.max_iterations = 1;
  o.reconstruction.max_error = 1e-14;
  ASSERT_FALSE(spectral_mesh_filter(sphere.positions, sphere.faces, o, r, report, error));
  EXPECT_NE(error.find("conjugate gradients stopped"), std::string::npos) << error;
  EXPECT_EQ(error.find("degenerate faces"), std::string::npos) << error;
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
