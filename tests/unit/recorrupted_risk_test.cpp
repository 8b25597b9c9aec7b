#include "evaluation/gaussian_noise.h"
#include "mesh/uniform_laplacian.h"
#include "mesh/vertex_adjacency.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/recorrupted_risk.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <vector>

namespace hht {
namespace {

// Five steps of the umbrella operator: a filter that removes most of the noise of a fine sphere.
Positions laplacian_smoothing(Positions p, const Faces& f) {
  const Eigen::SparseMatrix<double> l = uniform_laplacian(vertex_adjacency(f, static_cast<int>(p.rows())));
  for (int s = 0; s < 5; ++s) p -= 0.5 * Positions(l * p);
  return p;
}

double mean_squared_error(const Positions& a, const Positions& b) {
  return (a - b).squaredNorm() / static_cast<double>(a.rows());
}

// The risks differ as the true errors do, and by about as much: each is the true error at the
// copy's noise plus the same constant. Comparing with the noisy data itself (y2 = y) would call
// the identity the better procedure.
TEST(RecorruptedRisk, RanksProceduresAsTheirTrueErrorsDo) {
  const test::ArrayMesh s = test::sphere(4);
  const double edge = mean_edge_length(s.positions, s.faces), sigma = 0.2 * edge;
  const Positions noisy = add_gaussian_noise(s.positions, s.faces, 20, NoiseDirection::Isotropic, 3);
  auto run = [&](const Positions& y1, std::vector<Positions>& outputs) {
    outputs = {y1, laplacian_smoothing(y1, s.faces)};  // the identity and the smoothing
    return true;
  };
  RecorruptedRisks risks;
  ASSERT_TRUE(recorrupted_risks(noisy, sigma, {}, 3, 7, run, risks));
  EXPECT_EQ(risks.draws(), 3);
  const std::vector<double> mean = risks.mean();
  ASSERT_EQ(mean.size(), 2u);
  EXPECT_LT(mean[1], mean[0]);
  // The same difference as the true errors' at the copies' noise, sigma sqrt(1 + a^2), within 10%.
  const Positions noisier =
      add_gaussian_noise(s.positions, s.faces, 20 * std::sqrt(1 + kRecorruptionScale * kRecorruptionScale), NoiseDirection::Isotropic, 4);
  const double true_difference = mean_squared_error(noisier, s.positions) -
                                 mean_squared_error(laplacian_smoothing(noisier, s.faces), s.positions);
  EXPECT_NEAR(mean[0] - mean[1], true_difference, 0.1 * true_difference);
}

// Noise along the normals: the smoothing's slide along the surface is error, which the risk sees
// only if the copies' noise is along the normals too. Isotropic copies carry tangential noise the
// input does not have, and reward the slide that removes it.
TEST(RecorruptedRisk, DrawsTheNoiseInTheInputsShape) {
  const test::ArrayMesh s = test::remove_faces(test::sphere(4), 9);
  const double edge = mean_edge_length(s.positions, s.faces), sigma = 0.2 * edge;
  const Positions noisy = add_gaussian_noise(s.positions, s.faces, 20, NoiseDirection::Normal, 3);
  NoiseShape shape;
  shape.unit_normals = area_weighted_vertex_normals(s.positions, s.faces).rowwise().normalized();
  shape.tangential_share = 0;
  // The smoothing's move, whole (it slides) and along the normals only.
  auto along_normals = [&](const Positions& y, const Positions& smoothed) {
    const Eigen::VectorXd amount = (smoothed - y).cwiseProduct(shape.unit_normals).rowwise().sum();
    return Positions(y + shape.unit_normals.cwiseProduct(amount.replicate(1, 3)));
  };
  auto run = [&](const Positions& y1, std::vector<Positions>& outputs) {
    const Positions slid = laplacian_smoothing(y1, s.faces);
    outputs = {slid, along_normals(y1, slid)};
    return true;
  };
  const Positions noisier =
      add_gaussian_noise(s.positions, s.faces, 20 * std::sqrt(1 + kRecorruptionScale * kRecorruptionScale), NoiseDirection::Normal, 4);
  const Positions slid = laplacian_smoothing(noisier, s.faces);
  const double true_difference = mean_squared_error(slid, s.positions) -
                                 mean_squared_error(along_normals(noisier, slid), s.positions);
  ASSERT_GT(true_difference, 0);
  RecorruptedRisks shaped, isotropic;
  ASSERT_TRUE(recorrupted_risks(noisy, sigma, shape, 3, 7, run, shaped));
  ASSERT_TRUE(recorrupted_risks(noisy, sigma, {}, 3, 7, run, isotropic));
  const std::vector<double> by_shape = shaped.mean(), by_isotropic = isotropic.mean();
  EXPECT_LT(by_isotropic[0] - by_isotropic[1], 0);  // the slide called the better
  EXPECT_NEAR(by_shape[0] - by_shape[1], true_difference, 0.2 * true_difference);
}

TEST(RecorruptedRisk, RefusesWhatItCannotScore) {
  const test::ArrayMesh s = test::sphere(1);
  RecorruptedRisks risks;
  auto run = [](const Positions& y1, std::vector<Positions>& outputs) {
    outputs = {y1, y1};
    return true;
  };
  EXPECT_FALSE(recorrupted_risks(s.positions, 0, {}, 3, 1, run, risks));
  EXPECT_FALSE(recorrupted_risks(s.positions, 0.1, {}, 0, 1, run, risks));
  EXPECT_FALSE(recorrupted_risks(Positions(0, 3), 0.1, {}, 3, 1, run, risks));
  auto failing = [](const Positions&, std::vector<Positions>&) { return false; };
  EXPECT_FALSE(recorrupted_risks(s.positions, 0.1, {}, 3, 1, failing, risks));
  auto none = [](const Positions&, std::vector<Positions>& outputs) {
    outputs.clear();
    return true;
  };
  EXPECT_FALSE(recorrupted_risks(s.positions, 0.1, {}, 3, 1, none, risks));
  int calls = 0;
  auto changing = [&](const Positions& y1, std::vector<Positions>& outputs) {  // a procedure fewer on the second draw
    outputs.assign(++calls == 1 ? 2 : 1, y1);
    return true;
  };
  EXPECT_FALSE(recorrupted_risks(s.positions, 0.1, {}, 3, 1, changing, risks));
}

}  // namespace
}  // namespace hht
