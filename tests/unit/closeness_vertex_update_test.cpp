#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/closeness_vertex_update.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <string>

namespace hht {
namespace {

// Given the clean mesh's face normals as targets, the global fit takes a noisy fandisk back to
// them (E_a near zero, far below the noisy input's), keeps the vertices' mean where it was, and
// with no iterations returns the input. With the projection step replaced by the identity
// (B_f the face's current centred shape) nothing moves and the first check fails.
TEST(ClosenessVertexUpdate, FitsANoisyMeshToTheCleanNormals) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10, NoiseDirection::Normal, 11);
  const Positions targets = unit_face_normals(m.positions, m.faces);
  Positions fitted;
  std::string error;
  ASSERT_TRUE(fit_vertices_to_normals_with_closeness(noisy, m.faces, targets, 0.001, 20, fitted, error)) << error;
  const double before = mean_face_normal_error_degrees(noisy, m.positions, m.faces);
  const double after = mean_face_normal_error_degrees(fitted, m.positions, m.faces);
  EXPECT_GT(before, 5);
  EXPECT_LT(after, 0.5);  // measured 0.02
  EXPECT_LT((fitted.colwise().mean() - noisy.colwise().mean()).norm(), 1e-9);

  Positions unchanged;
  ASSERT_TRUE(fit_vertices_to_normals_with_closeness(noisy, m.faces, targets, 0.01, 0, unchanged, error)) << error;
  EXPECT_LT((unchanged - noisy).cwiseAbs().maxCoeff(), 1e-9);
}

// Mismatched sizes and a weight that is not positive are refused; the output stays as it was.
TEST(ClosenessVertexUpdate, RefusesBadArgumentsAndLeavesTheOutputAlone) {
  const test::ArrayMesh m = test::sphere(2);
  const Positions targets = unit_face_normals(m.positions, m.faces);
  const Positions sentinel = Positions::Constant(2, 3, 7.0);
  Positions out = sentinel;
  std::string error;
  EXPECT_FALSE(fit_vertices_to_normals_with_closeness(m.positions, m.faces, targets.topRows(3), 0.01, 5, out, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(out, sentinel);
  error.clear();
  EXPECT_FALSE(fit_vertices_to_normals_with_closeness(m.positions, m.faces, targets, 0.0, 5, out, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(out, sentinel);
  error.clear();
  EXPECT_FALSE(fit_vertices_to_normals_with_closeness(m.positions, m.faces, targets, 0.01, -1, out, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(out, sentinel);
}

}  // namespace
}  // namespace hht
