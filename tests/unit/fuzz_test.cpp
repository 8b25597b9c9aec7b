// Every entry point of the library on random broken meshes from a fixed seed: random points and
// faces, heavily noisy surfaces, deleted faces, duplicated and collapsed vertices, faces repeating a vertex, faces
// given twice and fins (edges of more than two faces), scales from
// 1e-20 to 1e20, NaN and infinite coordinates. Each call must return a finite result or refuse
// with a message, and leave its input as it was (compared bit for bit, NaN included).
//
// The entry points that return positions without an error path (bilateral, non-local means,
// noise, the comparison metrics) are called, as the plugin calls them, only on meshes that
// check_triangle_mesh accepts; the others get every mesh.
#include "cycle/cycle_decomposition.h"
#include "cycle/hamiltonian_cycle.h"
#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/bilateral_denoise.h"
#include "filters/feature_preserving_denoise.h"
#include "filters/guided_normal_denoise.h"
#include "filters/l0_denoise.h"
#include "filters/sd_normal_denoise.h"
#include "filters/noise_adaptive_smoothing.h"
#include "filters/nonlocal_means_denoise.h"
#include "filters/spectral_mesh_filter.h"
#include "filters/surface_emd.h"
#include "filters/surface_emd_smoothing.h"
#include "mesh/filter_input.h"
#include "mesh/mean_curvature.h"
#include "mesh/mesh_checks.h"
#include "mesh/sharp_features.h"
#include "signal/noise_estimate.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>
#include <random>

namespace hht::test {
namespace {

constexpr unsigned kSeed = 20261123;
constexpr int kMeshes = 300;

struct FuzzMesh {
  std::string how;  // what was done to it, for the failure message
  ArrayMesh mesh;
};

ArrayMesh wavy_grid(int nx, int ny) {
  ArrayMesh m = grid(nx, ny);
  for (Eigen::Index v = 0; v < m.positions.rows(); ++v) m.positions(v, 2) = 0.1 * std::sin(m.positions(v, 0) + 2.0 * m.positions(v, 1));
  return m;
}

// Random points and random faces (indices in range, anything else goes).
ArrayMesh soup(std::mt19937& rng) {
  std::uniform_int_distribution<int> count(3, 60);
  ArrayMesh m;
  const int n = count(rng);
  m.positions.resize(n, 3);
  for (Eigen::Index i = 0; i < m.positions.size(); ++i) m.positions.data()[i] = std::uniform_real_distribution<double>(-1, 1)(rng);
  m.faces.resize(count(rng) - 3, 3);
  std::uniform_int_distribution<int> vertex(0, n - 1);
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f) m.faces.row(f) << vertex(rng), vertex(rng), vertex(rng);
  return m;
}

ArrayMesh keep_faces(const ArrayMesh& m, const std::vector<bool>& keep) {
  ArrayMesh out{m.positions, Faces(std::count(keep.begin(), keep.end(), true), 3)};
  Eigen::Index f = 0;
  for (Eigen::Index i = 0; i < m.faces.rows(); ++i)
    if (keep[i]) out.faces.row(f++) = m.faces.row(i);
  return out;
}

FuzzMesh random_mesh(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  FuzzMesh fm;
  const int base = std::uniform_int_distribution<int>(0, 5)(rng);
  switch (base) {
    case 0: fm.mesh = sphere(2); fm.how = "sphere"; break;
    case 1: fm.mesh = torus(1, 0.4, 14, 8); fm.how = "torus"; break;
    case 2: fm.mesh = wavy_grid(9, 7); fm.how = "grid"; break;
    case 3: fm.mesh = disjoint_union(sphere(1), torus(1, 0.3, 10, 6)); fm.how = "two components"; break;
    case 4:  // heavy noise: the denoiser's untangling and its trial refinement (kCreaseRevealNoise) run
      fm.mesh = sphere(3);
      fm.mesh.positions = add_gaussian_noise(fm.mesh.positions, fm.mesh.faces, 40, NoiseDirection::Isotropic, rng());
      fm.how = "sphere, 40% noise";
      break;
    default: fm.mesh = soup(rng); fm.how = "random soup"; break;
  }
  ArrayMesh& m = fm.mesh;
  std::uniform_int_distribution<int> vertex(0, m.vertices() - 1);
  if (unit(rng) < 0.4 && m.faces.rows() > 1) {  // random deletions
    const double share = 0.3 * unit(rng);
    std::vector<bool> keep(m.faces.rows());
    for (auto&& k : keep) k = unit(rng) >= share;
    m = keep_faces(m, keep);
    fm.how += ", faces deleted";
  }
  if (unit(rng) < 0.3 && m.faces.rows() > 0) {  // a vertex duplicated, some of its faces moved to the copy
    const int v = vertex(rng), copy = m.vertices();
    m.positions.conservativeResize(copy + 1, 3);
    m.positions.row(copy) = m.positions.row(v);
    for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (m.faces(f, k) == v && unit(rng) < 0.5) m.faces(f, k) = copy;
    fm.how += ", vertex duplicated";
  }
  if (unit(rng) < 0.3 && m.faces.rows() > 0) {  // collapsed: some face's corners moved onto one point
    const Eigen::Index f = std::uniform_int_distribution<Eigen::Index>(0, m.faces.rows() - 1)(rng);
    m.positions.row(m.faces(f, 1)) = m.positions.row(m.faces(f, 0));
    if (unit(rng) < 0.5) m.positions.row(m.faces(f, 2)) = m.positions.row(m.faces(f, 0));
    fm.how += ", vertices collapsed";
  }
  if (unit(rng) < 0.15 && m.faces.rows() > 0) {  // a face repeating a vertex
    const Eigen::Index f = std::uniform_int_distribution<Eigen::Index>(0, m.faces.rows() - 1)(rng);
    m.faces(f, 2) = m.faces(f, 0);
    fm.how += ", repeated index";
  }
  const double exponent = std::uniform_real_distribution<double>(-20, 20)(rng);
  m.positions *= std::pow(10.0, exponent);
  fm.how += ", scale 1e" + std::to_string(static_cast<int>(std::round(exponent)));
  if (unit(rng) < 0.15) {
    const double bad = unit(rng) < 0.7 ? std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::infinity();
    m.positions(std::uniform_int_distribution<int>(0, m.vertices() - 1)(rng), std::uniform_int_distribution<int>(0, 2)(rng)) = bad;
    fm.how += std::isnan(bad) ? ", a NaN" : ", an Inf";
  }
  return fm;
}

// Edges of more than two faces (docs/quality.md item 44): some faces given twice (half of them
// reversed), or a fin face on one edge.
void add_crowded_edges(FuzzMesh& fm, std::mt19937& rng) {
  ArrayMesh& m = fm.mesh;
  std::uniform_real_distribution<double> unit(0, 1);
  if (m.faces.rows() == 0 || unit(rng) >= 0.4) return;
  std::uniform_int_distribution<Eigen::Index> face(0, m.faces.rows() - 1);
  const Eigen::Index f = face(rng);
  if (unit(rng) < 0.5) {
    const int repeats = std::uniform_int_distribution<int>(1, 5)(rng);
    for (int k = 0; k < repeats; ++k) {
      m.faces.conservativeResize(m.faces.rows() + 1, 3);
      m.faces.row(m.faces.rows() - 1) = m.faces.row(k == 0 ? f : face(rng));
      if (unit(rng) < 0.5) std::swap(m.faces(m.faces.rows() - 1, 1), m.faces(m.faces.rows() - 1, 2));
    }
    fm.how += ", faces given twice";
  } else {
    const int a = m.faces(f, 0), b = m.faces(f, 1), tip = m.vertices();
    m.positions.conservativeResize(tip + 1, 3);
    m.positions.row(tip) = m.positions.row(a) + m.positions.row(b) - m.positions.row(m.faces(f, 2));
    m.faces.conservativeResize(m.faces.rows() + 1, 3);
    m.faces.row(m.faces.rows() - 1) << a, b, tip;
    fm.how += ", a fin";
  }
}

const std::vector<FuzzMesh>& fuzz_meshes() {
  static const std::vector<FuzzMesh> meshes = [] {
    std::mt19937 rng(kSeed);
    std::mt19937 crowded(kSeed + 1);  // a stream of its own: the meshes drawn from `rng` stay as they were
    std::vector<FuzzMesh> all;
    for (int i = 0; i < kMeshes; ++i) {
      all.push_back(random_mesh(rng));
      add_crowded_edges(all.back(), crowded);
    }
    return all;
  }();
  return meshes;
}

// memcmp, which may not be given the null data() of an empty array.
bool same_bytes(const void* a, const void* b, size_t bytes) { return bytes == 0 || std::memcmp(a, b, bytes) == 0; }

bool same_bits(const ArrayMesh& a, const ArrayMesh& b) {
  return a.positions.rows() == b.positions.rows() && a.faces.rows() == b.faces.rows() &&
         same_bytes(a.positions.data(), b.positions.data(), sizeof(double) * a.positions.size()) &&
         same_bytes(a.faces.data(), b.faces.data(), sizeof(int) * a.faces.size());
}

// What one entry point gave: refused (with `error`), or the arrays it computed.
struct Outcome {
  bool ok = false;
  std::string error;
  std::vector<Eigen::MatrixXd> results;
};

using EntryPoint = std::function<Outcome(const Positions&, const Faces&)>;

struct Case {
  const char* name;
  bool needs_checked_input;  // no error path: the plugin calls it only on meshes check_triangle_mesh accepts
  EntryPoint run;
};

template <class Matrix>
Eigen::MatrixXd as_matrix(const Matrix& m) {
  return m.template cast<double>();
}

Outcome refused_or(bool ok, const std::string& error, std::vector<Eigen::MatrixXd> results) {
  return ok ? Outcome{true, "", std::move(results)} : Outcome{false, error, {}};
}

std::vector<Case> entry_points() {
  return {
      {"MeanCurvature", false,
       [](const Positions& p, const Faces& f) {
         MeanCurvature c;
         std::string e;
         const bool ok = mean_curvature(p, f, c, e);
         return refused_or(ok, e, {c.signal, c.laplacian, c.normals, c.areas});
       }},
      {"MeanCurvatureIntrinsicDelaunay", false,
       [](const Positions& p, const Faces& f) {
         MeanCurvature c;
         std::string e;
         const bool ok = mean_curvature(p, f, c, e, LaplacianTriangles::IntrinsicDelaunay);
         return refused_or(ok, e, {c.signal, c.laplacian, c.normals, c.areas});
       }},
      {"HamiltonianCycle", false,
       [](const Positions& p, const Faces& f) {
         HamiltonianCycle cycle;
         std::string e;
         const bool ok = hamiltonian_cycle(f, static_cast<int>(p.rows()), {}, cycle, e);
         Eigen::VectorXd position(cycle.position.size());
         for (size_t i = 0; i < cycle.position.size(); ++i) position[i] = cycle.position[i];
         return refused_or(ok, e, {position});
       }},
      {"HilbertSpectra", false,
       [](const Positions& p, const Faces& f) {
         MeanCurvature c;
         HamiltonianCycle cycle;
         CycleDecomposition d;
         std::string e;
         if (!mean_curvature(p, f, c, e) || !hamiltonian_cycle(f, static_cast<int>(p.rows()), {}, cycle, e) ||
             !decompose_along_cycle(cycle, c.signal, {}, d, e))
           return Outcome{false, e, {}};
         compute_spectra(d);
         std::vector<Eigen::MatrixXd> results;
         for (auto what : {CycleQuantity::Imf, CycleQuantity::Amplitude, CycleQuantity::Frequency, CycleQuantity::Phase,
                           CycleQuantity::Residue})
           results.push_back(quantity_on_vertices(cycle, d, what, 0, f));
         return Outcome{true, "", results};
       }},
      {"NoiseEstimate", false,
       [](const Positions& p, const Faces& f) {
         HamiltonianCycle cycle;
         NoiseEstimate n;
         std::string e;
         const bool ok = hamiltonian_cycle(f, static_cast<int>(p.rows()), {}, cycle, e) &&
                         estimate_noise(p, f, cycle, {}, n, e);
         return refused_or(ok, e, {Eigen::MatrixXd::Constant(1, 1, n.sigma)});
       }},
      {"SpectralFilterSmooth", false,
       [](const Positions& p, const Faces& f) {
         SpectralMeshFilterOptions o;
         SpectralMeshFilterReport r;
         Positions out;
         std::string e;
         const bool ok = spectral_mesh_filter(p, f, o, out, r, e);
         return refused_or(ok, e, {out});
       }},
      {"SpectralFilterEnhance", false,
       [](const Positions& p, const Faces& f) {
         SpectralMeshFilterOptions o;
         o.gain = 3;
         o.cycles = 2;
         SpectralMeshFilterReport r;
         Positions out;
         std::string e;
         const bool ok = spectral_mesh_filter(p, f, o, out, r, e);
         return refused_or(ok, e, {out});
       }},
      {"AdaptiveSmooth", false,
       [](const Positions& p, const Faces& f) {
         NoiseAdaptiveSmoothingReport r;
         Positions out;
         std::string e;
         const bool ok = noise_adaptive_smooth(p, f, {}, out, r, e);
         return refused_or(ok, e, {out});
       }},
      {"FeaturePreservingDenoise", false,
       [](const Positions& p, const Faces& f) {
         DenoiseReport r;
         Positions out;
         std::string e;
         const bool ok = feature_preserving_denoise(p, f, {}, out, r, e);
         return refused_or(ok, e, {out});
       }},
      {"FeaturePreservingDenoisePaperStage", false,
       [](const Positions& p, const Faces& f) {
         DenoiseOptions o;
         o.paper_stage = true;
         o.noise = 0.1;
         DenoiseReport r;
         Positions out;
         std::string e;
         const bool ok = feature_preserving_denoise(p, f, o, out, r, e);
         return refused_or(ok, e, {out});
       }},
      {"GuidedNormalDenoise", false,
       [](const Positions& p, const Faces& f) {
         GuidedNormalDenoiseOptions o;
         o.stand_up_turned_faces = true;  // as guided_denoise.mlx
         Positions out;
         std::string e;
         const bool ok = guided_normal_denoise(p, f, o, out, e);
         return refused_or(ok, e, {out});
       }},
      {"BilateralNormalDenoise", false,
       [](const Positions& p, const Faces& f) {
         GuidedNormalDenoiseOptions o;
         o.stand_up_turned_faces = true;  // as bilateral_normal_denoise.mlx
         o.guidance = NormalGuidance::OwnNormal;
         Positions out;
         std::string e;
         const bool ok = guided_normal_denoise(p, f, o, out, e);
         return refused_or(ok, e, {out});
       }},
      {"L0Denoise", false,
       [](const Positions& p, const Faces& f) {
         L0DenoiseOptions o;
         o.dihedral_mean = DihedralMean::Unsigned;  // the signed mean refuses meshes facing inwards, which the fuzz makes
         Positions out;
         std::string e;
         const bool ok = l0_denoise(p, f, o, out, e);
         return refused_or(ok, e, {out});
       }},
      {"SdNormalDenoise", false,
       [](const Positions& p, const Faces& f) {
         Positions out;
         std::string e;
         const bool ok = sd_normal_denoise(p, f, {}, out, e);
         return refused_or(ok, e, {out});
       }},
      {"SharpFeatures", false,
       [](const Positions& p, const Faces& f) {
         std::vector<FeatureType> type;
         std::string e;
         const bool ok = detect_sharp_features(p, f, {}, type, e);
         return refused_or(ok, e, {});
       }},
      {"SurfaceEmd", false,
       [](const Positions& p, const Faces& f) {
         MeanCurvature c;
         SurfaceEmdResult d;
         std::string e;
         if (!mean_curvature(p, f, c, e) || !surface_emd(p, f, c.signal, {}, d, e)) return Outcome{false, e, {}};
         std::vector<Eigen::MatrixXd> results(d.imfs.begin(), d.imfs.end());
         results.push_back(d.residue);
         return Outcome{true, "", results};
       }},
      {"SurfaceEmdSmoothing", false,
       [](const Positions& p, const Faces& f) {
         SurfaceEmdSmoothingReport r;
         Positions out;
         std::string e;
         const bool ok = surface_emd_smoothing(p, f, {}, out, r, e);
         return refused_or(ok, e, {out});
       }},
      {"FeatureCentricSurfaceEmd", false,
       [](const Positions& p, const Faces& f) {
         SurfaceEmdSmoothingOptions o;
         o.feature_centric = true;
         SurfaceEmdSmoothingReport r;
         Positions out;
         std::string e;
         const bool ok = surface_emd_smoothing(p, f, o, out, r, e);
         return refused_or(ok, e, {out});
       }},
      // The plugin's path (filter_hht/mesh_adapter.h): border vertices on each other merged, faces
      // against their neighbours turned, the smoothing, its result spread back to every copy.
      {"MergedOrientedThenAdaptiveSmooth", true,
       [](const Positions& p, const Faces& f) {
         Positions v = p;
         Faces faces = f;
         InputMap map;
         FilterInputReport input;
         prepare_filter_input(v, faces, true, map, input);
         NoiseAdaptiveSmoothingReport r;
         Positions out;
         std::string e;
         if (!noise_adaptive_smooth(v, faces, {}, out, r, e)) return Outcome{false, e, {}};
         out = to_input_vertices(out, map);
         EXPECT_EQ(out.rows(), p.rows()) << "the result brought back has a row per input vertex";
         return Outcome{true, "", {out}};
       }},
      {"Bilateral", true,
       [](const Positions& p, const Faces& f) { return Outcome{true, "", {bilateral_denoise(p, f, {})}}; }},
      {"NonLocalMeans", true,
       [](const Positions& p, const Faces& f) { return Outcome{true, "", {nonlocal_means_denoise(p, f, {})}}; }},
      {"GaussianNoise", true,
       [](const Positions& p, const Faces& f) {
         return Outcome{true, "", {add_gaussian_noise(p, f, 10, NoiseDirection::Normal, 1),
                                   add_gaussian_noise(p, f, 10, NoiseDirection::Random, 2)}};
       }},
      {"CompareMetrics", true,
       [](const Positions& p, const Faces& f) {
         const Positions other = add_gaussian_noise(p, f, 10, NoiseDirection::Isotropic, 3);
         return Outcome{true, "",
                        {Eigen::MatrixXd::Constant(1, 1, mean_face_normal_error_degrees(other, p, f)),
                         Eigen::MatrixXd::Constant(1, 1, mean_distance_to_reference(other, p, f)),
                         vertex_distance_to_reference(other, p, f), vertex_normal_error_degrees(other, p, f)}};
       }},
  };
}

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class Fuzz : public ::testing::TestWithParam<Case> {};

TEST_P(Fuzz, FiniteResultOrAMessageAndTheInputUntouched) {
  const Case& entry = GetParam();
  int refused = 0, ran = 0;
  for (const FuzzMesh& fm : fuzz_meshes()) {
    std::string why;
    if (entry.needs_checked_input && !check_triangle_mesh(fm.mesh.positions, fm.mesh.faces, why)) continue;
    const ArrayMesh input = fm.mesh;
    const Outcome outcome = entry.run(input.positions, input.faces);
    EXPECT_TRUE(same_bits(input, fm.mesh)) << fm.how << ": the input changed";
    if (!outcome.ok) {
      ++refused;
      EXPECT_FALSE(outcome.error.empty()) << fm.how << ": refused without a message";
      continue;
    }
    ++ran;
    for (size_t k = 0; k < outcome.results.size(); ++k)
      EXPECT_TRUE(outcome.results[k].allFinite()) << fm.how << ": result " << k << " is not finite";
  }
  // The meshes must exercise both paths, or the test proves little.
  EXPECT_GT(ran, kMeshes / 10);
  if (!entry.needs_checked_input) {
    EXPECT_GT(refused, 0);
  }
  std::cout << entry.name << ": " << ran << " results, " << refused << " refusals of " << kMeshes << " meshes\n";
}

// The entry points whose first result is new positions, which scale with the mesh.
std::vector<Case> entry_points_moving_vertices() {
  std::vector<Case> movers;
  for (const Case& c : entry_points()) {
    const std::string name = c.name;
    if (name != "MeanCurvature" && name != "MeanCurvatureIntrinsicDelaunay" && name != "HamiltonianCycle" && name != "HilbertSpectra" && name != "NoiseEstimate" &&
        name != "SharpFeatures" && name != "SurfaceEmd" && name != "CompareMetrics")
      movers.push_back(c);
  }
  return movers;
}

class ExtremeScale : public ::testing::TestWithParam<Case> {};

// Coordinates of 1e30 and 1e-20 (MeshLab holds floats: up to 3.4e38, normal down to 1.2e-38) give
// the result at scale 1, scaled: every stage works in mean-edge units or scales exactly.
TEST_P(ExtremeScale, GivesTheScaledResult) {
  const Case& entry = GetParam();
  ArrayMesh noisy = torus(1, 0.4, 24, 12);
  noisy.positions = add_gaussian_noise(noisy.positions, noisy.faces, 10, NoiseDirection::Random, 7);
  const Outcome reference = entry.run(noisy.positions, noisy.faces);
  ASSERT_TRUE(reference.ok) << reference.error;
  const double diagonal = bounding_box_diagonal(noisy.positions);
  for (double scale : {1e30, 1e-20}) {
    const Outcome scaled = entry.run(noisy.positions * scale, noisy.faces);
    ASSERT_TRUE(scaled.ok) << scale << ": " << scaled.error;
    ASSERT_TRUE(scaled.results[0].allFinite()) << scale;
    const double difference = (scaled.results[0] / scale - reference.results[0]).rowwise().norm().maxCoeff();
    EXPECT_LT(difference, 1e-6 * diagonal) << entry.name << " at scale " << scale;
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(EveryEntryPoint, Fuzz, ::testing::ValuesIn(entry_points()), case_name);
INSTANTIATE_TEST_SUITE_P(EveryEntryPointMovingVertices, ExtremeScale, ::testing::ValuesIn(entry_points_moving_vertices()),
                         case_name);

}  // namespace
}  // namespace hht::test
