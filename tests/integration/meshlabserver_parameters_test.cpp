// Every parameter path of every filter through meshlabserver, each run's saved mesh compared
// with the library called with the same options on the same input. MeshLab holds positions,
// quality and parameters in float: the library gets the input rounded to float, float-rounded
// parameter values, and the comparison allows for the float rounding of what was saved.
#include "meshlabserver_harness.h"
#include "test_meshes.h"

#include "filters/bilateral_denoise.h"
#include "cycle/cycle_decomposition.h"
#include "evaluation/denoise_metrics.h"
#include "filters/feature_preserving_denoise.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/mean_curvature.h"
#include "filters/spectral_mesh_filter.h"
#include "filters/guided_normal_denoise.h"
#include "filters/noise_adaptive_smoothing.h"
#include "filters/nonlocal_means_denoise.h"
#include "filters/surface_emd.h"
#include "filters/surface_emd_smoothing.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_off.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

namespace hht::test {
namespace {

namespace fs = std::filesystem;

struct Input {
  Positions positions;  // as MeshLab holds them: rounded to float
  Faces faces;
  double diagonal = 0;
};

Input read_input(const std::string& name) {
  TriMesh m;
  EXPECT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh(name).c_str()), 0);
  Input in;
  mesh_to_arrays(m, in.positions, in.faces);
  in.positions = in.positions.cast<float>().cast<double>();
  in.diagonal = (in.positions.colwise().maxCoeff() - in.positions.colwise().minCoeff()).norm();
  return in;
}

double f(double value) { return static_cast<float>(value); }  // a parameter as MeshLab reads it

Positions saved_positions(const ServerRun& run, Eigen::VectorXd* quality = nullptr) {
  TriMesh m;
  load(run, m);
  Positions p;
  Faces faces;
  mesh_to_arrays(m, p, faces);
  if (quality) {
    quality->resize(m.vn);
    for (int v = 0; v < m.vn; ++v) (*quality)[v] = m.vert[v].Q();
  }
  return p;
}

Eigen::VectorXd saved_quality(const ServerRun& run) {
  Eigen::VectorXd q;
  saved_positions(run, &q);
  return q;
}

ServerRun run_resource(const std::string& input, const std::string& resource_name,
                     const std::vector<std::pair<std::string, std::string>>& overrides, const std::string& tag) {
  return run_meshlabserver(input, chain_scripts(tag, {resource_name}, overrides), tag);
}

void expect_positions(const Positions& saved, const Positions& expected, double diagonal, const std::string& what) {
  ASSERT_EQ(saved.rows(), expected.rows()) << what;
  EXPECT_LT((saved - expected).rowwise().norm().maxCoeff(), 1e-6 * diagonal) << what;
}

void expect_values(const Eigen::VectorXd& saved, const Eigen::VectorXd& expected, const std::string& what) {
  ASSERT_EQ(saved.size(), expected.size()) << what;
  const double scale = std::max(1e-30, expected.cwiseAbs().maxCoeff());
  EXPECT_LT((saved - expected).cwiseAbs().maxCoeff(), 1e-6 * scale) << what;
  EXPECT_GT((expected.array() != 0).count(), expected.size() / 2) << what << ": mostly zeros proves little";
}

// ------------------------------------------------------------------------------ cycle

TEST(MeshlabserverParameters, HamiltonianCycleSeedTriesRepair) {
  struct Case {
    const char* mesh;
    int seed, tries;
    bool repair;
  };
  // Cases where each parameter shows: on bull the seeds leave different numbers of vertices off
  // the cycle, so three tries keep another cycle than one; cow at seed 11 leaves 2 vertices off
  // the cycle unrepaired (the repair attaches both).
  for (const Case c : {Case{"fandisk", 3, 1, true}, Case{"bull", 3, 3, false}, Case{"cow", 11, 1, false}}) {
    const std::string tag = std::string("cycle_") + c.mesh + "_" + std::to_string(c.seed) + "_" + std::to_string(c.tries) +
                            "_" + std::to_string(c.repair);
    const Input in = read_input(c.mesh);
    const ServerRun run = run_resource(data_mesh(c.mesh), "hamiltonian_cycle.mlx",
                                     {{"seed", std::to_string(c.seed)}, {"tries", std::to_string(c.tries)},
                                      {"repair", c.repair ? "true" : "false"}}, tag);
    CycleOptions o;
    o.seed = c.seed;
    o.tries = c.tries;
    o.repair = c.repair;
    HamiltonianCycle cycle;
    std::string error;
    ASSERT_TRUE(hamiltonian_cycle(in.faces, static_cast<int>(in.positions.rows()), o, cycle, error)) << error;
    if (!c.repair) {
      EXPECT_GT(cycle.isolated, 0) << tag << ": the case no longer shows the repair";
    }
    if (c.tries > 1) {
      CycleOptions once = o;
      once.tries = 1;
      HamiltonianCycle first;
      ASSERT_TRUE(hamiltonian_cycle(in.faces, static_cast<int>(in.positions.rows()), once, first, error)) << error;
      EXPECT_NE(first.position, cycle.position) << tag << ": the case no longer shows the tries";
    }
    const Eigen::VectorXd quality = saved_quality(run);
    ASSERT_EQ(quality.size(), in.positions.rows());
    for (Eigen::Index v = 0; v < quality.size(); ++v) ASSERT_EQ(quality[v], cycle.position[v]) << tag << " vertex " << v;
    EXPECT_NE(run.log.find(std::to_string(cycle.isolated) + " isolated"), std::string::npos) << run.log;
  }
}

// The cycle layer, saved as OBJ with its edges, read back edge by edge: the cycle's steps.
TEST(MeshlabserverParameters, CycleLayerEdgesAreTheCycle) {
  const Input in = read_input("fandisk");
  const std::string script = write_script("cycle_layer",
      " <filter name=\"HHT: Hamiltonian Cycle\">\n"
      "  <Param type=\"RichInt\" name=\"seed\" value=\"3\"/>\n"
      "  <Param type=\"RichInt\" name=\"tries\" value=\"1\"/>\n"
      "  <Param type=\"RichBool\" name=\"repair\" value=\"true\"/>\n"
      "  <Param type=\"RichBool\" name=\"addCycleLayer\" value=\"true\"/>\n"
      " </filter>\n"
      " <filter name=\"Change the current layer\">\n"
      "  <Param type=\"RichMesh\" name=\"layer\" value=\"1\"/>\n"
      " </filter>\n");
  const ServerRun run = run_script(MeshLab::V2020, {data_mesh("fandisk")}, script, "cycle_layer", ".obj");
  ASSERT_EQ(run.exit_code, 0) << run.log;
  CycleOptions o;
  o.seed = 3;
  HamiltonianCycle cycle;
  std::string error;
  ASSERT_TRUE(hamiltonian_cycle(in.faces, static_cast<int>(in.positions.rows()), o, cycle, error)) << error;
  const ObjPolyline layer = read_obj_polyline(run.output);
  ASSERT_EQ(layer.vertices.size(), cycle.order.size());
  for (size_t i = 0; i < layer.vertices.size(); ++i)
    ASSERT_LT((layer.vertices[i] - in.positions.row(cycle.order[i])).norm(), 1e-5 * in.diagonal) << "vertex " << i;
  ASSERT_EQ(layer.edges.size(), cycle.order.size());
  for (size_t i = 0; i < layer.edges.size(); ++i) {
    EXPECT_EQ(layer.edges[i].first, static_cast<int>(i));
    EXPECT_EQ(layer.edges[i].second, static_cast<int>((i + 1) % cycle.order.size()));
  }
}

// ------------------------------------------------------------------------------ curvature

TEST(MeshlabserverParameters, CurvatureColourRampClipsTheRequestedPercentile) {
  const Input in = read_input("fandisk");
  MeanCurvature h;
  std::string error;
  ASSERT_TRUE(mean_curvature(in.positions, in.faces, h, error, LaplacianTriangles::IntrinsicDelaunay));  // the script's
  for (int percentile : {2, 20}) {
    TriMesh m;
    load(run_resource(data_mesh("fandisk"), "curvature_signal.mlx", {{"rampPercentile", std::to_string(percentile)}},
                    "ramp_" + std::to_string(percentile)), m);
    Eigen::VectorXd q(m.vn);
    for (int v = 0; v < m.vn; ++v) q[v] = m.vert[v].Q();
    expect_values(q, h.signal, "curvature");
    // every vertex at or below the p-th percentile of G has the ramp's end colour
    int lowest = 0;
    for (int v = 0; v < m.vn; ++v)
      if (q[v] < q[lowest]) lowest = v;
    int saturated = 0;
    for (const auto& v : m.vert) saturated += v.cC() == m.vert[lowest].cC();
    EXPECT_NEAR(saturated, percentile / 100.0 * m.vn, 0.01 * m.vn) << percentile;
  }
}

// ------------------------------------------------------------------------------ spectra

// The library's per-vertex quantity for the spectra filter's options.
Eigen::VectorXd library_quantity(const Input& in, const Eigen::VectorXd& signal, CycleQuantity what, int imf,
                                 const CycleOptions& cycle_options = {}, const EmdOptions& emd_options = {}) {
  HamiltonianCycle cycle;
  CycleDecomposition d;
  std::string error;
  EXPECT_TRUE(hamiltonian_cycle(in.faces, static_cast<int>(in.positions.rows()), cycle_options, cycle, error)) << error;
  EXPECT_TRUE(decompose_along_cycle(cycle, signal, emd_options, d, error)) << error;
  compute_spectra(d);
  return quantity_on_vertices(cycle, d, what, imf, in.faces);
}

TEST(MeshlabserverParameters, HilbertSpectraEveryOutputAndImf) {
  const Input in = read_input("fandisk");
  MeanCurvature h;
  std::string error;
  ASSERT_TRUE(mean_curvature(in.positions, in.faces, h, error));
  const CycleQuantity outputs[] = {CycleQuantity::Imf, CycleQuantity::Amplitude, CycleQuantity::Frequency,
                                   CycleQuantity::Phase, CycleQuantity::Residue};
  for (int output = 0; output < 5; ++output)
    for (int imf : {1, 3}) {
      if (output == 4 && imf == 3) continue;  // the residue has no IMF number
      const std::string tag = "spectra_" + std::to_string(output) + "_" + std::to_string(imf);
      const ServerRun run = run_resource(data_mesh("fandisk"), "hilbert_spectra.mlx",
                                       {{"output", std::to_string(output)}, {"imf", std::to_string(imf)},
                                        {"histogramFile", ""}}, tag);
      expect_values(saved_quality(run), library_quantity(in, h.signal, outputs[output], imf - 1), tag);
    }
}

TEST(MeshlabserverParameters, HilbertSpectraCycleAndEmdOptions) {
  const Input in = read_input("fandisk");
  MeanCurvature h;
  std::string error;
  ASSERT_TRUE(mean_curvature(in.positions, in.faces, h, error));
  CycleOptions c;
  c.seed = 9;
  EmdOptions e;
  e.sd_threshold = f(0.3);
  e.max_sifts = 4;
  e.min_extrema = 40;
  e.max_imfs = 3;
  const ServerRun run = run_resource(data_mesh("fandisk"), "hilbert_spectra.mlx",
                                   {{"output", "4"}, {"seed", "9"}, {"sdThreshold", "0.3"}, {"maxSifts", "4"},
                                    {"minExtrema", "40"}, {"maxImfs", "3"}, {"histogramFile", ""}}, "spectra_options");
  const Eigen::VectorXd expected = library_quantity(in, h.signal, CycleQuantity::Residue, 0, c, e);
  expect_values(saved_quality(run), expected, "residue with options");
  // the options matter: the default residue differs
  EXPECT_GT((expected - library_quantity(in, h.signal, CycleQuantity::Residue, 0)).cwiseAbs().maxCoeff(),
            1e-3 * expected.cwiseAbs().maxCoeff());
}

// The signal is a quality the input file carries (not G): the filter must analyse that.
TEST(MeshlabserverParameters, HilbertSpectraOfAQualityThatIsNotG) {
  const Input in = read_input("fandisk");
  TriMesh m;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh("fandisk").c_str()), 0);
  Eigen::VectorXd signal(m.vn);
  for (int v = 0; v < m.vn; ++v) {
    const auto& p = m.vert[v].cP();
    m.vert[v].Q() = static_cast<float>(std::sin(40.0 * p[0] / in.diagonal) + 0.3 * std::cos(300.0 * p[1] / in.diagonal));
    signal[v] = m.vert[v].Q();
  }
  const std::string input = output_path("fandisk_with_quality.ply");
  ASSERT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, input.c_str(), vcg::tri::io::Mask::IOM_VERTQUALITY, false), 0);
  const ServerRun run = run_resource(input, "hilbert_spectra.mlx",
                                   {{"source", "1"}, {"output", "0"}, {"imf", "2"}, {"histogramFile", ""}}, "spectra_quality");
  expect_values(saved_quality(run), library_quantity(in, signal, CycleQuantity::Imf, 1), "IMF 2 of the quality");
}

TEST(MeshlabserverParameters, HistogramFileAndBins) {
  const Input in = read_input("fandisk");
  MeanCurvature h;
  std::string error;
  ASSERT_TRUE(mean_curvature(in.positions, in.faces, h, error));
  const ServerRun run = run_resource(data_mesh("fandisk"), "hilbert_spectra.mlx",
                                   {{"histogramFile", "histogram.png"}, {"bins", "20"}}, "histogram");
  ASSERT_EQ(run.exit_code, 0) << run.log;
  HamiltonianCycle cycle;
  CycleDecomposition d;
  ASSERT_TRUE(hamiltonian_cycle(in.faces, static_cast<int>(in.positions.rows()), {}, cycle, error));
  ASSERT_TRUE(decompose_along_cycle(cycle, h.signal, {}, d, error));
  compute_spectra(d);
  const auto expected = frequency_distribution(d, 20);
  std::ifstream csv(output_path("histogram.csv"));
  std::string line;
  std::getline(csv, line);  // header
  int row = 0;
  for (; std::getline(csv, line); ++row) {
    std::stringstream cells(line);
    std::string cell;
    std::getline(cells, cell, ',');
    EXPECT_NEAR(std::stod(cell), 0.5 * row / 20, 1e-9);
    std::getline(cells, cell, ',');
    for (size_t k = 0; k < expected.size(); ++k) {
      ASSERT_TRUE(std::getline(cells, cell, ',')) << line;
      EXPECT_NEAR(std::stod(cell), expected[k][row], 1e-4 * (1 + std::abs(expected[k][row]))) << "row " << row << " IMF " << k + 1;
    }
  }
  EXPECT_EQ(row, 20);
  EXPECT_GT(fs::file_size(output_path("histogram.png")), 1000u);
}

// ------------------------------------------------------------------------------ spectral filter

struct FilterCase {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> overrides;  // applied to enhance.mlx
  SpectralMeshFilterOptions options;                            // the same, for the library
};

void PrintTo(const FilterCase& c, std::ostream* os) { *os << c.tag; }

SpectralMeshFilterOptions enhance_script_options() {  // resources/enhance.mlx
  SpectralMeshFilterOptions o;
  o.band = {f(0.1), 0.5, false};
  o.gain = 2;
  o.cycles = 1;
  o.reconstruction.lambda = f(0.1);
  return o;
}

std::vector<FilterCase> filter_cases() {
  std::vector<FilterCase> cases;
  auto add = [&](const std::string& tag, std::vector<std::pair<std::string, std::string>> overrides,
                 const std::function<void(SpectralMeshFilterOptions&)>& set) {
    SpectralMeshFilterOptions o = enhance_script_options();
    overrides.insert(overrides.begin(), {"cycles", "1"});  // a case's own value comes later and wins
    o.cycles = 1;
    set(o);
    cases.push_back({tag, overrides, o});
  };
  add("band0", {{"band", "0"}, {"cutoff", "0.08"}, {"gain", "2.5"}},
      [](auto& o) { o.band = {f(0.08), 0.5, false}; o.gain = 2.5; });
  add("band1", {{"band", "1"}, {"cutoff", "0.03"}, {"gain", "0.5"}},
      [](auto& o) { o.band = {0.0, f(0.03), false}; o.gain = 0.5; });
  add("band2", {{"band", "2"}, {"lowFrequency", "0.02"}, {"highFrequency", "0.12"}, {"gain", "0"}},
      [](auto& o) { o.band = {f(0.02), f(0.12), false}; o.gain = 0; });
  add("band3", {{"band", "3"}, {"lowFrequency", "0.02"}, {"highFrequency", "0.12"}, {"gain", "0.25"}},
      [](auto& o) { o.band = {f(0.02), f(0.12), true}; o.gain = 0.25; });
  add("coarse", {{"coarseToFine", "true"}, {"coarsestImfs", "2"}},
      [](auto& o) { o.keep_coarsest = true; o.coarsest = 2; });
  add("literal", {{"literalTarget", "true"}, {"lambda", "0.05"}},
      [](auto& o) { o.reconstruction.target = ReconstructionTarget::NormalOnly; o.reconstruction.lambda = f(0.05); });
  add("emd", {{"seed", "4"}, {"sdThreshold", "0.2"}, {"maxSifts", "6"}, {"minExtrema", "30"}, {"maxImfs", "4"}},
      [](auto& o) {
        o.cycle.seed = 4;
        o.emd.sd_threshold = f(0.2);
        o.emd.max_sifts = 6;
        o.emd.min_extrema = 30;
        o.emd.max_imfs = 4;
      });
  add("cycles", {{"cycles", "3"}}, [](auto& o) { o.cycles = 3; });
  return cases;
}

class SpectralFilterPath : public ::testing::TestWithParam<FilterCase> {};

TEST_P(SpectralFilterPath, SavedMeshIsTheLibrarysResult) {
  const FilterCase& c = GetParam();
  const Input in = read_input("fandisk");
  const ServerRun run = run_resource(data_mesh("fandisk"), "enhance.mlx", c.overrides, c.tag);
  Positions expected;
  SpectralMeshFilterReport report;
  std::string error;
  ASSERT_TRUE(spectral_mesh_filter(in.positions, in.faces, c.options, expected, report, error)) << error;
  EXPECT_GT(report.max_displacement, 1e-4 * in.diagonal) << "the case must move the mesh";
  expect_positions(saved_positions(run), expected, in.diagonal, c.tag);
  // the log reports the library's solve
  EXPECT_NE(run.log.find(std::to_string(report.reconstruction.iterations) + " CG iterations"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find(std::to_string(report.imfs.size()) + " IMFs"), std::string::npos) << run.log;
}

INSTANTIATE_TEST_SUITE_P(Fandisk, SpectralFilterPath, ::testing::ValuesIn(filter_cases()),
                         [](const auto& info) { return info.param.tag; });

// ------------------------------------------------------------------------------ noise, bilateral

TEST(MeshlabserverParameters, NoiseSigmaDirectionSeed) {
  const Input in = read_input("fandisk");
  const NoiseDirection directions[] = {NoiseDirection::Random, NoiseDirection::Normal, NoiseDirection::Isotropic};
  for (int direction : {0, 1, 2}) {
    const std::string tag = "noise_" + std::to_string(direction);
    const ServerRun run = run_resource(data_mesh("fandisk"), "add_noise.mlx",
                                     {{"sigmaPercent", "7"}, {"direction", std::to_string(direction)}, {"seed", "5"}}, tag);
    const Positions expected = add_gaussian_noise(in.positions, in.faces, f(7), directions[direction], 5);
    expect_positions(saved_positions(run), expected, in.diagonal, tag);
  }
  // impulsive: a share of the vertices moved, the others where they were
  const ServerRun run = run_resource(data_mesh("fandisk"), "add_noise.mlx",
                                   {{"sigmaPercent", "7"}, {"direction", "1"}, {"sharePercent", "30"}, {"seed", "5"}}, "noise_share");
  const Positions expected = add_gaussian_noise(in.positions, in.faces, f(7), NoiseDirection::Normal, 5, f(30) / 100);
  EXPECT_NE(expected, add_gaussian_noise(in.positions, in.faces, f(7), NoiseDirection::Normal, 5));
  expect_positions(saved_positions(run), expected, in.diagonal, "noise_share");
}

TEST(MeshlabserverParameters, BilateralSigmasAndPasses) {
  const Input in = read_input("fandisk");
  const ServerRun run = run_resource(data_mesh("fandisk"), "bilateral.mlx",
                                   {{"sigmaC", "0.6"}, {"sigmaS", "0.05"}, {"passes", "3"}}, "bilateral");
  BilateralOptions o;
  o.sigma_c = f(0.6);
  o.sigma_s = f(0.05);
  o.passes = 3;
  const Positions expected = bilateral_denoise(in.positions, in.faces, o);
  EXPECT_GT((expected - in.positions).rowwise().norm().maxCoeff(), 1e-4 * in.diagonal);
  expect_positions(saved_positions(run), expected, in.diagonal, "bilateral");
}

// ------------------------------------------------------------------------------ denoise

// A noisy copy of `mesh` (positions rounded to float, as MeshLab holds them) written as an OFF file
// in the test output folder; returns its path.
std::string write_noisy_off(const std::string& file, const ArrayMesh& mesh, double percent, NoiseDirection direction,
                            unsigned seed, Positions& noisy) {
  noisy = add_gaussian_noise(mesh.positions, mesh.faces, percent, direction, seed).cast<float>().cast<double>();
  const std::string path = output_path(file);
  std::ofstream out(path);
  out << "OFF\n" << noisy.rows() << " " << mesh.faces.rows() << " 0\n";
  out.precision(9);
  for (Eigen::Index v = 0; v < noisy.rows(); ++v) out << noisy(v, 0) << " " << noisy(v, 1) << " " << noisy(v, 2) << "\n";
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f)
    out << "3 " << mesh.faces(f, 0) << " " << mesh.faces(f, 1) << " " << mesh.faces(f, 2) << "\n";
  return path;
}

// A noisy strip three vertices wide: its noise estimate rests on its few dozen interior vertices,
// and smooth.mlx's log says so and asks for the noise level.
TEST(MeshlabserverParameters, SmoothSaysWhenTheEstimateRestsOnAFewVertices) {
  const ArrayMesh strip = grid(40, 3);
  Positions noisy;
  const std::string input = write_noisy_off("strip_noisy.off", strip, 10, NoiseDirection::Normal, 3, noisy);
  HamiltonianCycle cycle;
  NoiseEstimate estimate;
  std::string error;
  ASSERT_TRUE(hamiltonian_cycle(strip.faces, static_cast<int>(noisy.rows()), {}, cycle, error)) << error;
  ASSERT_TRUE(estimate_noise(noisy, strip.faces, cycle, {}, estimate, error)) << error;
  ASSERT_TRUE(estimate.rests_on_few_samples());
  const ServerRun run = run_resource(input, "smooth.mlx", {}, "smooth_few_samples");
  EXPECT_NE(run.log.find("read over only " + std::to_string(estimate.samples) + " vertices"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("so it may be far off: if the result is too weak or too strong, undo and give noisePercent"),
            std::string::npos)
      << run.log;
}

// A noisy copy of a data mesh, written as a PLY the way MeshLab will read it (float positions):
// `noisy` holds those positions, `path` the file.
void write_noisy(const std::string& name, const Input& in, double percent, NoiseDirection direction, unsigned seed,
                 Positions& noisy, std::string& path) {
  noisy = add_gaussian_noise(in.positions, in.faces, percent, direction, seed).cast<float>().cast<double>();
  TriMesh m;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh(name).c_str()), 0);
  for (int v = 0; v < m.vn; ++v) m.vert[v].P() = vcg::Point3d(noisy(v, 0), noisy(v, 1), noisy(v, 2));
  path = output_path(name + "_noisy.ply");
  ASSERT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, path.c_str(), 0, true), 0);
}

TEST(MeshlabserverParameters, DenoiseOptions) {
  const Input in = read_input("fandisk");
  Positions noisy;
  std::string input;
  ASSERT_NO_FATAL_FAILURE(write_noisy("fandisk", in, 5.0, NoiseDirection::Random, 2, noisy, input));
  struct Case {
    std::string tag;
    std::vector<std::pair<std::string, std::string>> overrides;
    std::function<void(DenoiseOptions&)> set;
  };
  const Case cases[] = {
      {"paper_stage", {{"paperStage", "true"}, {"noisePercent", "5"}, {"untangle", "false"}, {"refineRounds", "2"},
                       {"featureAngle", "40"}, {"normalFilterIterations", "2"}, {"shortLinePasses", "3"}, {"cycles", "2"},
                       {"cutoff", "0.08"}, {"lambda", "0.5"}, {"refineNormalPasses", "3"}, {"refineVertexIterations", "5"},
                       {"showFeatures", "1"}},
       [](DenoiseOptions& o) {
         o.paper_stage = true;
         o.noise = f(5) / 100.0;
         o.untangle = false;
         o.refine_rounds = 2;
         o.features.angle_degrees = f(40);
         o.features.filter_iterations = 2;
         o.short_line_passes = 3;
         o.cycles = 2;
         o.cutoff = f(0.08);
         o.reconstruction.lambda = f(0.5);
         o.refine_normal_passes = 3;
         o.refine_vertex_iterations = 5;
       }},
      {"paper_stage_only", {{"paperStage", "true"}, {"detectFeatures", "false"}, {"seed", "3"}, {"maxImfs", "3"},
                            {"refineNormalPasses", "0"}},
       [](DenoiseOptions& o) {
         o.paper_stage = true;
         o.detect_features = false;
         o.cycle.seed = 3;
         o.emd.max_imfs = 3;
         o.refine_normal_passes = 0;
       }},
      {"guided_rounds_only", {{"refineOwnNormals", "false"}}, [](DenoiseOptions& o) { o.refine_own_normals = false; }},
      {"default", {}, [](DenoiseOptions&) {}},
  };
  for (const Case& c : cases) {
    DenoiseOptions o;  // denoise.mlx: the library's defaults
    c.set(o);
    Positions expected;
    DenoiseReport report;
    std::string error;
    ASSERT_TRUE(feature_preserving_denoise(noisy, in.faces, o, expected, report, error)) << error;
    const ServerRun run = run_resource(input, "denoise.mlx", c.overrides, "denoise_" + c.tag);
    expect_positions(saved_positions(run), expected, in.diagonal, c.tag);
    if (c.tag == "paper_stage") {  // showFeatures 1: the feature vertices are selected
      TriMesh saved;
      load(run, saved);
      int selected = 0;
      for (int v = 0; v < saved.vn; ++v) {
        EXPECT_EQ(saved.vert[v].IsS(), report.type[v] != FeatureType::None) << v;
        selected += saved.vert[v].IsS();
      }
      EXPECT_EQ(selected, report.feature_vertices);
    }
    if (c.tag == "guided_rounds_only") {  // the guided rounds' range widths, narrow at the creases
      EXPECT_EQ(report.refine_own_normal_rounds, 0);
      EXPECT_NE(run.log.find("; all guided"), std::string::npos) << run.log;
      EXPECT_NE(run.log.find("guided rounds: range width 0.25 on the"), std::string::npos) << run.log;
      EXPECT_NE(run.log.find("0.45 elsewhere"), std::string::npos) << run.log;
    } else if (!o.paper_stage) {
      EXPECT_EQ(report.refine_own_normal_rounds, report.refine_rounds);
    }
    if (o.paper_stage && o.detect_features) {  // the log reports the library's detection and line processing
      EXPECT_NE(run.log.find("features: " + std::to_string(report.feature_vertices) + " vertices"), std::string::npos) << run.log;
      EXPECT_NE(run.log.find(std::to_string(report.lines_by_emd) + " lines by EMD"), std::string::npos) << run.log;
    }
  }
}

// An organic mesh has no sharp creases: by default denoise.mlx gives the adaptive smoothing, and
// smoothCreaseless false forces the refinement; both saved meshes are the library's, and the log
// says which ran.
TEST(MeshlabserverParameters, DenoiseSmoothsSurfacesWithoutCreases) {
  const Input in = read_input("elephant");
  Positions noisy;
  std::string input;
  ASSERT_NO_FATAL_FAILURE(write_noisy("elephant", in, 20.0, NoiseDirection::Isotropic, 6, noisy, input));
  for (const bool smooth : {true, false}) {
    DenoiseOptions o;
    o.smooth_surfaces_by_smoothing = smooth;
    Positions expected;
    DenoiseReport report;
    std::string error;
    ASSERT_TRUE(feature_preserving_denoise(noisy, in.faces, o, expected, report, error)) << error;
    EXPECT_EQ(report.smoothed_instead(), smooth);
    const ServerRun run = run_resource(input, "denoise.mlx", {{"smoothCreaseless", smooth ? "true" : "false"}},
                                       smooth ? "denoise_creaseless" : "denoise_forced_refinement");
    expect_positions(saved_positions(run), expected, in.diagonal, smooth ? "smoothed" : "refined");
    EXPECT_EQ(run.log.find("the result is the adaptive smoothing") != std::string::npos, smooth) << run.log;
    EXPECT_EQ(run.log.find("refinement: ") != std::string::npos, !smooth) << run.log;
  }
}

// A finely meshed part (the meshed cube with every triangle cut in sixteen, 2% noise along the
// normals), whose creases are too few edges for the crease contrast: denoise.mlx refines it, as
// the library does, and the log names its crease lines (docs/quality.md item 28).
TEST(MeshlabserverParameters, DenoiseRefinesAFinelyMeshedPart) {
  const ArrayMesh cube = midpoint_subdivision(midpoint_subdivision(load_data_mesh("cube-meshed")));
  Positions noisy;
  const std::string input = write_noisy_off("cube_cut16_noisy.off", cube, 2.0, NoiseDirection::Normal, 17, noisy);
  Positions expected;
  DenoiseReport report;
  std::string error;
  ASSERT_TRUE(feature_preserving_denoise(noisy, cube.faces, DenoiseOptions{}, expected, report, error)) << error;
  ASSERT_LT(report.crease_contrast, kNoCreaseContrast);
  ASSERT_FALSE(report.smoothed_instead());
  const ServerRun run = run_resource(input, "denoise.mlx", {}, "denoise_finely_meshed_part");
  const double diagonal = (noisy.colwise().maxCoeff() - noisy.colwise().minCoeff()).norm();
  expect_positions(saved_positions(run), expected, diagonal, "refined");
  EXPECT_TRUE(std::regex_search(run.log, std::regex("its crease lines 3\\.[0-9] times its breadth"))) << run.log;
  EXPECT_EQ(run.log.find("the result is the adaptive smoothing"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("refinement: "), std::string::npos) << run.log;
}

// A coarse CAD export that the noise-level smoothing distorts (rotor, 5% noise along the normals):
// denoise.mlx refines it from the input (item 17), as the library does, and the log says why.
// A data mesh with noise (seed 11), written for meshlabserver, and the library's denoising of it.
struct DenoisedInput {
  Input in;
  std::string path;
  Positions expected;
  DenoiseReport report;
};

void denoise_noisy(const char* mesh, double percent, NoiseDirection direction, const DenoiseOptions& options,
                   DenoisedInput& out) {
  out.in = read_input(mesh);
  Positions noisy;
  ASSERT_NO_FATAL_FAILURE(write_noisy(mesh, out.in, percent, direction, 11, noisy, out.path));
  std::string error;
  ASSERT_TRUE(feature_preserving_denoise(noisy, out.in.faces, options, out.expected, out.report, error)) << error;
}

TEST(MeshlabserverParameters, DenoiseRefinesADistortedCoarseExportFromItsInput) {
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("rotor", 5.0, NoiseDirection::Normal, {}, d));
  EXPECT_TRUE(d.report.smoothing_distorts());
  EXPECT_FALSE(d.report.untangled);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {}, "denoise_distorted");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "distorted");
  EXPECT_NE(run.log.find("distorts features a few edges wide (a coarse CAD export); refined from the input"), std::string::npos)
      << run.log;
  EXPECT_NE(run.log.find("started from the input"), std::string::npos) << run.log;
}

// Blade at 10% along the normals: its slivers get converging rounds up to the count against their
// median altitude (item 41), as in the library; the log gives the altitude and the rounds allowed.
TEST(MeshlabserverParameters, DenoiseGivesThinFacesMoreConvergingRounds) {
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("blade", 10.0, NoiseDirection::Normal, {}, d));
  ASSERT_GT(d.report.refine_rounds, d.report.refine_rounds_asked);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {}, "denoise_thin_faces");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "thin faces");
  char altitude[32];
  std::snprintf(altitude, sizeof altitude, "%.2f", d.report.refine_median_altitude);
  const std::string line = "(up to " + std::to_string(d.report.refine_rounds_allowed) +
                           " while they converge: the faces' median altitude is " + altitude + " mean edges)";
  EXPECT_NE(run.log.find(line), std::string::npos) << line << "\n" << run.log;
}

// Fandisk at 70% isotropic noise: the smoothed mesh reads no sharp creases, a trial refinement
// brings them back and the part is refined after all (item 31), as in the library; the log says so.
TEST(MeshlabserverParameters, DenoiseKeepsARefinementThatBringsBackCreasesHeavyNoiseHid) {
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("fandisk", 70.0, NoiseDirection::Isotropic, {}, d));
  ASSERT_LT(d.report.crease_contrast, kNoCreaseContrast);
  ASSERT_TRUE(d.report.creases_revealed);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {}, "denoise_creases_revealed");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "creases revealed");
  EXPECT_TRUE(std::regex_search(run.log, std::regex("a trial refinement reads a crease contrast of [0-9.]+ \\(at least 60: flat "
                                                    "faces meeting at creases, refined after all\\)")))
      << run.log;
  EXPECT_EQ(run.log.find("the result is the adaptive smoothing"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("refinement: "), std::string::npos) << run.log;
}

// Handle at 10% noise along the normals: its noise-level smoothing moves it by about the noise's RMS,
// an uncertain reading of item 17's rule; denoise.mlx blends the refinement from the input and the
// usual route (item 33), as the library does, and the log gives the shares.
TEST(MeshlabserverParameters, DenoiseBlendsWhereTheSmoothingsMoveIsUncertain) {
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("handle", 10.0, NoiseDirection::Normal, {}, d));
  ASSERT_GT(d.report.distort_weight, 0.0);
  ASSERT_LT(d.report.distort_weight, 1.0);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {}, "denoise_uncertain_move");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "blended routes");
  EXPECT_TRUE(std::regex_search(run.log, std::regex("an uncertain reading \\(a move from 0\\.9 to 1\\.1, or from 8% to 12% of "
                                                    "the faces folded\\): the result is [0-9]+% the refinement from the "
                                                    "input and [0-9]+% the usual route's below")))
      << run.log;
}

// Handle at 30% noise along the normals: its noise-level smoothing moves it by more than the noise
// did, with about a tenth of its faces folded, an uncertain reading of item 17's folded share;
// denoise.mlx blends the two routes (item 34) as the library does.
TEST(MeshlabserverParameters, DenoiseBlendsWhereTheFoldedShareIsUncertain) {
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("handle", 30.0, NoiseDirection::Normal, {}, d));
  ASSERT_GE(d.report.smoothing_move, kDistortingMoveHigh);
  ASSERT_GT(d.report.folded_faces, kHeavilyFoldedLow * d.in.faces.rows());
  ASSERT_LT(d.report.folded_faces, kHeavilyFoldedHigh * d.in.faces.rows());
  ASSERT_GT(d.report.distort_weight, 0.0);
  ASSERT_LT(d.report.distort_weight, 1.0);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {}, "denoise_uncertain_folded_share");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "blended routes");
  const std::string shares = std::to_string(static_cast<int>(std::lround(100 * d.report.distort_weight))) +
                             "% the refinement from the input and " +
                             std::to_string(static_cast<int>(std::lround(100 * (1 - d.report.distort_weight)))) + "% the usual route's";
  EXPECT_NE(run.log.find(shares), std::string::npos) << shares << "\n" << run.log;
}

// Mannequin-devil at 10% isotropic noise reads uncertain creases: denoise.mlx blends the refinement
// and the adaptive smoothing (item 32), as the library does, and the log gives the shares.
TEST(MeshlabserverParameters, DenoiseBlendsWhereTheCreasesAreUncertain) {
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("mannequin-devil", 10.0, NoiseDirection::Isotropic, {}, d));
  ASSERT_GE(d.report.crease_contrast, kNoCreaseContrast);
  ASSERT_LT(d.report.crease_contrast, kCreaseContrast);
  ASSERT_GT(d.report.smoothing_weight, 0.0);
  ASSERT_LT(d.report.smoothing_weight, 1.0);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {}, "denoise_uncertain_creases");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "blended");
  EXPECT_TRUE(std::regex_search(run.log, std::regex("uncertain creases: the refinement reads a crease contrast of [0-9.]+ "
                                                    "\\(below 60: the result is [0-9]+% the adaptive smoothing and "
                                                    "[0-9]+% the refinement\\)")))
      << run.log;
  EXPECT_NE(run.log.find("refinement: "), std::string::npos) << run.log;
  EXPECT_EQ(run.log.find("no refinement"), std::string::npos) << run.log;
}

// The user's noise level reaches the denoiser's adaptive smoothing (a surface without creases),
// whose cut-off Stein's unbiased risk then chooses: the same result as the library, and the log says so.
TEST(MeshlabserverParameters, DenoiseWithAGivenNoiseChoosesTheCutoffByUnbiasedRisk) {
  DenoiseOptions o;
  o.noise = f(2) / 100.0;
  DenoisedInput d;
  ASSERT_NO_FATAL_FAILURE(denoise_noisy("bull", 2.0, NoiseDirection::Isotropic, o, d));
  EXPECT_TRUE(d.report.smoothed_instead());
  EXPECT_TRUE(d.report.smoothing.cutoff_by_risk);
  const ServerRun run = run_resource(d.path, "denoise.mlx", {{"noisePercent", "2"}}, "denoise_given_noise");
  expect_positions(saved_positions(run), d.expected, d.in.diagonal, "given noise");
  EXPECT_NE(run.log.find("the adaptive smoothing (cut-off by Stein's unbiased risk with the given noise)"), std::string::npos)
      << run.log;
}

// ------------------------------------------------------------------------------ compare

TEST(MeshlabserverParameters, CompareTwoDifferentMeshesEveryOutput) {
  const Input in = read_input("fandisk");
  const Positions noisy = add_gaussian_noise(in.positions, in.faces, 10.0, NoiseDirection::Random, 4).cast<float>().cast<double>();
  TriMesh m;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh("fandisk").c_str()), 0);
  for (int v = 0; v < m.vn; ++v) m.vert[v].P() = vcg::Point3d(noisy(v, 0), noisy(v, 1), noisy(v, 2));
  const std::string result = output_path("fandisk_noisy.ply");
  ASSERT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, result.c_str(), 0, true), 0);
  for (int per_vertex : {0, 1}) {
    const std::string tag = "compare_" + std::to_string(per_vertex);
    const ServerRun run = run_script(MeshLab::V2020, {data_mesh("fandisk"), result},
                                     chain_scripts(tag, {"compare.mlx"}, {{"perVertex", std::to_string(per_vertex)}}), tag);
    const Eigen::VectorXd expected = per_vertex ? vertex_normal_error_degrees(noisy, in.positions, in.faces)
                                                : vertex_distance_to_reference(noisy, in.positions, in.faces);
    expect_values(saved_quality(run), expected, tag);
    std::smatch ea, ev;
    ASSERT_TRUE(std::regex_search(run.log, ea, std::regex("E_a = ([0-9.eE+-]+)"))) << run.log;
    ASSERT_TRUE(std::regex_search(run.log, ev, std::regex("E_v = ([0-9.eE+-]+)"))) << run.log;
    const double expected_ea = mean_face_normal_error_degrees(noisy, in.positions, in.faces);
    const double expected_ev = mean_distance_to_reference(noisy, in.positions, in.faces);
    EXPECT_GT(expected_ea, 1.0);
    EXPECT_NEAR(std::stod(ea[1]), expected_ea, 1e-4 * expected_ea);
    EXPECT_NEAR(std::stod(ev[1]), expected_ev, 1e-3 * expected_ev);
  }
}

}  // namespace
}  // namespace hht::test

// ------------------------------------------------- the newer filters' parameter paths

namespace hht::test {
namespace {

// Fandisk with 5% noise along random directions, saved as MeshLab will read it.
struct NoisyInput {
  Input in;
  Positions noisy;
  std::string path;
};

NoisyInput noisy_fandisk(const std::string& name) {
  NoisyInput n{read_input("fandisk"), {}, output_path(name + ".ply")};
  n.noisy = add_gaussian_noise(n.in.positions, n.in.faces, 5.0, NoiseDirection::Random, 5).cast<float>().cast<double>();
  TriMesh m;
  EXPECT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh("fandisk").c_str()), 0);
  for (int v = 0; v < m.vn; ++v) m.vert[v].P() = vcg::Point3d(n.noisy(v, 0), n.noisy(v, 1), n.noisy(v, 2));
  EXPECT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, n.path.c_str(), 0, true), 0);
  return n;
}

TEST(MeshlabserverParameters, AdaptiveSmoothStrengthNoiseAndEmd) {
  const NoisyInput n = noisy_fandisk("adaptive_input");
  struct Case {
    std::string tag;
    std::vector<std::pair<std::string, std::string>> overrides;
    std::function<void(NoiseAdaptiveSmoothingOptions&)> set;
  };
  const Case cases[] = {
      {"strength", {{"strength", "2.5"}}, [](NoiseAdaptiveSmoothingOptions& o) { o.strength = f(2.5); }},
      {"noise", {{"noisePercent", "8"}}, [](NoiseAdaptiveSmoothingOptions& o) {
         o.noise = f(8) / 100.0;
         o.unbiased_risk = true;  // a given noise level: the cut-off by Stein's unbiased risk
       }},
      {"emd", {{"seed", "2"}, {"sdThreshold", "0.3"}, {"maxSifts", "7"}, {"minExtrema", "9"}, {"maxImfs", "2"}},
       [](NoiseAdaptiveSmoothingOptions& o) {
         o.cycle.seed = 2;
         o.emd.sd_threshold = f(0.3);
         o.emd.max_sifts = 7;
         o.emd.min_extrema = 9;
         o.emd.max_imfs = 2;
       }},
  };
  Positions previous;
  for (const Case& c : cases) {
    NoiseAdaptiveSmoothingOptions o;
    c.set(o);
    Positions expected;
    NoiseAdaptiveSmoothingReport report;
    std::string error;
    ASSERT_TRUE(noise_adaptive_smooth(n.noisy, n.in.faces, o, expected, report, error)) << error;
    const ServerRun run = run_resource(n.path, "smooth.mlx", c.overrides, "adaptive_" + c.tag);
    expect_positions(saved_positions(run), expected, n.in.diagonal, c.tag);
    EXPECT_EQ(run.log.find("cut-off by Stein's unbiased risk with the given noise") != std::string::npos, o.unbiased_risk)
        << run.log;
    if (previous.rows() > 0) {  // each option changes the result
      EXPECT_GT((expected - previous).rowwise().norm().maxCoeff(), 1e-5 * n.in.diagonal) << c.tag;
    }
    previous = expected;
  }
}

// smooth.mlx finishes as the library does, by the recorrupted risk of its four finishes (docs/quality.md
// items 20 and 22), and logs the choice: at 10% the face-normal pass kept on camel (well-shaped) and
// left out on cow (coarse), the slides capped on cow; at 20% camel takes Taubin's slide.
TEST(MeshlabserverParameters, AdaptiveSmoothLogsTheFinishChoice) {
  struct Case {
    const char* mesh;
    double percent;
  };
  bool slid = false, capped = false;
  for (const Case& c : {Case{"camel", 10}, Case{"cow", 10}, Case{"camel", 20}}) {
    const std::string tag = std::string(c.mesh) + std::to_string(static_cast<int>(c.percent));
    const Input in = read_input(c.mesh);
    Positions noisy;
    std::string input;
    ASSERT_NO_FATAL_FAILURE(write_noisy(c.mesh, in, c.percent, NoiseDirection::Isotropic, 21, noisy, input));
    Positions expected;
    NoiseAdaptiveSmoothingReport report;
    std::string error;
    ASSERT_TRUE(noise_adaptive_smooth(noisy, in.faces, {}, expected, report, error)) << error;
    if (c.percent == 10) {
      EXPECT_EQ(report.face_normal_pass, std::string(c.mesh) == "camel") << tag;
    }
    (report.taubin_slide ? slid : capped) = true;
    const ServerRun run = run_resource(input, "smooth.mlx", {}, "adaptive_finish_" + tag);
    expect_positions(saved_positions(run), expected, in.diagonal, tag);
    EXPECT_NE(run.log.find("finish chosen by recorrupted risk among 4"), std::string::npos) << run.log;
    EXPECT_NE(run.log.find(report.face_normal_pass ? "face-normal pass kept" : "face-normal pass left out"), std::string::npos)
        << run.log;
    EXPECT_NE(run.log.find(report.taubin_slide ? "slides along the surface by Taubin's smoothing"
                                               : "slides along the surface capped"),
              std::string::npos)
        << run.log;
  }
  EXPECT_TRUE(slid);
  EXPECT_TRUE(capped);
}

// Noise along the normals: the cap on slides along the surface follows the tangential noise the
// input holds, and the log says so; isotropic noise leaves the cap, and the log, as they were.
TEST(MeshlabserverParameters, AdaptiveSmoothLogsTheTangentialCap) {
  const Input in = read_input("camel");
  for (NoiseDirection direction : {NoiseDirection::Normal, NoiseDirection::Isotropic}) {
    const bool along_normals = direction == NoiseDirection::Normal;
    Positions noisy;
    std::string input;
    ASSERT_NO_FATAL_FAILURE(write_noisy("camel", in, 30.0, direction, 21, noisy, input));
    Positions expected;
    NoiseAdaptiveSmoothingReport report;
    std::string error;
    ASSERT_TRUE(noise_adaptive_smooth(noisy, in.faces, {}, expected, report, error)) << error;
    EXPECT_EQ(report.tangential_share < 0.5, along_normals);
    const ServerRun run = run_resource(input, "smooth.mlx", {}, along_normals ? "tangential_normal" : "tangential_iso");
    expect_positions(saved_positions(run), expected, in.diagonal, "camel");
    EXPECT_EQ(run.log.find("slides along the surface capped at") != std::string::npos, report.tangential_share < 1)
        << run.log;
  }
}

TEST(MeshlabserverParameters, GuidedDenoiseRoundsPassesSigmaIterations) {
  const NoisyInput n = noisy_fandisk("guided_input");
  GuidedNormalDenoiseOptions o;
  o.stand_up_turned_faces = true;  // the script's
  o.rounds = 2;
  o.normal_passes = 3;
  o.sigma = f(0.5);
  o.vertex_iterations = 7;
  Positions expected, defaults;
  std::string error;
  ASSERT_TRUE(guided_normal_denoise(n.noisy, n.in.faces, o, expected, error)) << error;
  ASSERT_TRUE(guided_normal_denoise(n.noisy, n.in.faces, {}, defaults, error)) << error;
  EXPECT_GT((expected - defaults).rowwise().norm().maxCoeff(), 1e-4 * n.in.diagonal);
  const ServerRun run = run_resource(
      n.path, "guided_denoise.mlx", {{"rounds", "2"}, {"normalPasses", "3"}, {"sigma", "0.5"}, {"vertexIterations", "7"}},
      "guided");
  expect_positions(saved_positions(run), expected, n.in.diagonal, "guided");
}

// bilateral_normal_denoise.mlx is the guided filter with the range kernel on each face's own
// normal and its authors' defaults; the guided filter's result is another.
TEST(MeshlabserverParameters, BilateralNormalDenoiseScript) {
  const NoisyInput n = noisy_fandisk("bilateral_normal_input");
  GuidedNormalDenoiseOptions o;
  o.stand_up_turned_faces = true;  // the script's
  o.guidance = NormalGuidance::OwnNormal;
  o.normal_passes = 20;
  o.vertex_iterations = 10;
  Positions expected, guided;
  std::string error;
  ASSERT_TRUE(guided_normal_denoise(n.noisy, n.in.faces, o, expected, error)) << error;
  o.guidance = NormalGuidance::ConsistentPatch;
  ASSERT_TRUE(guided_normal_denoise(n.noisy, n.in.faces, o, guided, error)) << error;
  EXPECT_GT((expected - guided).rowwise().norm().maxCoeff(), 1e-4 * n.in.diagonal);
  const ServerRun run = run_resource(n.path, "bilateral_normal_denoise.mlx", {}, "bilateral_normal");
  EXPECT_NE(run.log.find("Bilateral normal filtering denoise: 1 round(s) of 20 passes"), std::string::npos) << run.log;
  expect_positions(saved_positions(run), expected, n.in.diagonal, "bilateral_normal");
}

// On a clean irregular mesh (femur) guided_denoise.mlx stands up the faces the filter turned over,
// as the library does and its log says; standUpTurnedFaces false gives the published method.
TEST(MeshlabserverParameters, GuidedDenoiseStandsUpTurnedFaces) {
  const Input in = read_input("femur");
  const Positions& clean = in.positions;
  const std::string input = data_mesh("femur");
  GuidedNormalDenoiseOptions published, guarded;
  guarded.stand_up_turned_faces = true;
  Positions plain, stood;
  GuidedNormalDenoiseReport report;
  std::string error;
  ASSERT_TRUE(guided_normal_denoise(clean, in.faces, published, plain, error)) << error;
  ASSERT_TRUE(guided_normal_denoise(clean, in.faces, guarded, stood, error, {}, &report)) << error;
  ASSERT_GT(report.stood_up_faces, 0);
  EXPECT_GT((plain - stood).rowwise().norm().maxCoeff(), 1e-4 * in.diagonal);
  const ServerRun on = run_resource(input, "guided_denoise.mlx", {}, "guided_stand_up");
  expect_positions(saved_positions(on), stood, in.diagonal, "guided, faces stood up");
  EXPECT_NE(on.log.find("  " + std::to_string(report.stood_up_faces) + " faces the vertex update turned over stood back up"),
            std::string::npos)
      << on.log;
  const ServerRun off = run_resource(input, "guided_denoise.mlx", {{"standUpTurnedFaces", "false"}}, "guided_published");
  expect_positions(saved_positions(off), plain, in.diagonal, "guided, published");
  EXPECT_EQ(off.log.find("stood back up"), std::string::npos) << off.log;
}

TEST(MeshlabserverParameters, NonLocalMeansEtasAndIterations) {
  const NoisyInput n = noisy_fandisk("nlm_input");
  NonLocalMeansOptions o;
  o.eta1 = f(2.2);
  o.eta2 = f(0.9);
  o.eta3 = f(0.7);
  o.iterations = 2;
  const Positions expected = nonlocal_means_denoise(n.noisy, n.in.faces, o);
  EXPECT_GT((expected - nonlocal_means_denoise(n.noisy, n.in.faces, {})).rowwise().norm().maxCoeff(),
            1e-4 * n.in.diagonal);
  const ServerRun run = run_resource(n.path, "nonlocal_means.mlx",
                                     {{"eta1", "2.2"}, {"eta2", "0.9"}, {"eta3", "0.7"}, {"iterations", "2"}}, "nlm");
  expect_positions(saved_positions(run), expected, n.in.diagonal, "nlm");
}

TEST(MeshlabserverParameters, SurfaceEmdEveryOutputResidueAndOptions) {
  const Input in = read_input("fandisk");
  MeanCurvature curvature;
  std::string error;
  ASSERT_TRUE(mean_curvature(in.positions, in.faces, curvature, error)) << error;
  SurfaceEmdOptions emd;
  emd.sd_threshold = f(0.2);
  emd.max_sifts = 10;
  emd.min_extrema = 12;
  emd.max_imfs = 3;
  SurfaceEmdResult r;
  ASSERT_TRUE(surface_emd(in.positions, in.faces, curvature.signal, emd, r, error)) << error;
  ASSERT_EQ(r.imfs.size(), 3u);
  const std::vector<std::pair<std::string, std::string>> emd_overrides = {
      {"sdThreshold", "0.2"}, {"maxSifts", "10"}, {"minExtrema", "12"}, {"maxImfs", "3"}};
  auto with = [&](std::vector<std::pair<std::string, std::string>> more) {
    more.insert(more.end(), emd_overrides.begin(), emd_overrides.end());
    return more;
  };
  // IMF 2 into quality
  expect_values(saved_quality(run_resource(data_mesh("fandisk"), "surface_emd.mlx", with({{"imf", "2"}}), "semd_imf2")),
                r.imfs[1], "IMF 2");
  // the residue after the finest IMF: G minus IMF 1
  const Eigen::VectorXd residue1 = r.residue + r.imfs[1] + r.imfs[2];
  expect_values(saved_quality(run_resource(data_mesh("fandisk"), "surface_emd.mlx",
                                           with({{"output", "1"}, {"residue", "1"}}), "semd_residue1")),
                residue1, "residue 1");
  // the mesh rebuilt from residue 2 with lambda 0.5
  SurfaceEmdSmoothingOptions o;
  o.emd = emd;
  o.residue = 2;
  o.reconstruction.lambda = f(0.5);
  Positions expected;
  SurfaceEmdSmoothingReport report;
  ASSERT_TRUE(surface_emd_smoothing(in.positions, in.faces, o, expected, report, error)) << error;
  EXPECT_GT((expected - in.positions).rowwise().norm().maxCoeff(), 1e-4 * in.diagonal);
  expect_positions(saved_positions(run_resource(data_mesh("fandisk"), "surface_emd.mlx",
                                                with({{"output", "2"}, {"residue", "2"}, {"lambda", "0.5"}}),
                                                "semd_rebuild")),
                   expected, in.diagonal, "rebuilt from residue 2");
}

TEST(MeshlabserverParameters, FeatureCentricAngleAndPasses) {
  const NoisyInput n = noisy_fandisk("centric_input");
  SurfaceEmdSmoothingOptions o;
  o.feature_centric = true;
  o.residue = 2;
  o.emd.max_imfs = 2;  // keeps the test short; the residue is the same
  o.features.angle_degrees = f(40);
  o.features.filter_iterations = 2;
  Positions expected, defaults;
  SurfaceEmdSmoothingReport report, default_report;
  std::string error;
  ASSERT_TRUE(surface_emd_smoothing(n.noisy, n.in.faces, o, expected, report, error)) << error;
  SurfaceEmdSmoothingOptions d;
  d.feature_centric = true;
  d.residue = 2;
  d.emd.max_imfs = 2;
  ASSERT_TRUE(surface_emd_smoothing(n.noisy, n.in.faces, d, defaults, default_report, error)) << error;
  EXPECT_NE(report.feature_vertices, default_report.feature_vertices);
  const ServerRun run = run_resource(
      n.path, "feature_centric_emd.mlx",
      {{"residue", "2"}, {"maxImfs", "2"}, {"featureAngle", "40"}, {"normalFilterIterations", "2"}},
      "centric");
  expect_positions(saved_positions(run), expected, n.in.diagonal, "feature-centric");
  EXPECT_NE(run.log.find(std::to_string(report.feature_vertices) + " feature vertices"), std::string::npos) << run.log;
}

}  // namespace
}  // namespace hht::test
