#include "reconstruction/cutoff_selection.h"

#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/noise_adaptive_smoothing.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/biharmonic_low_pass.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hht {
namespace {

struct Case {
  Positions clean, noisy;  // unit mean edge
  Faces faces;
  VertexAdjacency adjacency;
  Positions normals;       // of the clean surface (they only project)
};

Case noisy_case(const test::ArrayMesh& m, double level, unsigned seed) {
  Case c;
  const double edge = mean_edge_length(m.positions, m.faces);
  c.clean = m.positions / edge;
  c.noisy = add_gaussian_noise(c.clean, m.faces, 100 * level, NoiseDirection::Isotropic, seed);
  c.faces = m.faces;
  c.adjacency = vertex_adjacency(m.faces, static_cast<int>(m.positions.rows()));
  c.normals = area_weighted_vertex_normals(c.clean, m.faces);
  return c;
}

// The risk the selection estimates, measured against the clean surface: the squared edge
// differences of the normal error.
double true_risk(const Case& c, double mu) {
  Positions x;
  BiharmonicLowPassReport report;
  EXPECT_TRUE(biharmonic_low_pass(c.adjacency, c.noisy, mu, 0, 1e-6, x, report));
  Eigen::VectorXd e(x.rows());
  for (Eigen::Index i = 0; i < x.rows(); ++i) e[i] = c.normals.row(i).dot(x.row(i) - c.clean.row(i));
  double risk = 0;
  for (int i = 0; i < c.adjacency.vertices(); ++i)
    for (const int* j = c.adjacency.begin(i); j != c.adjacency.end(i); ++j)
      if (*j > i) risk += std::pow(e[i] - e[*j], 2);
  return risk;
}

// Cross-validation without the noise level picks, among the cut-offs it scored, one whose true
// risk is near the best of them: on a dense smooth surface (the best filter is strong) and on a
// coarse one with detail at the edge scale (much weaker).
TEST(CutoffSelection, NearTheBestCutoffWithoutKnowingTheNoise) {
  const test::ArrayMesh fine = test::sphere(5), coarse = test::load_data_mesh("cow");
  double chosen[2];
  int index = 0;
  for (const test::ArrayMesh* m : {&fine, &coarse}) {
    const Case c = noisy_case(*m, 0.15, 3);
    CutoffSelectionOptions options;
    options.mu_largest = 2;
    options.mu_smallest = 0.1;
    CutoffSelection selection;
    std::string error;
    ASSERT_TRUE(select_cutoff(c.adjacency, c.noisy, c.normals, options, selection, error)) << error;
    ASSERT_GE(selection.curve.size(), 3u);
    double best = HUGE_VAL;
    for (const auto& point : selection.curve) best = std::min(best, true_risk(c, point.mu));
    EXPECT_LT(true_risk(c, selection.mu), 1.15 * best) << index;
    // Nor is it the weakest or the strongest filter of the grid: a real minimum.
    EXPECT_LT(selection.mu, options.mu_largest / 1.2) << index;
    EXPECT_GT(selection.mu, options.mu_smallest * 1.2) << index;
    chosen[index++] = selection.mu;
  }
  EXPECT_LT(chosen[0], 0.7 * chosen[1]);  // the smooth dense surface takes the stronger filter
}

// With the noise known, Stein's unbiased risk picks, among the cut-offs it scored, one whose true
// risk is near the best, at heavy noise and at light noise that the surface's own detail
// outweighs (cow at 2%: there the best cut-off is weaker than the noise law's, and the
// cross-validation's score falls towards the identity).
TEST(CutoffSelection, SteinsRiskFindsTheBestCutoffWhereTheNoiseIsKnown) {
  const test::ArrayMesh cow = test::load_data_mesh("cow");
  for (double level : {0.15, 0.02}) {
    const Case c = noisy_case(cow, level, 3);
    CutoffSelectionOptions options;
    options.mu_largest = 8;
    options.mu_smallest = 0.1;
    options.noise_sigma = level;  // the positions are in mean edges
    CutoffSelection selection;
    std::string error;
    ASSERT_TRUE(select_cutoff(c.adjacency, c.noisy, c.normals, options, selection, error)) << error;
    ASSERT_GE(selection.curve.size(), 3u);
    double best = HUGE_VAL, best_mu = 0;
    for (const auto& point : selection.curve) {
      const double truth = true_risk(c, point.mu);
      if (truth < best) best = truth, best_mu = point.mu;
    }
    EXPECT_LT(true_risk(c, selection.mu), 1.1 * best) << level;
    EXPECT_NEAR(std::log(selection.mu), std::log(best_mu), std::log(1.5)) << level;
  }
}

// Large meshes are scored on patches: the choice stays close to the whole mesh's.
TEST(CutoffSelection, PatchesOfALargeMeshChooseLikeTheWhole) {
  const Case c = noisy_case(test::sphere(5), 0.15, 4);
  CutoffSelectionOptions options;
  options.mu_largest = 2;
  CutoffSelection whole, sampled;
  std::string error;
  ASSERT_TRUE(select_cutoff(c.adjacency, c.noisy, c.normals, options, whole, error)) << error;
  options.sample_vertices = c.adjacency.vertices() / 3;
  ASSERT_TRUE(select_cutoff(c.adjacency, c.noisy, c.normals, options, sampled, error)) << error;
  EXPECT_EQ(whole.sampled_vertices, c.adjacency.vertices());
  EXPECT_LE(sampled.sampled_vertices, options.sample_vertices);
  EXPECT_GT(sampled.sampled_vertices, options.sample_vertices * 9 / 10);
  EXPECT_NEAR(std::log(sampled.mu), std::log(whole.mu), std::log(1.2));
}

// Through the smoothing: on a dense smooth surface the cross-validated cut-off is stronger than
// the noise level's and the normals come out better for it.
TEST(CutoffSelection, StrengthensTheSmoothingOfADenseSmoothSurface) {
  const test::ArrayMesh m = test::sphere(5);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10, NoiseDirection::Isotropic, 8);
  double error_degrees[2];
  double mu[2];
  for (int select = 0; select < 2; ++select) {
    NoiseAdaptiveSmoothingOptions options;
    options.select_cutoff = select == 1;
    NoiseAdaptiveSmoothingReport report;
    Positions out;
    std::string error;
    ASSERT_TRUE(noise_adaptive_smooth(noisy, m.faces, options, out, report, error)) << error;
    EXPECT_EQ(report.cutoff_selected, select == 1);
    error_degrees[select] = mean_face_normal_error_degrees(out, m.positions, m.faces);
    mu[select] = report.mu;
  }
  EXPECT_LT(mu[1], 0.8 * mu[0]);
  EXPECT_LT(error_degrees[1], 0.85 * error_degrees[0]);
}

// The cross-validated cut-off is made kSelectionBias stronger than the score's minimum (its squared
// risk favours weaker filters than the angle error does).
TEST(CutoffSelection, TheSmoothingTakesTheChoiceBiasedStronger) {
  const test::ArrayMesh m = test::sphere(5);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10, NoiseDirection::Isotropic, 8);
  double mu[2];
  for (int biased = 0; biased < 2; ++biased) {
    NoiseAdaptiveSmoothingOptions options;
    if (!biased) options.selection_bias = 1;
    NoiseAdaptiveSmoothingReport report;
    Positions out;
    std::string error;
    ASSERT_TRUE(noise_adaptive_smooth(noisy, m.faces, options, out, report, error)) << error;
    ASSERT_TRUE(report.cutoff_selected);
    mu[biased] = report.mu;
  }
  EXPECT_GT(kSelectionBias, 1.0);
  EXPECT_NEAR(mu[1], mu[0] / kSelectionBias, 1e-9 * mu[0]);
}

}  // namespace
}  // namespace hht
