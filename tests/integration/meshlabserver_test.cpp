// The plugin as a user runs it: the shipped scripts through the real meshlabserver.
#include "meshlabserver_harness.h"

#include "mean_curvature.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/import_off.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace hht::test {
namespace {

namespace fs = std::filesystem;

void load_output(const ServerRun& run, TriMesh& m) {
  bool has_quality = false;
  EXPECT_EQ(run.exit_code, 0) << run.log;
  EXPECT_TRUE(load_ply(run.output, m, has_quality)) << run.output;
  EXPECT_TRUE(has_quality) << "no vertex quality saved";
}

TEST(Meshlabserver, HamiltonianCycleOnFandisk) {
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), resource("hamiltonian_cycle.mlx"), "cycle_fandisk");
  TriMesh m;
  load_output(run, m);
  ASSERT_EQ(m.vn, 6475);
  Positions positions;
  Faces faces;
  mesh_to_arrays(m, positions, faces);
  // quality: 0..k-1 each exactly once along the cycle, -1 elsewhere
  std::vector<int> at(m.vn, -1);
  int on_cycle = 0;
  for (int v = 0; v < m.vn; ++v) {
    const double q = m.vert[v].Q();
    if (q < 0) {
      EXPECT_EQ(q, -1.0);
      continue;
    }
    ASSERT_LT(q, m.vn);
    ASSERT_EQ(at[static_cast<int>(q)], -1) << "position " << q << " twice";
    at[static_cast<int>(q)] = v;
    ++on_cycle;
  }
  EXPECT_GE(on_cycle, 0.999 * m.vn);
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      edges.insert({std::min(faces(f, k), faces(f, (k + 1) % 3)), std::max(faces(f, k), faces(f, (k + 1) % 3))});
  for (int i = 0; i < on_cycle; ++i) {
    ASSERT_GE(at[i], 0) << "position " << i << " missing";
    const int a = at[i], b = at[(i + 1) % on_cycle];
    EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)})) << "cycle step " << i << " is not a mesh edge";
  }
  EXPECT_NE(run.log.find("on the cycle"), std::string::npos);
}

TEST(Meshlabserver, CycleLayerIsAnEdgePolyline) {
  const std::string script = write_script("cycle_layer",
      " <filter name=\"HHT: Hamiltonian Cycle\">\n"
      "  <Param type=\"RichInt\" name=\"seed\" value=\"3\"/>\n"
      "  <Param type=\"RichInt\" name=\"tries\" value=\"2\"/>\n"
      "  <Param type=\"RichBool\" name=\"repair\" value=\"true\"/>\n"
      "  <Param type=\"RichBool\" name=\"addCycleLayer\" value=\"true\"/>\n"
      " </filter>\n"
      " <filter name=\"Change the current layer\">\n"
      "  <Param type=\"RichMesh\" name=\"layer\" value=\"1\"/>\n"
      " </filter>\n");
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), script, "cycle_layer");
  ASSERT_EQ(run.exit_code, 0) << run.log;
  // the saved current layer is the polyline: one vertex per cycle vertex, no faces
  TriMesh m;
  bool has_quality = false;
  ASSERT_TRUE(load_ply(run.output, m, has_quality));
  EXPECT_GE(m.vn, 0.999 * 6475);
  EXPECT_EQ(m.fn, 0);
}

TEST(Meshlabserver, CurvatureSignalMatchesTheLibrary) {
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), resource("curvature_signal.mlx"), "curvature_fandisk");
  TriMesh m;
  load_output(run, m);
  TriMesh input;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(input, data_mesh("fandisk").c_str()), 0);
  Positions positions;
  Faces faces;
  mesh_to_arrays(input, positions, faces);
  MeanCurvature expected;
  std::string error;
  ASSERT_TRUE(mean_curvature(positions, faces, expected, error));
  ASSERT_EQ(m.vn, expected.signal.size());
  // MeshLab runs on floats: compare relative to the signal's scale
  const double scale = expected.signal.cwiseAbs().maxCoeff();
  for (int v = 0; v < m.vn; ++v) ASSERT_NEAR(m.vert[v].Q(), expected.signal[v], 1e-3 * scale) << v;
  std::set<unsigned> colours;
  for (const auto& v : m.vert) colours.insert(*reinterpret_cast<const unsigned*>(&v.C()[0]));
  EXPECT_GT(colours.size(), 100u) << "the colour ramp should show the signal";
}

void write_off(const std::string& path, const std::string& body) { std::ofstream(path) << body; }

struct BadInput {
  const char* name;
  const char* off;
  const char* message;
};

class MeshlabserverBadInput : public ::testing::TestWithParam<std::tuple<BadInput, const char*>> {};

TEST_P(MeshlabserverBadInput, ClearMessageAndNoOutput) {
  const BadInput bad = std::get<0>(GetParam());
  const std::string script = std::get<1>(GetParam());
  const std::string input = output_path(std::string("bad_") + bad.name + ".off");
  write_off(input, bad.off);
  const std::string tag = std::string("bad_") + bad.name + "_" + fs::path(script).stem().string();
  const ServerRun run = run_meshlabserver(input, resource(script), tag);
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.log.find("failed: Nothing was changed"), std::string::npos) << run.log;
  EXPECT_NE(run.log.find(bad.message), std::string::npos) << run.log;
  EXPECT_FALSE(fs::exists(run.output));
  EXPECT_EQ(run.log.find("Segmentation"), std::string::npos);
}

const BadInput kCloud{"cloud", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "no faces"};
const BadInput kFin{"fin",
                    "OFF\n5 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 0 1 4\n",
                    "non-manifold edge"};
const BadInput kNaN{"nan", "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
                    "NaN"};

INSTANTIATE_TEST_SUITE_P(Cycle, MeshlabserverBadInput,
                         ::testing::Combine(::testing::Values(kCloud, kFin, kNaN),
                                            ::testing::Values("hamiltonian_cycle.mlx")));
INSTANTIATE_TEST_SUITE_P(Curvature, MeshlabserverBadInput,
                         ::testing::Combine(::testing::Values(kCloud, kNaN), ::testing::Values("curvature_signal.mlx")));

// Every shipped script runs as it is on the default model.
class ShippedScript : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScript, RunsOnFandisk) {
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), GetParam(), "script_" + fs::path(GetParam()).stem().string());
  EXPECT_EQ(run.exit_code, 0) << run.log;
  EXPECT_TRUE(fs::exists(run.output));
  EXPECT_EQ(run.log.find("failed"), std::string::npos) << run.log;
}

std::vector<std::string> shipped_scripts() {
  std::vector<std::string> scripts;
  for (const auto& entry : fs::directory_iterator(HHT_RESOURCES_DIR))
    if (entry.path().extension() == ".mlx") scripts.push_back(entry.path().string());
  std::sort(scripts.begin(), scripts.end());
  return scripts;
}

INSTANTIATE_TEST_SUITE_P(Resources, ShippedScript, ::testing::ValuesIn(shipped_scripts()),
                         [](const auto& info) { return fs::path(info.param).stem().string(); });

}  // namespace
}  // namespace hht::test
