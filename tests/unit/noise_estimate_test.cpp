#include "evaluation/gaussian_noise.h"
#include "signal/noise_estimate.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace hht {
namespace {

NoiseEstimate estimate(const Positions& p, const Faces& f) {
  HamiltonianCycle cycle;
  std::string error;
  EXPECT_TRUE(hamiltonian_cycle(f, static_cast<int>(p.rows()), {}, cycle, error)) << error;
  NoiseEstimate out;
  EXPECT_TRUE(estimate_noise(p, f, cycle, {}, out, error)) << error;
  return out;
}

double mad_sigma(std::vector<double> x) {
  for (double& v : x) v = std::abs(v);
  std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
  return x[x.size() / 2] / 0.6745;
}

// A strip three vertices wide has one interior vertex a column: its estimate rests on those alone,
// a few dozen on a short strip (which the filters then say in their log), hundreds on a long one.
TEST(NoiseEstimate, SaysWhenItRestsOnAFewVertices) {
  for (int length : {40, 400}) {
    const test::ArrayMesh strip = test::grid(length, 3);
    const Positions noisy = add_gaussian_noise(strip.positions, strip.faces, 10, NoiseDirection::Normal, 3);
    const NoiseEstimate e = estimate(noisy, strip.faces);
    EXPECT_GT(e.samples, 0) << length;
    EXPECT_LE(e.samples, length - 2) << length;  // the interior vertices only
    EXPECT_EQ(e.rests_on_few_samples(), e.samples < kFewImfSamples) << length;
    EXPECT_EQ(e.rests_on_few_samples(), length == 40) << length << " " << e.samples;
  }
}

TEST(NoiseEstimate, FirstImfOfWhiteNoiseHoldsMostOfIt) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> gauss(0.0, 2.0);
  std::vector<double> white(50000);
  for (double& x : white) x = gauss(rng);
  EmdOptions o;
  o.max_imfs = 1;
  const EmdResult e = emd(white, o);
  ASSERT_EQ(e.imfs.size(), 1u);
  EXPECT_NEAR(mad_sigma(e.imfs[0]) / 2.0, 0.95, 0.03);
}

TEST(NoiseEstimate, RecoversIsotropicAndNormalNoiseOnASphere) {
  const test::ArrayMesh s = test::sphere(5);
  // within 6% up to 20% noise; at 30% the noisy normals make it about 10% low
  for (double level : {0.05, 0.1, 0.2, 0.3}) {
    const double low = level < 0.25 ? 0.94 : 0.85, high = 1.06;
    const Positions iso = add_gaussian_noise(s.positions, s.faces, 100 * level, NoiseDirection::Isotropic, 3);
    const Positions normal = add_gaussian_noise(s.positions, s.faces, 100 * level, NoiseDirection::Normal, 4);
    for (const Positions* p : {&iso, &normal}) {
      const double e = estimate(*p, s.faces).relative();
      EXPECT_GT(e, low * level) << level;
      EXPECT_LT(e, high * level) << level;
    }
  }
}

TEST(NoiseEstimate, CleanSmoothMeshShowsAlmostNoNoise) {
  const test::ArrayMesh s = test::sphere(5);
  EXPECT_LT(estimate(s.positions, s.faces).relative(), 0.01);
}

TEST(NoiseEstimate, GrowsWithTheNoiseOnAnIrregularScan) {
  // cow: a coarse irregular mesh whose triangulation shows up as a floor of about 0.07 edges
  const test::ArrayMesh cow = test::load_data_mesh("cow");
  double last = estimate(cow.positions, cow.faces).relative();
  EXPECT_LT(last, 0.08);
  for (double level : {0.1, 0.2, 0.3}) {
    const double e = estimate(add_gaussian_noise(cow.positions, cow.faces, 100 * level, NoiseDirection::Isotropic, 9),
                              cow.faces).relative();
    EXPECT_GT(e, last);
    EXPECT_GT(e, 0.8 * level);
    EXPECT_LT(e, std::hypot(level, 0.08) * 1.05);
    last = e;
  }
}

// The flat hinges' cap: a clean CAD export reads as noise-free although its coarse
// triangulation fills the finest IMF (spool 0.13, rotor 0.40 mean edges); light noise on it is
// read nearer the truth; heavier noise, and noise on curved meshes, are left to the IMF.
TEST(NoiseEstimate, FlatHingesCapTheFloorOfCleanCadMeshes) {
  for (const char* name : {"spool", "rotor", "cube-meshed"}) {
    const test::ArrayMesh m = test::load_data_mesh(name);
    const NoiseEstimate clean = estimate(m.positions, m.faces);
    EXPECT_GT(clean.imf_sigma / clean.mean_edge, 0.1) << name;
    EXPECT_TRUE(clean.capped()) << name;
    EXPECT_LT(clean.relative(), 1e-3) << name;
    const Positions light = add_gaussian_noise(m.positions, m.faces, 2, NoiseDirection::Normal, 5);
    const NoiseEstimate l = estimate(light, m.faces);
    EXPECT_TRUE(l.capped()) << name;
    EXPECT_GT(l.relative(), 0.02) << name;
    // a bound: at or above the noise, and about the cap's factor above it at most
    EXPECT_LT(l.relative(), 1.25 * kFlatHingeBound * 0.02) << name;
  }
  for (const char* name : {"cube-meshed", "fandisk", "cow"}) {
    const test::ArrayMesh m = test::load_data_mesh(name);
    for (double level : {0.1, 0.3})
      for (NoiseDirection d : {NoiseDirection::Isotropic, NoiseDirection::Normal}) {
        const NoiseEstimate e = estimate(add_gaussian_noise(m.positions, m.faces, 100 * level, d, 6), m.faces);
        EXPECT_FALSE(e.capped()) << name << " " << level;
        EXPECT_GT(e.hinge_sigma / e.mean_edge, 0.5 * level) << name << " " << level;
      }
  }
}

// A noisy mesh with an exactly flat part (a planar cut, a flattened base) keeps its estimate
// while that part holds a small share of its hinges; the cap needs a tenth of them flat.
TEST(NoiseEstimate, ASmallFlatPartDoesNotCapANoisyMesh) {
  const test::ArrayMesh cow = test::load_data_mesh("cow");
  const Positions noisy = add_gaussian_noise(cow.positions, cow.faces, 10, NoiseDirection::Isotropic, 9);
  const NoiseEstimate plain = estimate(noisy, cow.faces);
  auto flatten_lowest = [&](double share) {  // the lowest vertices put on one plane
    std::vector<double> z(noisy.rows());
    for (Eigen::Index i = 0; i < noisy.rows(); ++i) z[i] = noisy(i, 2);
    std::nth_element(z.begin(), z.begin() + static_cast<long>(share * z.size()), z.end());
    const double cut = z[static_cast<size_t>(share * z.size())];
    Positions out = noisy;
    for (Eigen::Index i = 0; i < out.rows(); ++i) out(i, 2) = std::max(out(i, 2), cut);
    return out;
  };
  const NoiseEstimate cut = estimate(flatten_lowest(0.03), cow.faces);
  EXPECT_FALSE(cut.capped());
  EXPECT_NEAR(cut.relative(), plain.relative(), 0.1 * plain.relative());
  EXPECT_TRUE(estimate(flatten_lowest(0.3), cow.faces).capped());
}

// Clean meshes read their own detail at the edge scale as noise (docs/quality.md: as white as
// noise, so no reading tells the two apart): the filters flag an estimate within that reach. Not
// heavy noise, nor an estimate the flat hinges capped (that one read the noise), nor a noise-free
// reading.
TEST(NoiseEstimate, AReadingWithinACleanMeshsOwnDetailIsFlagged) {
  for (const char* name : {"femur", "bull", "cow"}) {
    const test::ArrayMesh m = test::load_data_mesh(name);
    const NoiseEstimate clean = estimate(m.positions, m.faces);
    EXPECT_GT(clean.relative(), 0.05) << name;  // the floor: no noise at all
    EXPECT_TRUE(may_be_surface_detail(clean)) << name;
    const NoiseEstimate heavy =
        estimate(add_gaussian_noise(m.positions, m.faces, 30, NoiseDirection::Isotropic, 2), m.faces);
    EXPECT_FALSE(may_be_surface_detail(heavy)) << name << " " << heavy.relative();
  }
  const test::ArrayMesh rotor = test::load_data_mesh("rotor");
  const NoiseEstimate capped = estimate(add_gaussian_noise(rotor.positions, rotor.faces, 2, NoiseDirection::Normal, 5), rotor.faces);
  EXPECT_TRUE(capped.capped());
  EXPECT_LT(capped.relative(), kCleanDetailReads);
  EXPECT_FALSE(may_be_surface_detail(capped));
  const test::ArrayMesh spool = test::load_data_mesh("spool");
  EXPECT_FALSE(may_be_surface_detail(estimate(spool.positions, spool.faces)));
}

// The lower bound the log gives (docs/quality.md item 38): what IMF 1 holds beyond the most detail
// IMF 2 allows. Clean coarse meshes read no noise surely there (their estimate is their own detail),
// nor bull and cow at 2% (femur at 2% reads 0-0.43 of its estimate over ten draws); at 10% and
// 20% it reads the noise; on the sphere, which has no detail, it stays below the estimate.
TEST(NoiseEstimate, LowerBoundTellsNoiseFromACoarseMeshsOwnDetail) {
  for (const char* name : {"femur", "bull", "cow"}) {
    const test::ArrayMesh m = test::load_data_mesh(name);
    const NoiseEstimate clean = estimate(m.positions, m.faces);
    EXPECT_GT(clean.relative(), 0.05) << name;  // the floor
    EXPECT_LT(clean.surely_noise_sigma, 0.1 * clean.sigma) << name;
    if (std::string(name) != "femur") {
      const NoiseEstimate light = estimate(add_gaussian_noise(m.positions, m.faces, 2, NoiseDirection::Isotropic, 7), m.faces);
      EXPECT_LT(light.surely_noise_sigma, 0.35 * light.sigma) << name;
    }
    for (double level : {0.1, 0.2}) {
      const NoiseEstimate e = estimate(add_gaussian_noise(m.positions, m.faces, 100 * level, NoiseDirection::Isotropic, 7), m.faces);
      EXPECT_GT(e.surely_noise_sigma, 0.5 * level * e.mean_edge) << name << " " << level;
      EXPECT_LT(e.surely_noise_sigma, 1.2 * level * e.mean_edge) << name << " " << level;
    }
  }
  const test::ArrayMesh s = test::sphere(5);
  for (double level : {0.05, 0.1, 0.2}) {
    const NoiseEstimate e = estimate(add_gaussian_noise(s.positions, s.faces, 100 * level, NoiseDirection::Isotropic, 3), s.faces);
    EXPECT_LE(e.surely_noise_sigma, e.imf_sigma) << level;
    EXPECT_GT(e.surely_noise_sigma, 0.6 * e.sigma) << level;
  }
}

// Impulsive noise (a share of the vertices moved, the others left exactly where they were) keeps
// the untouched flat hinges exactly flat: they read no noise, and capped by them the estimate
// read the mesh as noise-free (fandisk with a tenth of its vertices moved: 0.0000). Read by its
// spikes, the cap is not taken, and the estimate is near the noise's RMS along the normals over
// all vertices, which the MAD of the finest IMF alone reads low on blade (0.05 for 0.15).
TEST(NoiseEstimate, ImpulsiveNoiseIsNotCappedByItsUntouchedFlatHinges) {
  for (const char* name : {"fandisk", "cube-meshed", "turbine", "blade"})
    for (double share : {0.1, 0.3}) {
      const test::ArrayMesh m = test::load_data_mesh(name);
      const Positions noisy = add_gaussian_noise(m.positions, m.faces, 50, NoiseDirection::Normal, 3, share);
      const NoiseEstimate e = estimate(noisy, m.faces);
      const double truth = noise_along_normals(m.positions, noisy, m.faces);
      EXPECT_TRUE(e.impulsive()) << name << " " << share;
      EXPECT_FALSE(e.capped()) << name << " " << share;
      EXPECT_LT(kFlatHingeBound * e.hinge_sigma / e.mean_edge, 0.5 * truth) << name << " " << share;  // the cap would bind
      EXPECT_GT(e.relative(), 0.6 * truth) << name << " " << share;
      EXPECT_LT(e.relative(), 1.4 * truth) << name << " " << share;
      EXPECT_FALSE(may_be_surface_detail(e)) << name << " " << share;
    }
}

TEST(NoiseEstimate, IsScaleFree) {
  const test::ArrayMesh s = test::sphere(4);
  const Positions noisy = add_gaussian_noise(s.positions, s.faces, 20, NoiseDirection::Isotropic, 1);
  const NoiseEstimate a = estimate(noisy, s.faces), b = estimate(noisy * 1e4, s.faces);
  EXPECT_NEAR(a.relative(), b.relative(), 1e-9);
  EXPECT_NEAR(b.sigma, 1e4 * a.sigma, 1e-6 * b.sigma);
}

// Moved 1e3 to 1e5 mean edges from the origin, noisy meshes read as they do at it: the allowance for
// the coordinates' rounding leaves hinges flat by chance there, which must not read as impulsive
// noise (docs/quality.md item 48: elephant at 10%, 4.5e4 mean edges out, read 2.7% of its
// vertices as spikes and `smooth.mlx` moved the vertices by a third of what it does at the origin).
TEST(NoiseEstimate, IsTranslationFree) {
  for (const char* name : {"elephant", "bull", "fandisk"})
    for (double level : {2.0, 10.0, 30.0}) {
      const test::ArrayMesh m = test::load_data_mesh(name);
      const Positions noisy = add_gaussian_noise(m.positions, m.faces, level, NoiseDirection::Isotropic, 7);
      const NoiseEstimate at_origin = estimate(noisy, m.faces);
      const double edge = mean_edge_length(noisy, m.faces);
      for (double away : {1e3, 1e4, 4.5e4, 1e5}) {
        const NoiseEstimate far = estimate(noisy.rowwise() + Eigen::RowVector3d(away * edge, 0.5 * away * edge, 0), m.faces);
        EXPECT_FALSE(far.impulsive()) << name << " " << level << "% at " << away;
        EXPECT_NEAR(far.relative(), at_origin.relative(), 1e-3 * at_origin.relative()) << name << " " << level << "% at " << away;
      }
    }
}

TEST(NoiseEstimate, RefusesBrokenInput) {
  test::ArrayMesh s = test::sphere(2);
  HamiltonianCycle cycle;
  std::string error;
  ASSERT_TRUE(hamiltonian_cycle(s.faces, s.vertices(), {}, cycle, error));
  s.positions(3, 1) = std::nan("");
  NoiseEstimate out;
  EXPECT_FALSE(estimate_noise(s.positions, s.faces, cycle, {}, out, error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;
}

}  // namespace
}  // namespace hht
