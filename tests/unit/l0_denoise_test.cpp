#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "filters/l0_denoise.h"
#include "mesh/dihedral_angles.h"
#include "mesh/vertex_adjacency.h"
#include "test_meshes.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace hht {
namespace {

Positions denoise(const Positions& p, const Faces& f, const L0DenoiseOptions& o = {}) {
  Positions result;
  std::string error;
  EXPECT_TRUE(l0_denoise(p, f, o, result, error)) << error;
  return result;
}

// Uniform Laplacian smoothing, each step halfway to the one-ring's centroid.
Positions laplacian_steps(const Positions& p, const Faces& f, int steps) {
  const VertexAdjacency adjacency = vertex_adjacency(f, static_cast<int>(p.rows()));
  Positions out = p;
  for (int s = 0; s < steps; ++s) {
    Positions next = out;
    for (int i = 0; i < adjacency.vertices(); ++i) {
      if (adjacency.valence(i) == 0) continue;
      Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
      for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) mean += out.row(*j);
      next.row(i) = 0.5 * (out.row(i) + mean / adjacency.valence(i));
    }
    out.swap(next);
  }
  return out;
}

double rms_move(const Positions& a, const Positions& b) { return std::sqrt((a - b).rowwise().squaredNorm().mean()); }

// The mean angle (degrees) between the face normals across the edges that are creases (over
// 60 degrees) in the clean mesh: 90 on the cube, less where a filter rounded them off.
double crease_angle(const Positions& p, const Positions& clean, const Faces& f) {
  const std::vector<DihedralAngle> truth = dihedral_angles(clean, f), result = dihedral_angles(p, f);
  EXPECT_EQ(truth.size(), result.size());
  double sum = 0;
  int count = 0;
  for (size_t e = 0; e < truth.size(); ++e)
    if (truth[e].radians > M_PI / 3) {
      sum += result[e].radians;
      ++count;
    }
  EXPECT_GT(count, 0);
  return count > 0 ? sum / count * 180 / M_PI : 0;
}

// The reference code's defaults denoise the meshed cube (noise along the normals, 15% of the
// mean edge) well below the noisy input's E_a.
TEST(L0Denoise, DenoisesTheCube) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 15, NoiseDirection::Normal, 11);
  const double before = mean_face_normal_error_degrees(noisy, m.positions, m.faces);
  const double after = mean_face_normal_error_degrees(denoise(noisy, m.faces), m.positions, m.faces);
  EXPECT_GT(before, 10);
  EXPECT_LT(after, 0.1 * before);  // measured 15.2 -> 0.60
}

// Its creases stay sharper than under uniform Laplacian smoothing of equal strength: as many
// steps as it takes to move the vertices as far (RMS) from the noisy input as L0 does.
TEST(L0Denoise, KeepsCreasesSharperThanLaplacianSmoothingOfEqualStrength) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 15, NoiseDirection::Normal, 11);
  const Positions l0 = denoise(noisy, m.faces);
  const double move = rms_move(l0, noisy);
  int steps = 0;
  Positions smoothed = noisy;
  while (rms_move(smoothed, noisy) < move && steps < 200) smoothed = laplacian_steps(noisy, m.faces, ++steps);
  ASSERT_LT(steps, 200);
  // measured: 2 steps; creases 89.6 degrees against 62.7, E_a 0.60 against 8.4
  EXPECT_GT(crease_angle(l0, m.positions, m.faces), crease_angle(smoothed, m.positions, m.faces) + 20);
  EXPECT_LT(mean_face_normal_error_degrees(l0, m.positions, m.faces),
            0.5 * mean_face_normal_error_degrees(smoothed, m.positions, m.faces));
}

// A grid in a tilted plane, its vertices jittered within the plane: whatever the weights, every
// term of the solve is in the plane (D and R ignore translations), so the result stays in it.
TEST(L0Denoise, APlaneStaysAPlane) {
  test::ArrayMesh m = test::grid(12, 10);
  const Positions jitter = add_gaussian_noise(m.positions, m.faces, 8, NoiseDirection::Isotropic, 5);  // no fold
  m.positions.col(0) = jitter.col(0);
  m.positions.col(1) = jitter.col(1);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::RowVector3d offset(0.3, -2, 5);
  const Positions tilted = (m.positions * r.transpose()).rowwise() + offset;
  const Eigen::RowVector3d normal = (r * Eigen::Vector3d::UnitZ()).transpose();
  L0DenoiseOptions strong;
  strong.alpha = 0.5;
  strong.alpha_decay = 1;  // R keeps pulling the jittered triangles to parallelograms: they move
  strong.lambda = 0.01;
  for (const L0DenoiseOptions& o : {L0DenoiseOptions{}, strong}) {
    const Positions out = denoise(tilted, m.faces, o);
    ASSERT_EQ(out.rows(), tilted.rows());
    if (o.alpha) {
      EXPECT_GT(rms_move(out, tilted), 0.01);  // measured 0.095
    }
    const Eigen::VectorXd height = (out.rowwise() - offset) * normal.transpose();
    EXPECT_LT(height.cwiseAbs().maxCoeff(), 1e-9);
  }
}

// Noise along the normals of a plane: the unsigned mean sees it and sets the weights from it,
// and the result is far flatter than the input.
TEST(L0Denoise, FlattensANoisyPlaneWithTheUnsignedMean) {
  const test::ArrayMesh m = test::grid(20, 20);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 15, NoiseDirection::Normal, 7);
  L0DenoiseOptions o;
  o.dihedral_mean = DihedralMean::Unsigned;
  const Positions out = denoise(noisy, m.faces, o);
  EXPECT_LT(out.col(2).cwiseAbs().mean(), 0.3 * noisy.col(2).cwiseAbs().mean());  // measured 0.136 -> 0.021
}

// The default weights: on the clean cube, the mean signed dihedral angle is 90 degrees times the
// share of crease edges, the same unsigned, and negated with the faces turned inwards (which
// l0_denoise then refuses, unless told to take the unsigned mean).
TEST(L0Denoise, DefaultWeightsFollowTheReferenceCode) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  int creases = 0;
  const std::vector<DihedralAngle> angles = dihedral_angles(m.positions, m.faces);
  for (const DihedralAngle& a : angles) creases += a.radians > 1;
  L0Weights w;
  std::string error;
  ASSERT_TRUE(l0_default_weights(m.positions, m.faces, DihedralMean::Signed, w, error)) << error;
  EXPECT_NEAR(w.mean_dihedral, M_PI / 2 * creases / angles.size(), 1e-9);  // closed: every edge has an angle
  EXPECT_NEAR(w.mean_edge_length, mean_edge_length(m.positions, m.faces), 1e-12);  // closed: each edge twice there
  EXPECT_DOUBLE_EQ(w.alpha, kAlphaPerDihedral * w.mean_dihedral);
  EXPECT_DOUBLE_EQ(w.lambda, kLambdaPerDihedral * w.mean_edge_length * w.mean_edge_length * w.mean_dihedral);
  L0Weights unsigned_weights;
  ASSERT_TRUE(l0_default_weights(m.positions, m.faces, DihedralMean::Unsigned, unsigned_weights, error));
  EXPECT_NEAR(unsigned_weights.mean_dihedral, w.mean_dihedral, 1e-12);

  Faces inwards = m.faces;
  inwards.col(1).swap(inwards.col(2));
  L0Weights turned;
  ASSERT_TRUE(l0_default_weights(m.positions, inwards, DihedralMean::Signed, turned, error));
  EXPECT_NEAR(turned.mean_dihedral, -w.mean_dihedral, 1e-12);
  Positions out;
  EXPECT_FALSE(l0_denoise(m.positions, inwards, {}, out, error));
  EXPECT_NE(error.find("negative"), std::string::npos) << error;
  L0DenoiseOptions o;
  o.dihedral_mean = DihedralMean::Unsigned;
  EXPECT_TRUE(l0_denoise(m.positions, inwards, o, out, error)) << error;
}

// Every term scales with the mesh (lambda with the squared edge length): a scaled copy gives
// the scaled result.
TEST(L0Denoise, ScaledMeshGivesTheScaledResult) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 15, NoiseDirection::Normal, 3);
  const Positions small = denoise(noisy, m.faces);
  const Positions large = denoise(7 * noisy, m.faces);
  EXPECT_LT((large - 7 * small).cwiseAbs().maxCoeff(), 1e-8 * large.cwiseAbs().maxCoeff());
}

TEST(L0Denoise, BrokenInputAndBadOptionsAreRefusedAndTheOutputUntouched) {
  const test::ArrayMesh m = test::sphere(2);
  const Positions sentinel = Positions::Constant(3, 3, 42.0);
  Positions out = sentinel;
  std::string error;
  EXPECT_FALSE(l0_denoise(m.positions, Faces(0, 3), {}, out, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(out, sentinel);

  Positions nan = m.positions;
  nan(3, 1) = std::numeric_limits<double>::quiet_NaN();
  error.clear();
  EXPECT_FALSE(l0_denoise(nan, m.faces, {}, out, error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;
  EXPECT_EQ(out, sentinel);

  Faces nonmanifold(3, 3);  // three triangles on the edge (0, 1)
  nonmanifold << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  error.clear();
  EXPECT_FALSE(l0_denoise(Positions::Random(5, 3), nonmanifold, {}, out, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(out, sentinel);

  for (auto bad : {+[](L0DenoiseOptions& o) { o.beta0 = 0; }, +[](L0DenoiseOptions& o) { o.kappa = 1; },
                   +[](L0DenoiseOptions& o) { o.beta_max = o.beta0 / 2; }, +[](L0DenoiseOptions& o) { o.alpha = -1; },
                   +[](L0DenoiseOptions& o) { o.lambda = std::nan(""); }}) {
    L0DenoiseOptions o;
    bad(o);
    EXPECT_FALSE(l0_denoise(m.positions, m.faces, o, out, error));
    EXPECT_EQ(out, sentinel);
  }
}

}  // namespace
}  // namespace hht
