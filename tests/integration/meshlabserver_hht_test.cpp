// The HHT core filters (Hilbert Spectra, Spectral Filter, Add Gaussian Noise) through meshlabserver.
#include "meshlabserver_harness.h"

#include "evaluation/denoise_metrics.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/import_off.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace hht::test {
namespace {

namespace fs = std::filesystem;

void load_input(const std::string& name, TriMesh& m) {
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh(name).c_str()), 0);
}

TEST(MeshlabserverHht, HilbertSpectraFrequencyAndDistribution) {
  fs::remove(output_path("frequency_distribution.png"));
  fs::remove(output_path("frequency_distribution.csv"));
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), resource("hilbert_spectra.mlx"), "spectra_fandisk");
  TriMesh m;
  load(run, m);
  for (const auto& v : m.vert) {  // the script writes the finest IMF's instantaneous frequency
    ASSERT_GE(v.cQ(), 0.0);
    ASSERT_LE(v.cQ(), 0.5);
  }
  EXPECT_NE(run.log.find("IMF 1:"), std::string::npos) << run.log;
  EXPECT_GT(fs::file_size(output_path("frequency_distribution.png")), 1000u);
  std::ifstream csv(output_path("frequency_distribution.csv"));
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("frequency_low,frequency_high,imf1,imf2", 0), 0u) << header;
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 50);
}

TEST(MeshlabserverHht, SpectraOfAQualityLeftByAnotherFilter) {
  // the curvature filter writes G into quality; the spectra filter then analyses that quality
  const std::string script = chain_scripts("spectra_of_quality", {"curvature_signal.mlx", "hilbert_spectra.mlx"},
                                           {{"source", "1"}, {"output", "4"}, {"histogramFile", ""}});
  TriMesh m;
  load(run_meshlabserver(data_mesh("fandisk"), script, "spectra_of_quality"), m);
  double spread = 0;
  for (const auto& v : m.vert) spread = std::max(spread, std::abs(double(v.cQ())));
  EXPECT_GT(spread, 0.0);  // the residue of G, not zeros
}

TEST(MeshlabserverHht, GainOneGivesTheMeshBackInTheSavedFile) {
  const std::string script = chain_scripts("gain_one", {"enhance.mlx"}, {{"gain", "1"}});
  TriMesh out, in;
  load(run_meshlabserver(data_mesh("fandisk"), script, "gain_one"), out);
  load_input("fandisk", in);
  ASSERT_EQ(out.vn, in.vn);
  EXPECT_LT(max_distance(out, in), 1e-5 * bbox_diagonal(in));
}

TEST(MeshlabserverHht, NoiseThenSmoothIsVisiblySmoother) {
  TriMesh noisy, smoothed;
  load(run_meshlabserver(data_mesh("armadillo"), chain_scripts("noise_only", {"add_noise.mlx"}), "noise_only"), noisy);
  load(run_meshlabserver(data_mesh("armadillo"), chain_scripts("noise_smooth", {"add_noise.mlx", "smooth.mlx"}),
                         "noise_smooth"), smoothed);
  EXPECT_LT(mean_dihedral_angle(smoothed), 0.7 * mean_dihedral_angle(noisy));
}

TEST(MeshlabserverHht, EnhanceStrengthensDetail) {
  TriMesh in, enhanced;
  load_input("fandisk", in);
  load(run_meshlabserver(data_mesh("fandisk"), resource("enhance.mlx"), "enhance_fandisk"), enhanced);
  EXPECT_GT(mean_dihedral_angle(enhanced), 1.1 * mean_dihedral_angle(in));
  EXPECT_LT(max_distance(enhanced, in), 0.05 * bbox_diagonal(in));  // detail, not a different shape
}

TEST(MeshlabserverHht, NoiseHasTheRequestedSigma) {
  TriMesh in, noisy;
  load_input("fandisk", in);
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), chain_scripts("noise_sigma", {"add_noise.mlx"}), "noise_sigma");
  load(run, noisy);
  Positions p;
  Faces f;
  mesh_to_arrays(in, p, f);
  double edge = 0, sq = 0;
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) edge += (p.row(f(i, k)) - p.row(f(i, (k + 1) % 3))).norm();
  edge /= 3.0 * f.rows();
  for (int v = 0; v < in.vn; ++v) sq += (noisy.vert[v].cP() - in.vert[v].cP()).SquaredNorm();
  EXPECT_NEAR(std::sqrt(sq / in.vn) / edge, 0.10, 0.10 * 0.03);  // the script asks for 10%
}

// The log gives the noise's part along the normals, the level the smoothing and denoising
// filters read and take as noisePercent: a third of the variance for the script's random
// directions (10% / sqrt 3 = 5.77%), all of it along the normals.
TEST(MeshlabserverHht, NoiseLogsItsPartAlongTheNormals) {
  for (const char* direction : {"0", "1"}) {
    const std::string tag = std::string("noise_along_") + direction;
    const ServerRun run = run_meshlabserver(data_mesh("fandisk"), chain_scripts(tag, {"add_noise.mlx"}, {{"direction", direction}}), tag);
    ASSERT_EQ(run.exit_code, 0) << run.log;
    const std::string key = "along the vertex normals ";
    const size_t at = run.log.find(key);
    ASSERT_NE(at, std::string::npos) << run.log;
    const double percent = std::stod(run.log.substr(at + key.size()));
    EXPECT_NEAR(percent, direction == std::string("0") ? 10 / std::sqrt(3.0) : 10.0, 0.4) << run.log;
  }
}

// A clean irregular mesh with slivers standing off its surface (bull: enhance.mlx turned 171
// faces over before the flip guard, smooth.mlx 5 before its un-turning of wrinkles): both
// scripts change it and turn no face over.
TEST(MeshlabserverHht, CleanIrregularMeshKeepsEveryFaceTheRightWayUp) {
  TriMesh in;
  load_input("bull", in);
  for (const char* script : {"smooth.mlx", "enhance.mlx"}) {
    const std::string tag = std::string("clean_bull_") + script;
    const ServerRun run = run_meshlabserver(data_mesh("bull"), resource(script), tag.substr(0, tag.size() - 4));
    TriMesh out;
    load(run, out);
    ASSERT_EQ(out.vn, in.vn) << script;
    ASSERT_EQ(out.fn, in.fn) << script;
    EXPECT_GT(max_distance(out, in), 1e-4 * bbox_diagonal(in)) << script;
    Positions p, q;
    Faces f, g;
    mesh_to_arrays(in, p, f);
    mesh_to_arrays(out, q, g);
    EXPECT_EQ(flipped_faces(q, p, f), 0) << script;
    if (std::string(script) == "smooth.mlx") {
      // the log says the estimate may be bull's own detail, and that its lower bound on the noise reads 0 (item 38)
      std::smatch surely;
      ASSERT_TRUE(std::regex_search(run.log, surely, std::regex("the noise is at least ([0-9.]+)%"))) << run.log;
      EXPECT_LT(std::stod(surely[1]), 1.0) << run.log;
    }
  }
}

TEST(MeshlabserverHht, BadInputLeavesNothingBehind) {
  expect_bad_input_refused({"hilbert_spectra.mlx", "smooth.mlx", "enhance.mlx", "add_noise.mlx"}, "hht_bad");
}

}  // namespace
}  // namespace hht::test
