#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/nonlocal_means_denoise.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace hht {
namespace {

double diagonal(const Positions& p) { return (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm(); }

// One iteration as the header writes it, by brute force: the vertices a walk reaches (P's one-ring,
// and every vertex inside the ball joined to P through vertices inside it, found by growing that
// set to a fixed point), the annuli's centroids, D^2 over all three annuli, and the weighted
// normal offset. Positions in `p`, radii in mean edge lengths `l`.
Positions nonlocal_means_by_hand(const Positions& p, const Faces& f, const NonLocalMeansOptions& o) {
  const Eigen::Index n = p.rows();
  const double l = mean_edge_length(p, f), eta1 = o.eta1 * l, eta2 = o.eta2 * l, eta3 = o.eta3 * l;
  Eigen::MatrixXi adjacent = Eigen::MatrixXi::Zero(n, n);
  Positions normals = Positions::Zero(n, 3);
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    const Eigen::RowVector3d a = p.row(f(i, 0)), b = p.row(f(i, 1)), c = p.row(f(i, 2));
    for (int k = 0; k < 3; ++k) {
      normals.row(f(i, k)) += (b - a).cross(c - a);
      adjacent(f(i, k), f(i, (k + 1) % 3)) = adjacent(f(i, (k + 1) % 3), f(i, k)) = 1;
    }
  }
  normals.rowwise().normalize();
  auto reached = [&](Eigen::Index v, double radius) {
    std::vector<char> in(n, 0);
    in[v] = 1;
    for (bool grew = true; grew;) {
      grew = false;
      for (Eigen::Index q = 0; q < n; ++q)
        if (!in[q] && (p.row(q) - p.row(v)).norm() < radius)
          for (Eigen::Index r = 0; r < n && !in[q]; ++r)
            if (in[r] && adjacent(q, r)) in[q] = grew = true;
    }
    for (Eigen::Index q = 0; q < n; ++q) in[q] = q != v && (in[q] || adjacent(v, q));
    return in;
  };
  std::vector<std::array<Eigen::RowVector3d, 3>> centroid(n);
  for (Eigen::Index v = 0; v < n; ++v) {
    const std::vector<char> in = reached(v, 3.5 * eta3);
    for (int a = 0; a < 3; ++a) {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      int count = 0;
      for (Eigen::Index q = 0; q < n; ++q) {
        const double x = (p.row(q) - p.row(v)).norm() / eta3;
        if (in[q] && (a == 0 ? x < 1.5 : x >= a + 0.5 && x < a + 1.5)) {
          sum += p.row(q);
          ++count;
        }
      }
      centroid[v][a] = count > 0 ? Eigen::RowVector3d(sum / count) : a > 0 ? centroid[v][a - 1] : Eigen::RowVector3d(p.row(v));
    }
  }
  Positions out = p;
  for (Eigen::Index v = 0; v < n; ++v) {
    const std::vector<char> in = reached(v, eta1);
    const Eigen::RowVector3d nv = normals.row(v);
    double sum_wh = 0, sum_w = 0;
    for (Eigen::Index q = 0; q < n; ++q) {
      if (!in[q]) continue;
      double d2 = 0;
      for (int a = 0; a < 3; ++a) d2 += std::pow(nv.dot(centroid[q][a] - centroid[v][a]), 2);
      const Eigen::RowVector3d d = p.row(q) - p.row(v);
      const double w = std::exp(-d.squaredNorm() / (2 * std::pow(eta1 / 2, 2))) * std::exp(-d2 / (eta2 * eta2));
      sum_wh += w * nv.dot(d);
      sum_w += w;
    }
    out.row(v) += nv * (sum_wh / sum_w);
  }
  return out;
}

// Fails with the neighbourhoods compared on their first annulus only, or the walk not kept within
// the ball, or the spatial kernel's width other than eta1 / 2.
TEST(NonLocalMeans, OneIterationIsTheDocumentedAverage) {
  const test::ArrayMesh m = test::torus(3.0, 1.0, 32, 16);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Random, 3);
  const Positions result = nonlocal_means_denoise(noisy, m.faces, NonLocalMeansOptions{});
  EXPECT_LT((result - nonlocal_means_by_hand(noisy, m.faces, NonLocalMeansOptions{})).rowwise().norm().maxCoeff(),
            1e-12 * diagonal(noisy));
}

TEST(NonLocalMeans, RemovesNormalNoiseOnATorus) {
  const test::ArrayMesh m = test::torus(3.0, 1.0, 96, 48);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Normal, 5);
  const Positions result = nonlocal_means_denoise(noisy, m.faces, NonLocalMeansOptions{});
  EXPECT_LT(mean_face_normal_error_degrees(result, m.positions, m.faces),
            mean_face_normal_error_degrees(noisy, m.positions, m.faces) / 4);
  EXPECT_LT(mean_distance_to_reference(result, m.positions, m.faces),
            0.75 * mean_distance_to_reference(noisy, m.positions, m.faces));
}

TEST(NonLocalMeans, SimilarityWeightsKeepCreases) {
  // Fandisk with 30% noise: the neighbourhood term must do better than the same average
  // without it (eta2 huge: a plain Gaussian average of the normal offsets).
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Normal, 7);
  NonLocalMeansOptions plain;
  plain.eta2 = 1e6;
  const double with = mean_face_normal_error_degrees(nonlocal_means_denoise(noisy, m.faces, {}), m.positions, m.faces);
  const double without = mean_face_normal_error_degrees(nonlocal_means_denoise(noisy, m.faces, plain), m.positions, m.faces);
  const double before = mean_face_normal_error_degrees(noisy, m.positions, m.faces);
  EXPECT_LT(with, 0.5 * before);
  EXPECT_LT(with, 0.9 * without) << "with " << with << " without " << without << " noisy " << before;
}

TEST(NonLocalMeans, ScaledMeshGivesScaledResult) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Random, 9);
  NonLocalMeansOptions o;
  o.iterations = 1;
  const Positions a = nonlocal_means_denoise(noisy, m.faces, o);
  EXPECT_GT((a - noisy).rowwise().norm().maxCoeff(), 1e-3 * diagonal(noisy));
  for (double s : {0.25, 37.0}) {
    const Positions b = nonlocal_means_denoise(noisy * s, m.faces, o);
    EXPECT_LT((b - a * s).rowwise().norm().maxCoeff(), 1e-9 * diagonal(b)) << "scale " << s;
  }
}

TEST(NonLocalMeans, BadInputComesBackUnchanged) {
  const test::ArrayMesh m = test::sphere(2);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Normal, 1);
  EXPECT_EQ(nonlocal_means_denoise(noisy, Faces(0, 3), {}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {3.0, 1.3, 1.0, 0}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {0.0, 1.3, 1.0, 1}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {3.0, -1.0, 1.0, 1}), noisy);
  EXPECT_EQ(nonlocal_means_denoise(noisy, m.faces, {3.0, 1.3, 0.0, 1}), noisy);
  Positions broken = noisy;
  broken(3, 1) = std::numeric_limits<double>::quiet_NaN();
  const Positions back = nonlocal_means_denoise(broken, m.faces, {});
  EXPECT_TRUE(back.row(3).hasNaN());
  EXPECT_EQ(back.topRows(3), noisy.topRows(3));
  Faces bad = m.faces;
  bad(0, 0) = m.vertices();
  EXPECT_EQ(nonlocal_means_denoise(noisy, bad, {}), noisy);
  const Positions point = Positions::Ones(m.vertices(), 3);
  EXPECT_EQ(nonlocal_means_denoise(point, m.faces, {}), point);
}

}  // namespace
}  // namespace hht
