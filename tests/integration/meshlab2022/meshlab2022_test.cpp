// MeshLab 2022.02: every shipped script through tools/meshlabserver2022 with the 2022.02
// plugin, in the Debian 13 root, against 2020.09's meshlabserver on the same input.
#include "meshlabserver_harness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace hht::test {
namespace {

namespace fs = std::filesystem;

// Both builds keep float meshes and run the same double-precision code, but with other
// compilers (g++ 12 / 14) and library versions (Eigen, CHOLMOD): positions may differ in
// the last float bits and iterative solves may stop one iteration apart.
constexpr double kPositionTolerance = 1e-4;  // x bounding-box diagonal
constexpr double kQualityTolerance = 1e-4;   // x the range of the 2020.09 quality

std::vector<std::string> shipped_scripts() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(HHT_RESOURCES_DIR))
    if (entry.path().extension() == ".mlx") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Fandisk with the paper's noise, made by 2020.09: every script gets non-trivial input.
std::string noisy_fandisk(const std::string& tag) {
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), resource("add_noise.mlx"), tag + "_input");
  EXPECT_EQ(run.exit_code, 0) << run.log;
  return run.output;
}

std::vector<std::string> inputs_for(const std::string& script, const std::string& noisy) {
  if (script == "compare.mlx") return {data_mesh("fandisk"), noisy};  // reference, then result
  return {noisy};
}

class ShippedScript : public testing::TestWithParam<std::string> {};

TEST_P(ShippedScript, SameResultInMeshLab2022As2020) {
  const std::string script = GetParam();
  const std::string tag = "mlx2022_" + fs::path(script).stem().string();
  const std::string noisy = noisy_fandisk(tag);
  const ServerRun old_run = run_script(MeshLab::V2020, inputs_for(script, noisy), resource(script), tag + "_2020");
  const ServerRun new_run = run_script(MeshLab::V2022, inputs_for(script, noisy), resource(script), tag + "_2022");
  ASSERT_EQ(old_run.exit_code, 0) << old_run.log;
  ASSERT_EQ(new_run.exit_code, 0) << new_run.log;
  TriMesh a, b;
  bool a_quality = false, b_quality = false;
  ASSERT_TRUE(load_ply(old_run.output, a, a_quality));
  ASSERT_TRUE(load_ply(new_run.output, b, b_quality));
  ASSERT_EQ(a.VN(), b.VN());
  ASSERT_EQ(a.FN(), b.FN());
  const double diagonal = bbox_diagonal(a);
  const double moved = max_distance(a, b);
  EXPECT_LE(moved, kPositionTolerance * diagonal) << script << ": largest difference " << moved / diagonal
                                                  << " x diagonal";
  ASSERT_EQ(a_quality, b_quality) << script;
  if (a_quality) {
    double low = a.vert[0].Q(), high = low;
    double differs = 0;
    for (size_t i = 0; i < a.vert.size(); ++i) {
      low = std::min(low, a.vert[i].Q());
      high = std::max(high, a.vert[i].Q());
      differs = std::max(differs, double(std::abs(a.vert[i].Q() - b.vert[i].Q())));
    }
    const double range = std::max(high - low, 1e-30);
    EXPECT_LE(differs, kQualityTolerance * range) << script << ": largest quality difference " << differs / range
                                                  << " x range";
    std::printf("%s: 2022.02 vs 2020.09 quality within %.2e x its range\n", script.c_str(), differs / range);
  }
  TriMesh input;
  ASSERT_TRUE(load_ply(noisy, input, b_quality));
  std::printf("%s: 2022.02 vs 2020.09 positions within %.2e x diagonal; the script itself moved vertices by up to "
              "%.2e x diagonal\n", script.c_str(), moved / diagonal, max_distance(input, a) / diagonal);
}

INSTANTIATE_TEST_SUITE_P(Resources, ShippedScript, testing::ValuesIn(shipped_scripts()),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return fs::path(info.param).stem().string();
                         });

TEST(MeshLab2022, BadInputRefusedAsIn2020) {
  expect_bad_input_refused(shipped_scripts(), "mlx2022_bad", MeshLab::V2022);
}

TEST(MeshLab2022, LoaderRemovesNanVerticesBeforeAnyFilter) {
  const std::string nan = output_path("mlx2022_nan.off");
  std::ofstream(nan) << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nnan 1 1\n3 0 1 2\n3 0 1 3\n3 1 2 4\n";
  const ServerRun run = run_script(MeshLab::V2022, {nan}, resource("curvature_signal.mlx"), "mlx2022_nan");
  EXPECT_NE(run.log.find("1 vertices with NAN coords"), std::string::npos) << run.log;
  TriMesh m;
  load(run, m);
  EXPECT_EQ(m.VN(), 4);
  EXPECT_EQ(m.FN(), 2);
}

TEST(MeshLab2022, RunnerRefusesAScriptMissingAParameter) {
  std::ifstream in(resource("add_noise.mlx"));
  std::string xml((std::istreambuf_iterator<char>(in)), {});
  const size_t seed = xml.find("<Param type=\"RichInt\" name=\"seed\"");
  ASSERT_NE(seed, std::string::npos);
  xml.erase(seed, xml.find("/>", seed) + 2 - seed);
  const std::string script = output_path("mlx2022_missing.mlx");
  std::ofstream(script) << xml;
  const ServerRun run = run_script(MeshLab::V2022, {data_mesh("fandisk")}, script, "mlx2022_missing");
  EXPECT_EQ(run.exit_code, 1) << run.log;
  EXPECT_NE(run.log.find("HHT: Add Gaussian Noise failed: the script does not give parameter 'seed'"),
            std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(run.output));
}

TEST(MeshLab2022, RunnerRefusesAnUnknownFilter) {
  const std::string script = write_script("mlx2022_unknown", " <filter name=\"HHT: No Such Filter\"/>\n");
  const ServerRun run = run_script(MeshLab::V2022, {data_mesh("fandisk")}, script, "mlx2022_unknown");
  EXPECT_EQ(run.exit_code, 1) << run.log;
  EXPECT_NE(run.log.find("HHT: No Such Filter failed: no filter of this name is loaded"), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(run.output));
}

}  // namespace
}  // namespace hht::test
