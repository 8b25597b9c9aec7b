// The plugin as a user runs it: the shipped scripts through the real meshlabserver.
#include "meshlabserver_harness.h"

#include "evaluation/gaussian_noise.h"
#include "mesh/mean_curvature.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_off.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

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

// The script's default takes L over the intrinsic Delaunay triangles; `intrinsicDelaunay` false over
// Fandisk's own (746 of its edges are not Delaunay, so the two differ).
TEST(Meshlabserver, CurvatureSignalMatchesTheLibrary) {
  TriMesh input;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(input, data_mesh("fandisk").c_str()), 0);
  Positions positions;
  Faces faces;
  mesh_to_arrays(input, positions, faces);
  for (const bool intrinsic : {true, false}) {
    const ServerRun run =
        intrinsic ? run_meshlabserver(data_mesh("fandisk"), resource("curvature_signal.mlx"), "curvature_fandisk")
                  : run_meshlabserver(data_mesh("fandisk"),
                                      chain_scripts("curvature_own", {"curvature_signal.mlx"}, {{"intrinsicDelaunay", "false"}}),
                                      "curvature_fandisk_own");
    TriMesh m;
    load_output(run, m);
    MeanCurvature expected, other;
    std::string error;
    const auto triangles = intrinsic ? LaplacianTriangles::IntrinsicDelaunay : LaplacianTriangles::Mesh;
    ASSERT_TRUE(mean_curvature(positions, faces, expected, error, triangles));
    ASSERT_TRUE(mean_curvature(positions, faces, other, error,
                               intrinsic ? LaplacianTriangles::Mesh : LaplacianTriangles::IntrinsicDelaunay));
    ASSERT_EQ(m.vn, expected.signal.size());
    // MeshLab runs on floats: compare relative to the signal's scale
    const double scale = expected.signal.cwiseAbs().maxCoeff();
    for (int v = 0; v < m.vn; ++v) ASSERT_NEAR(m.vert[v].Q(), expected.signal[v], 1e-3 * scale) << v << " " << intrinsic;
    EXPECT_GT((other.signal - expected.signal).cwiseAbs().maxCoeff(), 0.05 * scale) << "the two must differ";
    EXPECT_NE(run.log.find(intrinsic ? "Laplacian over the intrinsic Delaunay triangulation: " : "Curvature signal"),
              std::string::npos)
        << run.log;
    std::set<unsigned> colours;
    for (const auto& v : m.vert) colours.insert(*reinterpret_cast<const unsigned*>(&v.C()[0]));
    EXPECT_GT(colours.size(), 100u) << "the colour ramp should show the signal";
  }
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
const BadInput kNaN{"nan", "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
                    "NaN"};

// A ring of quads closed with a half twist.
const std::string kMoebiusOff = [] {
  const int steps = 24;
  std::ostringstream off;
  off << "OFF\n" << 2 * steps << " " << 2 * steps << " 0\n";
  for (int i = 0; i < steps; ++i) {
    const double a = 2 * M_PI * i / steps, twist = a / 2;
    for (double w : {-0.3, 0.3})
      off << (1 + w * std::cos(twist)) * std::cos(a) << " " << (1 + w * std::cos(twist)) * std::sin(a) << " "
          << w * std::sin(twist) << "\n";
  }
  for (int i = 0; i < steps; ++i) {
    const bool last = i + 1 == steps;
    const int a = 2 * i, b = 2 * i + 1, c = last ? 1 : 2 * i + 2, d = last ? 0 : 2 * i + 3;
    off << "3 " << a << " " << b << " " << d << "\n3 " << a << " " << d << " " << c << "\n";
  }
  return off.str();
}();
const BadInput kMoebius{"moebius", kMoebiusOff.c_str(), "not orientable"};

// A bumpy grid with six faces of no area (a vertex moved onto the midpoint of its face's opposite
// edge, as triangulated polygons leave them): the spectral filter's rebuild stalls on their
// cotangent weights, and the message names them and the cleaning filters that remove them.
const std::string kDegenerateOff = [] {
  const int n = 16;
  std::vector<std::array<double, 3>> v;
  std::vector<std::array<int, 3>> f;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = 4.0 * i / (n - 1), y = 4.0 * j / (n - 1);
      v.push_back({x, y, 0.3 * std::sin(x) * std::cos(y)});
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      f.push_back({a, a + 1, a + n + 1});
      f.push_back({a, a + n + 1, a + n});
    }
  for (int k : {40, 90, 140, 200, 260, 330})
    for (int c = 0; c < 3; ++c) v[f[k][2]][c] = 0.5 * (v[f[k][0]][c] + v[f[k][1]][c]);
  std::ostringstream off;
  off.precision(17);
  off << "OFF\n" << v.size() << " " << f.size() << " 0\n";
  for (const auto& p : v) off << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const auto& t : f) off << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return off.str();
}();
const BadInput kDegenerate{"degenerate", kDegenerateOff.c_str(), "6 degenerate faces"};

INSTANTIATE_TEST_SUITE_P(Rebuild, MeshlabserverBadInput,
                         ::testing::Combine(::testing::Values(kDegenerate), ::testing::Values("enhance.mlx")));
INSTANTIATE_TEST_SUITE_P(Cycle, MeshlabserverBadInput,
                         ::testing::Combine(::testing::Values(kCloud, kNaN, kMoebius),
                                            ::testing::Values("hamiltonian_cycle.mlx")));
INSTANTIATE_TEST_SUITE_P(Curvature, MeshlabserverBadInput,
                         ::testing::Combine(::testing::Values(kCloud, kNaN), ::testing::Values("curvature_signal.mlx")));

// Every shipped script runs as it is on the default model.
class ShippedScript : public ::testing::TestWithParam<std::string> {};

// compare.mlx compares two different meshes: Fandisk (the reference) and a noisy copy. The
// noise-adaptive scripts (denoise.mlx, smooth.mlx) leave a clean CAD mesh as it is
// (MeshlabserverDenoise.CleanCadExportIsLeftAsItIs), so they get the noisy copy.
TEST_P(ShippedScript, RunsOnFandisk) {
  const std::string stem = fs::path(GetParam()).stem().string();
  std::vector<std::string> inputs{data_mesh("fandisk")};
  TriMesh mesh;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(mesh, data_mesh("fandisk").c_str()), 0);
  Positions input;
  Faces faces;
  mesh_to_arrays(mesh, input, faces);
  const bool noise_adaptive = stem == "denoise" || stem == "smooth";
  if (stem == "compare" || noise_adaptive) {
    input = add_gaussian_noise(input, faces, 10.0, NoiseDirection::Random, 1);
    for (int v = 0; v < mesh.vn; ++v) mesh.vert[v].P() = vcg::Point3d(input(v, 0), input(v, 1), input(v, 2));
    const std::string noisy = output_path("fandisk_noisy_" + stem + ".ply");
    ASSERT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(mesh, noisy.c_str(), 0, false), 0);
    if (noise_adaptive) inputs = {noisy}; else inputs.push_back(noisy);
  }
  const ServerRun run = run_script(MeshLab::V2020, inputs, GetParam(), "script_" + stem);
  EXPECT_EQ(run.log.find("failed"), std::string::npos) << run.log;
  TriMesh out;
  load(run, out);
  ASSERT_EQ(out.vn, input.rows());
  // each script changes the positions or writes a varying quality
  double moved = 0, lowest = out.vert[0].Q(), highest = lowest;
  for (int v = 0; v < out.vn; ++v) {
    const auto& p = out.vert[v].cP();
    moved = std::max(moved, (Eigen::RowVector3d(p[0], p[1], p[2]) - input.row(v)).norm());
    lowest = std::min(lowest, double(out.vert[v].Q()));
    highest = std::max(highest, double(out.vert[v].Q()));
  }
  EXPECT_TRUE(moved > 1e-4 * bbox_diagonal(mesh) || highest > lowest) << "the output is the input";
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
