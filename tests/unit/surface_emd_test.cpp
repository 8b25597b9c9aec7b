#include "filters/surface_emd.h"

#include "mesh/cotangent_laplacian.h"
#include "test_meshes.h"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <random>

namespace {

using hht::SurfaceEmdOptions;
using hht::SurfaceEmdResult;

// A spherical harmonic of degree l: the sum of three sectoral ones about the three axes,
// Re((x + iy)^l) + Re((y + iz)^l) + Re((z + ix)^l), each a harmonic homogeneous polynomial of
// degree l, so their sum is one too and its extrema are spread over the whole sphere.
Eigen::VectorXd harmonic(const hht::Positions& p, int l) {
  Eigen::VectorXd f(p.rows());
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    const Eigen::Vector3d u = p.row(i).normalized();
    using C = std::complex<double>;
    f[i] = std::real(std::pow(C(u.x(), u.y()), l)) + std::real(std::pow(C(u.y(), u.z()), l)) +
           std::real(std::pow(C(u.z(), u.x()), l));
  }
  return f / std::sqrt(f.squaredNorm() / f.size());  // unit RMS
}

double correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const Eigen::VectorXd x = a.array() - a.mean(), y = b.array() - b.mean();
  return x.dot(y) / std::sqrt(x.squaredNorm() * y.squaredNorm());
}

Eigen::VectorXd sum_of(const SurfaceEmdResult& r) {
  Eigen::VectorXd s = r.residue;
  for (const auto& imf : r.imfs) s += imf;
  return s;
}

TEST(SurfaceEmd, SeparatesTwoSphericalHarmonicsOfDistantDegree) {
  const auto sphere = hht::test::sphere(5);  // 10242 vertices
  const Eigen::VectorXd fine = harmonic(sphere.positions, 15), coarse = harmonic(sphere.positions, 3);
  SurfaceEmdOptions options;
  options.min_extrema = 4;  // the degree-3 harmonic has fewer than 15 maxima: let it be an IMF too
  SurfaceEmdResult r;
  std::string error;
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, fine + coarse, options, r, error)) << error;
  ASSERT_GE(r.imfs.size(), 2u);
  EXPECT_GT(correlation(r.imfs[0], fine), 0.95);
  EXPECT_LT(std::abs(correlation(r.imfs[0], coarse)), 0.2);
  EXPECT_GT(correlation(r.imfs[1], coarse), 0.9);
  EXPECT_LT(std::abs(correlation(r.imfs[1], fine)), 0.2);
  // Nothing much is left for further IMFs and the residue.
  const Eigen::VectorXd rest = sum_of(r) - r.imfs[0] - r.imfs[1];
  EXPECT_LT(rest.norm(), 0.3 * coarse.norm());
}

TEST(SurfaceEmd, OneHarmonicIsOneImf) {
  const auto sphere = hht::test::sphere(5);
  const Eigen::VectorXd fine = harmonic(sphere.positions, 15);
  SurfaceEmdResult r;
  std::string error;
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, fine, {}, r, error)) << error;
  ASSERT_GE(r.imfs.size(), 1u);
  EXPECT_GT(correlation(r.imfs[0], fine), 0.98);
  EXPECT_LT((r.imfs[0] - fine).norm(), 0.2 * fine.norm());
}

TEST(SurfaceEmd, ImfsPlusResidueIsTheSignal) {
  const auto mesh = hht::test::load_data_mesh("fandisk");
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::VectorXd s(mesh.vertices());
  for (Eigen::Index i = 0; i < s.size(); ++i) s[i] = noise(rng) + 3.0 * std::sin(20.0 * mesh.positions(i, 0));
  SurfaceEmdResult r;
  std::string error;
  ASSERT_TRUE(hht::surface_emd(mesh.positions, mesh.faces, s, {}, r, error)) << error;
  EXPECT_GE(r.imfs.size(), 3u);
  EXPECT_LT((sum_of(r) - s).cwiseAbs().maxCoeff(), 1e-12 * s.cwiseAbs().maxCoeff());
  // The envelopes were solved both ways, and the stopping rule held: the residue has fewer than
  // 15 maxima or minima, or the IMF before it did not lower the count.
  EXPECT_GT(r.report.factorizations, 0);
  for (int sifts : r.sifts) EXPECT_LE(sifts, 50);
}

TEST(SurfaceEmd, EnvelopesAreTheConstrainedBiharmonicFields) {
  // One sift, checked against the reduced system solved densely:
  // (C M^-1 C)_FF e_F = -(C M^-1 C)_FX s_X, e_X = s_X, for the maxima and for the minima.
  const auto sphere = hht::test::sphere(2);  // 162 vertices
  const int n = sphere.vertices();
  const Eigen::VectorXd s = harmonic(sphere.positions, 4) + 0.3 * sphere.positions.col(0);
  SurfaceEmdOptions options;
  options.max_imfs = 1;
  options.max_sifts = 1;
  options.min_extrema = 1;
  SurfaceEmdResult r;
  std::string error;
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, s, options, r, error)) << error;
  ASSERT_EQ(r.imfs.size(), 1u);
  ASSERT_EQ(r.sifts, std::vector<int>{1});
  EXPECT_EQ(r.report.factorizations, 2);

  const hht::CotangentLaplacian laplacian = hht::extrinsic_cotangent_laplacian(sphere.positions, sphere.faces);
  const Eigen::MatrixXd c = Eigen::MatrixXd(hht::cotangent_matrix(laplacian, n));
  const Eigen::VectorXd& areas = laplacian.areas;
  const Eigen::MatrixXd a = c * areas.cwiseInverse().asDiagonal() * c;
  std::vector<int> offset, neighbours;
  hht::one_ring_adjacency(sphere.faces, n, offset, neighbours);
  hht::SurfaceExtrema extrema;
  hht::surface_extrema(offset, neighbours, s, nullptr, extrema);
  ASSERT_GE(extrema.maxima.size(), 3u);
  auto envelope = [&](const std::vector<int>& fixed) {
    std::vector<unsigned char> is_fixed(n, 0);
    for (int v : fixed) is_fixed[v] = 1;
    std::vector<int> free;
    for (int v = 0; v < n; ++v)
      if (!is_fixed[v]) free.push_back(v);
    Eigen::MatrixXd aff(free.size(), free.size());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free.size());
    for (size_t i = 0; i < free.size(); ++i) {
      for (size_t j = 0; j < free.size(); ++j) aff(i, j) = a(free[i], free[j]);
      for (int x : fixed) rhs[i] -= a(free[i], x) * s[x];
    }
    const Eigen::VectorXd ef = aff.ldlt().solve(rhs);
    Eigen::VectorXd e = s;
    for (size_t i = 0; i < free.size(); ++i) e[free[i]] = ef[i];
    return e;
  };
  const Eigen::VectorXd mean = 0.5 * (envelope(extrema.maxima) + envelope(extrema.minima));
  EXPECT_LT((r.imfs[0] - (s - mean)).cwiseAbs().maxCoeff(), 1e-8 * s.cwiseAbs().maxCoeff());
  // Not the trivial answer: the envelopes differ from the signal off the extrema.
  EXPECT_GT((s - mean).cwiseAbs().maxCoeff(), 0.1 * s.cwiseAbs().maxCoeff());
}

TEST(SurfaceEmd, AConstantOffsetStaysInTheResidue) {
  const auto sphere = hht::test::sphere(4);
  const Eigen::VectorXd fine = harmonic(sphere.positions, 10);
  SurfaceEmdOptions options;
  options.max_imfs = 1;
  SurfaceEmdResult r;
  std::string error;
  const Eigen::VectorXd s = fine.array() + 4.0;  // an offset the envelope mean must remove
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, s, options, r, error)) << error;
  ASSERT_EQ(r.imfs.size(), 1u);
  EXPECT_LT(std::abs(r.imfs[0].mean()), 0.05);
  EXPECT_NEAR(r.residue.mean(), 4.0, 0.05);
}

TEST(SurfaceEmd, ExtremaTiesAreBrokenByIndex) {
  // A strip of 4 vertices 0-1-2-3 (two triangles 0 1 2, 1 3 2) with equal values.
  hht::Faces faces(2, 3);
  faces << 0, 1, 2, 1, 3, 2;
  std::vector<int> offset, neighbours;
  hht::one_ring_adjacency(faces, 4, offset, neighbours);
  hht::SurfaceExtrema e;
  hht::surface_extrema(offset, neighbours, Eigen::VectorXd::Zero(4), nullptr, e);
  EXPECT_EQ(e.maxima, std::vector<int>{3});  // 3 is adjacent to 1 and 2, both lower in index
  EXPECT_EQ(e.minima, std::vector<int>{0});
  const std::vector<unsigned char> excluded{0, 0, 0, 1};
  hht::surface_extrema(offset, neighbours, Eigen::VectorXd::Zero(4), &excluded, e);
  EXPECT_EQ(e.maxima, std::vector<int>{2});
  EXPECT_EQ(e.minima, std::vector<int>{0});
}

TEST(SurfaceEmd, FeatureVerticesStayInTheResidue) {
  const auto sphere = hht::test::sphere(4);
  const Eigen::VectorXd fine = harmonic(sphere.positions, 10);
  std::vector<unsigned char> feature(sphere.vertices(), 0);
  Eigen::VectorXd s = fine;
  for (int v = 0; v < sphere.vertices(); v += 7) {
    feature[v] = 1;
    s[v] += 50.0;  // spikes that would dominate an envelope
  }
  SurfaceEmdOptions options;
  options.feature_vertices = &feature;
  SurfaceEmdResult r;
  std::string error;
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, s, options, r, error)) << error;
  ASSERT_GE(r.imfs.size(), 1u);
  for (int v = 0; v < sphere.vertices(); ++v) {
    if (!feature[v]) continue;
    for (const auto& imf : r.imfs) ASSERT_EQ(imf[v], 0.0);
    ASSERT_EQ(r.residue[v], s[v]);
  }
  // Kept out of the fitting, the spikes do not leak into the IMF elsewhere: it still follows
  // the harmonic on the other vertices.
  std::vector<double> a, b;
  for (int v = 0; v < sphere.vertices(); ++v)
    if (!feature[v]) {
      a.push_back(r.imfs[0][v]);
      b.push_back(fine[v]);
    }
  EXPECT_GT(correlation(Eigen::Map<Eigen::VectorXd>(a.data(), a.size()), Eigen::Map<Eigen::VectorXd>(b.data(), b.size())),
            0.9);
  // Without the mask the spikes are extrema and the same IMF no longer follows the harmonic.
  SurfaceEmdResult plain;
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, s, {}, plain, error)) << error;
  ASSERT_GE(plain.imfs.size(), 1u);
  EXPECT_GT(std::abs(plain.imfs[0][0]), 10.0);
}

TEST(SurfaceEmd, VerticesOfNoFaceKeepTheirValue) {
  auto sphere = hht::test::sphere(4);
  const int n = sphere.vertices();
  sphere.positions.conservativeResize(n + 1, 3);
  sphere.positions.row(n) << 5, 5, 5;
  Eigen::VectorXd s(n + 1);
  s.head(n) = harmonic(sphere.positions.topRows(n), 10);
  s[n] = 7.0;
  SurfaceEmdResult r;
  std::string error;
  ASSERT_TRUE(hht::surface_emd(sphere.positions, sphere.faces, s, {}, r, error)) << error;
  ASSERT_GE(r.imfs.size(), 1u);
  EXPECT_EQ(r.residue[n], 7.0);
  EXPECT_GT(correlation(r.imfs[0].head(n), s.head(n)), 0.95);
}

TEST(SurfaceEmd, LeavesOpenBlasThreadCountAsItFoundIt) {
  // The two envelopes run on two threads with OpenBLAS held to one thread meanwhile; the rest of
  // the process (MeshLab, the reconstruction's factorisation) must get its BLAS threads back.
  auto set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  if (set == nullptr || get == nullptr) GTEST_SKIP() << "the BLAS is not OpenBLAS";
  const int before = get();
  set(2);
  const auto sphere = hht::test::sphere(4);
  SurfaceEmdResult r;
  std::string error;
  const bool ok = hht::surface_emd(sphere.positions, sphere.faces, harmonic(sphere.positions, 10), {}, r, error);
  const int after = get();
  set(before);
  ASSERT_TRUE(ok) << error;
  EXPECT_GE(r.report.factorizations, 2);
  EXPECT_EQ(after, 2);
}

TEST(SurfaceEmd, RefusesBadInput) {
  const auto sphere = hht::test::sphere(3);
  const Eigen::VectorXd s = harmonic(sphere.positions, 5);
  SurfaceEmdResult r;
  std::string error;
  EXPECT_FALSE(hht::surface_emd(sphere.positions, sphere.faces, s.head(10), {}, r, error));
  EXPECT_NE(error.find("values for"), std::string::npos) << error;
  Eigen::VectorXd nan = s;
  nan[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(hht::surface_emd(sphere.positions, sphere.faces, nan, {}, r, error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;
  EXPECT_FALSE(hht::surface_emd(sphere.positions, hht::Faces(0, 3), s, {}, r, error));
  auto broken = sphere.faces;
  broken(0, 1) = sphere.vertices() + 3;
  EXPECT_FALSE(hht::surface_emd(sphere.positions, broken, s, {}, r, error));
  EXPECT_NE(error.find("index no vertex"), std::string::npos) << error;
  broken = sphere.faces;
  broken(0, 1) = broken(0, 0);
  EXPECT_FALSE(hht::surface_emd(sphere.positions, broken, s, {}, r, error));
  auto positions = sphere.positions;
  positions(2, 0) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(hht::surface_emd(positions, sphere.faces, s, {}, r, error));
  const std::vector<unsigned char> short_mask(5, 0);
  SurfaceEmdOptions options;
  options.feature_vertices = &short_mask;
  EXPECT_FALSE(hht::surface_emd(sphere.positions, sphere.faces, s, options, r, error));
  EXPECT_NE(error.find("feature mask"), std::string::npos) << error;
}

}  // namespace
