// The edges of the plugin through meshlabserver (issue 10): parameters outside their ranges are
// refused with a message naming the parameter and its range, before any work (no run of
// minutes, nothing saved); a result that moved vertices farther than the bounding-box diagonal is
// refused; coordinates of about 1e30 and 1e-20 give the scaled result of the unscaled mesh; faces
// oriented against their neighbours give the result of the coherently oriented mesh.
#include "meshlabserver_harness.h"

#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/mesh_checks.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_off.h>

#include <chrono>
#include <filesystem>

namespace hht::test {
namespace {

struct Refusal {
  std::string tag;
  std::string script;
  std::vector<std::pair<std::string, std::string>> overrides;
  std::string message;  // part of the expected message
};

void PrintTo(const Refusal& r, std::ostream* os) { *os << r.tag; }

class ExtremeParameter : public ::testing::TestWithParam<Refusal> {};

TEST_P(ExtremeParameter, RefusedAtOnceWithItsRange) {
  const Refusal& r = GetParam();
  const auto start = std::chrono::steady_clock::now();
  const ServerRun run = run_script(MeshLab::V2020, {data_mesh("fandisk")}, chain_scripts(r.tag, {r.script}, r.overrides),
                                   r.tag);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(run.exit_code, 0) << run.log;
  EXPECT_NE(run.log.find("failed: Nothing was changed: " + r.message), std::string::npos) << run.log;
  EXPECT_FALSE(std::filesystem::exists(run.output)) << "a refused filter saved " << run.output;
  EXPECT_LT(seconds, 60) << "refusing took " << seconds << " s";
}

const Refusal kRefusals[] = {
    // the cases: minutes of work, or vertices moved by 1e5 (lambda) and 3e7 (gain) on a mesh of size 1.5
    {"cycles_100000", "enhance.mlx", {{"cycles", "100000"}}, "cycles must lie in [1, 100]"},
    {"lambda_1e-12", "enhance.mlx", {{"lambda", "1e-12"}}, "lambda must lie in [0.0001, 10000]"},
    {"gain_1e9", "enhance.mlx", {{"gain", "1e9"}}, "the gain must lie in [0, 100]"},
    {"imf_999", "hilbert_spectra.mlx", {{"output", "0"}, {"imf", "999"}, {"histogramFile", ""}},
     "the decomposition has"},
    {"max_sifts", "smooth.mlx", {{"maxSifts", "1000000"}}, "maxSifts must lie in [1, 1000]"},
    {"denoise_cycles", "denoise.mlx", {{"cycles", "100000"}}, "cycles must lie in [1, 100]"},
    {"denoise_passes", "denoise.mlx", {{"refineNormalPasses", "100000"}}, "refineNormalPasses must lie in [0, 1000]"},
    {"tries", "hamiltonian_cycle.mlx", {{"tries", "100000"}}, "tries must lie in [1, 100]"},
    {"ramp", "curvature_signal.mlx", {{"rampPercentile", "80"}}, "the colour ramp clipping must lie in [0, 50]"},
    {"bins", "hilbert_spectra.mlx", {{"bins", "0"}}, "the histogram bins must lie in [1, 10000]"},
    {"noise_sigma", "add_noise.mlx", {{"sigmaPercent", "1e6"}}, "sigma must lie in [0, 1000]"},
    {"noise_share", "add_noise.mlx", {{"sharePercent", "150"}}, "share of vertices moved must lie in [0, 100]"},
    {"bilateral_radius", "bilateral.mlx", {{"sigmaC", "1000"}}, "sigma_c must lie in [0.01, 10]"},
    {"nlm_radius", "nonlocal_means.mlx", {{"eta1", "1e6"}}, "eta1 must lie in [0.01, 10]"},
    {"nlm_iterations", "nonlocal_means.mlx", {{"iterations", "1000000"}}, "iterations must lie in [0, 1000]"},
    {"surface_emd_lambda", "surface_emd_smooth.mlx", {{"lambda", "1e-9"}}, "lambda must lie in [0.0001, 10000]"},
    {"centric_angle", "feature_centric_emd.mlx", {{"featureAngle", "720"}}, "the feature angle must lie in [0, 180]"},
    {"centric_passes", "feature_centric_emd.mlx", {{"normalFilterIterations", "-3"}},
     "normalFilterIterations must lie in [0, 1000]"},
    {"guided_rounds", "guided_denoise.mlx", {{"rounds", "1000000"}}, "rounds must lie in [1, 100]"},
    {"adaptive_strength", "smooth.mlx", {{"strength", "1e9"}}, "the strength must lie in [0.1, 10]"},
};

INSTANTIATE_TEST_SUITE_P(Fandisk, ExtremeParameter, ::testing::ValuesIn(kRefusals),
                         [](const ::testing::TestParamInfo<Refusal>& info) {
                           std::string name = info.param.tag;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// Fandisk scaled by `scale`, as a PLY in the test's folder.
std::string scaled_fandisk(double scale, const std::string& name) {
  TriMesh m;
  EXPECT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh("fandisk").c_str()), 0);
  for (auto& v : m.vert) v.P() *= scale;
  const std::string path = output_path(name + ".ply");
  EXPECT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, path.c_str(), 0, true), 0);
  return path;
}

Positions positions_of(const ServerRun& run) {
  TriMesh m;
  load(run, m);
  Positions p;
  Faces f;
  mesh_to_arrays(m, p, f);
  return p;
}

// Each script on Fandisk at about 1e30 and 1e-20 gives the result at scale 1, scaled: finite, and
// the same up to single precision. The scales are powers of two (2^100 = 1.3e30, 2^-66 = 1.4e-20)
// so that the float input is exactly the scaled Fandisk: the EMD's choice of extrema follows
// rounding differences of 1e-7, which a scale like 1e30 would bring in. (denoise.mlx at 1e30
// wrote non-finite positions.)
class ExtremeScale : public ::testing::TestWithParam<std::string> {};

TEST_P(ExtremeScale, ScaledMeshGivesTheScaledResult) {
  const std::string script = GetParam();
  const std::string tag = script.substr(0, script.find('.'));
  const ServerRun reference = run_script(MeshLab::V2020, {data_mesh("fandisk")}, resource(script), tag + "_1");
  const Positions expected = positions_of(reference);
  ASSERT_GT(expected.rows(), 0);
  const double diagonal = bounding_box_diagonal(expected);
  for (double scale : {0x1p100, 0x1p-66}) {
    const std::string name = tag + (scale > 1 ? "_2e100" : "_2e-66");
    const ServerRun run = run_script(MeshLab::V2020, {scaled_fandisk(scale, name + "_input")}, resource(script), name);
    const Positions result = positions_of(run);
    ASSERT_EQ(result.rows(), expected.rows()) << name;
    EXPECT_TRUE(result.allFinite()) << name;
    const double difference = (result / scale - expected).rowwise().norm().maxCoeff();
    EXPECT_LT(difference, 1e-5 * diagonal) << name << ": the scaled run differs from the unscaled one by "
                                           << difference / diagonal << " diagonals";
  }
}

INSTANTIATE_TEST_SUITE_P(Scripts, ExtremeScale,
                         ::testing::Values("denoise.mlx", "smooth.mlx", "enhance.mlx", "guided_denoise.mlx", "bilateral_normal_denoise.mlx",
                                           "bilateral.mlx", "nonlocal_means.mlx", "surface_emd_smooth.mlx"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

// Fandisk with 10% isotropic noise, every third face's vertex order reversed when `misoriented`,
// as a PLY in the test's folder; its faces in `faces`.
std::string noisy_fandisk(bool misoriented, const std::string& name, Faces& faces) {
  TriMesh m;
  EXPECT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh("fandisk").c_str()), 0);
  Positions p;
  mesh_to_arrays(m, p, faces);
  set_vertex_positions(m, add_gaussian_noise(p, faces, 10, NoiseDirection::Isotropic, 7));
  if (misoriented)
    for (int f = 0; f < static_cast<int>(m.face.size()); f += 3) {
      std::swap(m.face[f].V(1), m.face[f].V(2));
      std::swap(faces(f, 1), faces(f, 2));
    }
  const std::string path = output_path(name + ".ply");
  EXPECT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, path.c_str(), 0, true), 0);
  return path;
}

// `run`'s saved positions are `reference`'s, to 1e-9 of the diagonal; `what` says what differs if not.
void expect_same_positions(const ServerRun& reference, const ServerRun& run, const std::string& what) {
  const Positions expected = positions_of(reference), result = positions_of(run);
  ASSERT_GT(expected.rows(), 0);
  ASSERT_EQ(result.rows(), expected.rows());
  const double difference = (result - expected).rowwise().norm().maxCoeff();
  EXPECT_LT(difference, 1e-9 * bounding_box_diagonal(expected)) << what << " by " << difference;
}

// Each script that moves vertices, on a noisy Fandisk with a third of its faces oriented against
// their neighbours (as STL exports and some scans come), gives the result it gives on the same
// mesh coherently oriented, says so in the log, and leaves the mesh's faces as they were. Before,
// the normals of such a mesh pointed in and out at random (libcgal-demo's blobby-shuffled at 10%:
// E_a 14.32 degrees through smooth.mlx against 3.15 on blobby, the same surface oriented).
class MisorientedFaces : public ::testing::TestWithParam<std::string> {};

TEST_P(MisorientedFaces, GiveTheCoherentMeshsResult) {
  const std::string script = GetParam();
  const std::string tag = script.substr(0, script.find('.'));
  Faces coherent, misoriented;
  const ServerRun reference =
      run_script(MeshLab::V2020, {noisy_fandisk(false, tag + "_coherent_input", coherent)}, resource(script), tag + "_coherent");
  const ServerRun run = run_script(MeshLab::V2020, {noisy_fandisk(true, tag + "_misoriented_input", misoriented)},
                                   resource(script), tag + "_misoriented");
  expect_same_positions(reference, run, "the misoriented mesh's result differs from the coherent one's");
  const int flipped = static_cast<int>((coherent.rows() + 2) / 3);
  EXPECT_NE(run.log.find("Orientation: " + std::to_string(flipped) + " of " + std::to_string(coherent.rows()) + " faces"),
            std::string::npos)
      << run.log;
  EXPECT_EQ(reference.log.find("Orientation:"), std::string::npos) << "a coherent mesh has nothing to say";
  TriMesh saved;
  load(run, saved);
  Positions p;
  Faces faces;
  mesh_to_arrays(saved, p, faces);
  EXPECT_TRUE(faces == misoriented) << "the saved mesh's faces are not the input's";
}

INSTANTIATE_TEST_SUITE_P(Scripts, MisorientedFaces,
                         ::testing::Values("smooth.mlx", "denoise.mlx", "enhance.mlx", "guided_denoise.mlx",
                                           "bilateral_normal_denoise.mlx", "bilateral.mlx", "nonlocal_means.mlx",
                                           "surface_emd_smooth.mlx", "feature_centric_emd.mlx"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

// Noisy Fandisk with faces repeated (every 50th face given again, half of the repeats reversed, and
// face 0 given twice beside a neighbour given three times, as exports and merged files repeat faces)
// gives the result of Fandisk itself through each script, says so in the log and keeps the repeats.
// Before, the pairing at the edge of five faces left it an edge of three after the split, and every
// script refused the mesh ("1 non-manifold edges ... repair them first"; a fuzz of libcgal-demo's
// bull with 5% of its faces repeated found it).
class RepeatedFaces : public ::testing::TestWithParam<std::string> {};

TEST_P(RepeatedFaces, AreLeftOutOfTheFiltersCopy) {
  const std::string script = GetParam();
  const std::string tag = script.substr(0, script.find('.'));
  Faces faces;
  const ServerRun reference = run_script(MeshLab::V2020, {noisy_fandisk(false, tag + "_input", faces)}, resource(script), tag);
  TriMesh m;
  bool has_quality = false;
  ASSERT_TRUE(load_ply(output_path(tag + "_input.ply"), m, has_quality));
  const Eigen::Index nf = faces.rows();
  std::vector<Eigen::Index> repeats;
  for (Eigen::Index f = 0; f < nf; f += 50) repeats.push_back(f);
  Eigen::Index neighbour = 1;
  const auto shared = [&](Eigen::Index g) {
    int count = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) count += faces(0, i) == faces(g, j);
    return count;
  };
  while (shared(neighbour) != 2) ++neighbour;
  repeats.insert(repeats.end(), {neighbour, neighbour});  // face 0 is among every 50th
  auto fi = vcg::tri::Allocator<TriMesh>::AddFaces(m, repeats.size());
  for (size_t k = 0; k < repeats.size(); ++k, ++fi)
    for (int i = 0; i < 3; ++i) fi->V(k % 2 ? 2 - i : i) = &m.vert[faces(repeats[k], i)];
  const std::string input = output_path(tag + "_repeated_input.ply");
  ASSERT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, input.c_str(), 0, true), 0);
  const ServerRun run = run_script(MeshLab::V2020, {input}, resource(script), tag + "_repeated");
  ASSERT_EQ(run.exit_code, 0) << run.log;
  expect_same_positions(reference, run, "the result with repeats differs from Fandisk's");
  EXPECT_NE(run.log.find("Repeated faces: " + std::to_string(repeats.size()) + " of " +
                         std::to_string(nf + static_cast<Eigen::Index>(repeats.size())) + " faces"),
            std::string::npos)
      << run.log;
  TriMesh saved;
  load(run, saved);
  EXPECT_EQ(saved.FN(), m.FN()) << "the repeats were not kept";
}

INSTANTIATE_TEST_SUITE_P(Scripts, RepeatedFaces,
                         ::testing::Values("smooth.mlx", "denoise.mlx", "enhance.mlx", "guided_denoise.mlx"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

// Noisy Fandisk written as a triangle soup (every face with three vertices of its own, as some
// exporters write meshes and MeshLab keeps them) goes through smooth.mlx and denoise.mlx as the
// joined mesh does: its E_a against the clean Fandisk within 10% of the joined mesh's result and
// at least a quarter under the noisy input's, every copy of a vertex moved to the same place (no gaps open),
// and the log says what was merged. Before, the noise estimate read no interior vertex ("noise
// 0.0%") and the mesh was left as it was; given the noise, each face shrank on its own.
class TriangleSoup : public ::testing::TestWithParam<std::string> {};

// `faces` over `positions`, written to `tag`_joined_input.ply and, every face with three vertices of
// its own (vertex 3 f + k is corner k of face f), to `tag`_soup_input.ply.
std::pair<std::string, std::string> joined_and_soup(const Positions& positions, const Faces& faces, const std::string& tag) {
  TriMesh m;
  auto mv = vcg::tri::Allocator<TriMesh>::AddVertices(m, positions.rows());
  for (Eigen::Index i = 0; i < positions.rows(); ++i, ++mv)
    mv->P() = TriMesh::CoordType(positions(i, 0), positions(i, 1), positions(i, 2));
  auto mf = vcg::tri::Allocator<TriMesh>::AddFaces(m, faces.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f, ++mf)
    for (int k = 0; k < 3; ++k) mf->V(k) = &m.vert[faces(f, k)];
  const std::string joined_path = output_path(tag + "_joined_input.ply");
  EXPECT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, joined_path.c_str(), 0, true), 0);
  TriMesh soup;
  const int nf = static_cast<int>(faces.rows());
  auto vi = vcg::tri::Allocator<TriMesh>::AddVertices(soup, 3 * nf);
  auto fi = vcg::tri::Allocator<TriMesh>::AddFaces(soup, nf);
  for (int f = 0; f < nf; ++f, ++fi)
    for (int k = 0; k < 3; ++k, ++vi) {
      vi->P() = TriMesh::CoordType(positions(faces(f, k), 0), positions(faces(f, k), 1), positions(faces(f, k), 2));
      fi->V(k) = &*vi;
    }
  const std::string soup_path = output_path(tag + "_soup_input.ply");
  EXPECT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(soup, soup_path.c_str(), 0, true), 0);
  return {joined_path, soup_path};
}

Faces fandisk_faces(Positions& positions) {
  TriMesh m;
  EXPECT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(m, data_mesh("fandisk").c_str()), 0);
  Faces faces;
  mesh_to_arrays(m, positions, faces);
  return faces;
}

// `clean` with noise of `percent`, joined and as a soup, through `script`: every copy of a vertex
// moved alike, the soup's E_a within 10% of the joined mesh's and under 0.75 of the noisy input's,
// the log's seam line and `log_line`.
void soup_is_filtered_as_joined(const std::string& script, const Positions& clean, const Faces& faces, double percent,
                                const std::string& tag, const std::string& log_line) {
  const int nf = static_cast<int>(faces.rows());
  const Positions noisy = add_gaussian_noise(clean, faces, percent, NoiseDirection::Isotropic, 7);
  const auto [joined_path, soup_path] = joined_and_soup(noisy, faces, tag);

  const ServerRun joined = run_script(MeshLab::V2020, {joined_path}, resource(script), tag + "_joined");
  const ServerRun run = run_script(MeshLab::V2020, {soup_path}, resource(script), tag + "_soup");
  const Positions joined_result = positions_of(joined), soup_result = positions_of(run);
  ASSERT_EQ(soup_result.rows(), 3 * nf) << run.log;
  // The soup's result as positions of the joined mesh's vertices, each copy checked against the first.
  Positions as_joined = Positions::Constant(clean.rows(), 3, std::nan(""));
  int apart = 0;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = soup_result.row(3 * f + k);
      if (std::isnan(as_joined(faces(f, k), 0)))
        as_joined.row(faces(f, k)) = p;
      else
        apart += as_joined.row(faces(f, k)) != p;
    }
  EXPECT_EQ(apart, 0) << "copies of a vertex moved apart: the seams opened";
  const double noisy_error = mean_face_normal_error_degrees(noisy, clean, faces);
  const double joined_error = mean_face_normal_error_degrees(joined_result, clean, faces);
  const double soup_error = mean_face_normal_error_degrees(as_joined, clean, faces);
  EXPECT_LT(soup_error, 0.75 * noisy_error) << "left about as noisy as it came";
  EXPECT_LT(std::abs(soup_error - joined_error), 0.1 * joined_error)
      << "soup " << soup_error << " against the joined mesh's " << joined_error << " degrees (noisy " << noisy_error << ")";
  EXPECT_NE(run.log.find("Seams: " + std::to_string(3 * nf - clean.rows()) + " of " + std::to_string(3 * nf) + " vertices"),
            std::string::npos)
      << run.log;
  EXPECT_NE(run.log.find(log_line), std::string::npos) << run.log;
}

TEST_P(TriangleSoup, IsFilteredAsTheJoinedMesh) {
  const std::string script = GetParam();
  Positions clean;
  const Faces faces = fandisk_faces(clean);
  soup_is_filtered_as_joined(script, clean, faces, 10, script.substr(0, script.find('.')), "Seams: ");
}

INSTANTIATE_TEST_SUITE_P(Scripts, TriangleSoup, ::testing::Values("smooth.mlx", "denoise.mlx"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

// A soup of a sphere with a fin on six of its edges: merged, the merge makes those edges of three
// faces again, which the filter cuts as on the joined mesh (item 44). Before, the merge refused to
// make such edges and the soup was filtered face by face (smooth.mlx left it as noisy as it came).
class TriangleSoupWithAFin : public ::testing::TestWithParam<std::string> {};

TEST_P(TriangleSoupWithAFin, IsFilteredAsTheJoinedMesh) {
  const std::string script = GetParam();
  const ArrayMesh finned = finned_sphere(3, 6);
  soup_is_filtered_as_joined(script, finned.positions, finned.faces, 20, "fin_" + script.substr(0, script.find('.')),
                             "Non-manifold: 6 edges shared by more than two faces");
}

INSTANTIATE_TEST_SUITE_P(Scripts, TriangleSoupWithAFin, ::testing::Values("smooth.mlx", "denoise.mlx"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

// The analyses that write vertex quality read a soup as the joined mesh too: the curvature signal
// of noisy Fandisk's soup gives every copy of a vertex the joined mesh's value there (the same to
// single precision); without the merge each face alone gave boundary values (all of them off).
TEST(TriangleSoupAnalysis, CurvatureSignalIsTheJoinedMeshs) {
  Positions clean;
  const Faces faces = fandisk_faces(clean);
  const int nf = static_cast<int>(faces.rows());
  const auto [joined_path, soup_path] =
      joined_and_soup(add_gaussian_noise(clean, faces, 10, NoiseDirection::Isotropic, 7), faces, "curvature");
  const ServerRun joined = run_script(MeshLab::V2020, {joined_path}, resource("curvature_signal.mlx"), "curvature_joined");
  const ServerRun run = run_script(MeshLab::V2020, {soup_path}, resource("curvature_signal.mlx"), "curvature_soup");
  TriMesh a, b;
  bool qa = false, qb = false;
  ASSERT_TRUE(load_ply(joined.output, a, qa) && qa) << joined.log;
  ASSERT_TRUE(load_ply(run.output, b, qb) && qb) << run.log;
  ASSERT_EQ(b.vn, 3 * nf);
  double largest = 0, worst = 0;
  for (int v = 0; v < a.vn; ++v) largest = std::max(largest, std::abs(double(a.vert[v].Q())));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(double(b.vert[3 * f + k].Q()) - double(a.vert[faces(f, k)].Q())));
  EXPECT_LT(worst, 1e-5 * largest) << "a copy's curvature differs from the joined mesh's by " << worst;
  EXPECT_NE(run.log.find("Seams: "), std::string::npos) << run.log;
}

// A noisy mesh with a non-manifold part through `script`: the saved mesh has the input's faces, its
// result is nearer the clean mesh than the noisy input (E_a; the enhancement sharpens the noise),
// and the log has `log_line`.
void filters_nonmanifold_mesh(const std::string& script, const ArrayMesh& clean, const std::string& log_line) {
  const std::string tag = script.substr(0, script.find('.')) + "_" + std::to_string(clean.vertices());
  const Positions noisy = add_gaussian_noise(clean.positions, clean.faces, 20, NoiseDirection::Isotropic, 5);
  TriMesh m;
  auto vi = vcg::tri::Allocator<TriMesh>::AddVertices(m, noisy.rows());
  for (Eigen::Index i = 0; i < noisy.rows(); ++i, ++vi) vi->P() = TriMesh::CoordType(noisy(i, 0), noisy(i, 1), noisy(i, 2));
  auto fi = vcg::tri::Allocator<TriMesh>::AddFaces(m, clean.faces.rows());
  for (Eigen::Index f = 0; f < clean.faces.rows(); ++f, ++fi)
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[clean.faces(f, k)];
  const std::string input = output_path(tag + "_input.ply");
  ASSERT_EQ(vcg::tri::io::ExporterPLY<TriMesh>::Save(m, input.c_str(), 0, true), 0);
  const ServerRun run = run_script(MeshLab::V2020, {input}, resource(script), tag);
  ASSERT_EQ(run.exit_code, 0) << run.log;
  TriMesh saved;
  load(run, saved);
  Positions result;
  Faces faces;
  mesh_to_arrays(saved, result, faces);
  ASSERT_EQ(result.rows(), noisy.rows());
  EXPECT_TRUE(faces == clean.faces) << "the saved mesh's faces are not the input's";
  EXPECT_TRUE(result.allFinite());
  if (script != "enhance.mlx") {
    EXPECT_LT(mean_face_normal_error_degrees(result, clean.positions, faces),
              mean_face_normal_error_degrees(noisy, clean.positions, faces));
  }
  EXPECT_NE(run.log.find(log_line), std::string::npos) << run.log;
}

std::string script_name(const ::testing::TestParamInfo<std::string>& info) {
  return info.param.substr(0, info.param.find('.'));
}

const auto kScriptsOnAManifold =
    ::testing::Values("smooth.mlx", "denoise.mlx", "enhance.mlx", "guided_denoise.mlx");

// Two noisy spheres touching at one vertex (two fans of faces meet there: a non-manifold vertex, as
// scans and exports often hold a few) go through the scripts built on the Hamiltonian cycle and on
// guided filtering, the touching vertex still shared after. They refused such a mesh before ("1
// non-manifold vertices ... repair them first").
class NonManifoldVertex : public ::testing::TestWithParam<std::string> {};

TEST_P(NonManifoldVertex, IsSplitForTheFilterAndJoinedAgain) {
  filters_nonmanifold_mesh(GetParam(), touching_spheres(3), "Non-manifold: 1 vertex where");
}

INSTANTIATE_TEST_SUITE_P(Scripts, NonManifoldVertex, kScriptsOnAManifold, script_name);

// A noisy sphere with a fin standing on six of its edges (each shared by three faces, as exports
// with internal or dangling faces have them) goes through the same scripts, the fin still on its
// edges after. They refused such a mesh before ("6 non-manifold edges ... repair them first").
class NonManifoldEdge : public ::testing::TestWithParam<std::string> {};

TEST_P(NonManifoldEdge, IsCutForTheFilterAndJoinedAgain) {
  filters_nonmanifold_mesh(GetParam(), finned_sphere(3, 6), "Non-manifold: 6 edges shared by more than two faces");
}

INSTANTIATE_TEST_SUITE_P(Scripts, NonManifoldEdge, kScriptsOnAManifold, script_name);

}  // namespace
}  // namespace hht::test
