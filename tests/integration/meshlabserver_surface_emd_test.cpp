// The surface EMD, feature-centric EMD and non-local means filters (issue 8) through meshlabserver.
#include "meshlabserver_harness.h"

#include "evaluation/denoise_metrics.h"
#include "mesh/mean_curvature.h"
#include "filters/surface_emd.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/import_off.h>

namespace hht::test {
namespace {

void arrays(const TriMesh& m, Positions& p, Faces& f) { mesh_to_arrays(m, p, f); }

double normal_error_against_fandisk(const TriMesh& result) {
  TriMesh truth;
  EXPECT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(truth, data_mesh("fandisk").c_str()), 0);
  Positions p, q;
  Faces f, g;
  arrays(truth, p, f);
  arrays(result, q, g);
  EXPECT_EQ(f, g);
  return mean_face_normal_error_degrees(q, p, f);
}

TEST(MeshlabserverSurfaceEmd, FirstImfIntoQualityIsTheLibrarys) {
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), resource("surface_emd.mlx"), "surface_emd_imf");
  TriMesh out, in;
  load(run, out);
  EXPECT_NE(run.log.find("Surface EMD of the curvature signal"), std::string::npos) << run.log;
  ASSERT_EQ(vcg::tri::io::ImporterOFF<TriMesh>::Open(in, data_mesh("fandisk").c_str()), 0);
  Positions p;
  Faces f;
  arrays(in, p, f);
  MeanCurvature curvature;
  std::string error;
  ASSERT_TRUE(mean_curvature(p, f, curvature, error)) << error;
  SurfaceEmdResult r;
  ASSERT_TRUE(surface_emd(p, f, curvature.signal, {}, r, error)) << error;
  ASSERT_FALSE(r.imfs.empty());
  // MeshLab holds positions in float: the signal differs by rounding, far below the IMF's size.
  double difference = 0, size = 0;
  for (int i = 0; i < out.vn; ++i) {
    difference += std::pow(out.vert[i].Q() - r.imfs[0][i], 2);
    size += std::pow(r.imfs[0][i], 2);
  }
  EXPECT_LT(std::sqrt(difference / size), 0.01);
  EXPECT_GT(size, 0.0);
}

TEST(MeshlabserverSurfaceEmd, SmoothingBlursFandiskAndTheFeatureCentricVariantDoesNot) {
  TriMesh noisy, plain, centric;
  load(run_meshlabserver(data_mesh("fandisk"), chain_scripts("semd_noise", {"add_noise.mlx"}), "semd_noisy"), noisy);
  load(run_meshlabserver(data_mesh("fandisk"), chain_scripts("semd_plain", {"add_noise.mlx", "surface_emd_smooth.mlx"}),
                         "semd_plain"), plain);
  const ServerRun run = run_meshlabserver(
      data_mesh("fandisk"), chain_scripts("semd_centric", {"add_noise.mlx", "feature_centric_emd.mlx"}), "semd_centric");
  load(run, centric);
  EXPECT_NE(run.log.find("feature vertices kept out of the envelopes"), std::string::npos) << run.log;
  const double before = normal_error_against_fandisk(noisy);
  EXPECT_GT(normal_error_against_fandisk(plain), before);  // the paper's Fig. 10b
  EXPECT_LT(normal_error_against_fandisk(centric), before);
}

TEST(MeshlabserverSurfaceEmd, NonLocalMeansSmoothsANoisyModel) {
  TriMesh noisy, smoothed;
  load(run_meshlabserver(data_mesh("armadillo"), chain_scripts("nlm_noise", {"add_noise.mlx"}), "nlm_noisy"), noisy);
  load(run_meshlabserver(data_mesh("armadillo"), chain_scripts("nlm", {"add_noise.mlx", "nonlocal_means.mlx"}),
                         "nlm_smoothed"), smoothed);
  EXPECT_LT(mean_dihedral_angle(smoothed), 0.8 * mean_dihedral_angle(noisy));
}

TEST(MeshlabserverSurfaceEmd, QualityWithoutCurvatureCannotBeRebuilt) {
  const std::string script =
      chain_scripts("semd_quality_rebuild", {"curvature_signal.mlx", "surface_emd.mlx"}, {{"source", "1"}, {"output", "2"}});
  const ServerRun run = run_meshlabserver(data_mesh("fandisk"), script, "semd_quality_rebuild");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.log.find("Nothing was changed: the mesh can only be rebuilt from the curvature signal"), std::string::npos)
      << run.log;
}

TEST(MeshlabserverSurfaceEmd, BadInputLeavesNothingBehind) {
  expect_bad_input_refused({"surface_emd.mlx", "surface_emd_smooth.mlx", "feature_centric_emd.mlx", "nonlocal_means.mlx"},
                           "semd_bad");
}

}  // namespace
}  // namespace hht::test
