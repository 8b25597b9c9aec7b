#include "evaluation/gaussian_noise.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/normal_vertex_update.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace hht {
namespace {

// The update as its definition reads: a sweep over the faces, each pulling its corners towards the
// plane of its target normal through its centroid, then every vertex moved by its mean pull.
Positions sweep_over_faces(const Positions& positions, const Faces& faces, const Positions& targets, int iterations) {
  Positions v = positions;
  Eigen::VectorXi count = Eigen::VectorXi::Zero(v.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    if (targets.row(f).squaredNorm() > 0)
      for (int k = 0; k < 3; ++k) ++count[faces(f, k)];
  for (int it = 0; it < iterations; ++it) {
    Positions step = Positions::Zero(v.rows(), 3);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d normal = targets.row(f);
      if (normal.squaredNorm() == 0) continue;
      const Eigen::RowVector3d centroid = (v.row(faces(f, 0)) + v.row(faces(f, 1)) + v.row(faces(f, 2))) / 3.0;
      for (int k = 0; k < 3; ++k) step.row(faces(f, k)) += normal * normal.dot(centroid - v.row(faces(f, k)));
    }
    for (Eigen::Index i = 0; i < v.rows(); ++i)
      if (count[i] > 0) v.row(i) += step.row(i) / count[i];
  }
  return v;
}

// The parallel gather over each vertex's faces is the sweep over the faces to the bit, targets left
// out (zero rows) included, on a mesh large enough to be split between threads (parallel_for's
// blocks of 16,384).
TEST(NormalVertexUpdate, GatherIsTheSweepOverTheFaces) {
  const test::ArrayMesh m = test::sphere(6);  // 40,962 vertices, 81,920 faces
  ASSERT_GT(m.faces.rows(), 4 * 16384);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 20, NoiseDirection::Normal, 11);
  Positions targets = unit_face_normals(m.positions, m.faces);
  for (Eigen::Index f = 0; f < targets.rows(); f += 7) targets.row(f).setZero();
  EXPECT_EQ(fit_vertices_to_normals(noisy, m.faces, targets, 10), sweep_over_faces(noisy, m.faces, targets, 10));
  EXPECT_EQ(fit_vertices_to_normals(noisy, m.faces, targets, 0), noisy);
}

// A 30 x 30 grid in the plane z = 0 with its heights made bumpy, and its plane's normal as every
// face's target.
struct BumpyGrid {
  test::ArrayMesh mesh = test::grid(30, 30);
  Positions noisy, targets;
  BumpyGrid() : noisy(mesh.positions), targets(mesh.faces.rows(), 3) {
    for (Eigen::Index i = 0; i < noisy.rows(); ++i) noisy(i, 2) = 0.05 * std::sin(3.0 * i);
    targets.rowwise() = Eigen::RowVector3d(0, 0, 1);
  }
};

// Targets of a plane flatten a noisy plane; a vertex whose faces all have zero targets stays.
TEST(NormalVertexUpdate, PlaneTargetsFlattenANoisyGrid) {
  BumpyGrid g;
  const test::ArrayMesh& m = g.mesh;
  const Positions& noisy = g.noisy;
  Positions& targets = g.targets;
  for (int k = 0; k < 3; ++k) {  // the faces of vertex 0 left out
    for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
      if (m.faces(f, k) == 0) targets.row(f).setZero();
  }
  const Positions fitted = fit_vertices_to_normals(noisy, m.faces, targets, 50);
  EXPECT_EQ(fitted.row(0), noisy.row(0));
  EXPECT_LT(fitted.col(2).tail(noisy.rows() - 1).array().abs().maxCoeff() + 1e-12,
            0.5 * noisy.col(2).array().abs().maxCoeff());
  EXPECT_LT((fitted.leftCols(2) - noisy.leftCols(2)).cwiseAbs().maxCoeff(), 1e-12);  // moves along the targets only
}

// Fixed vertices stay to the bit while the others are fitted; an all-free mask is no mask.
TEST(NormalVertexUpdate, FixedVerticesStay) {
  const BumpyGrid g;
  const test::ArrayMesh& m = g.mesh;
  const Positions &noisy = g.noisy, &targets = g.targets;
  std::vector<unsigned char> fixed(static_cast<size_t>(noisy.rows()), 0);
  for (size_t i = 0; i < fixed.size(); i += 3) fixed[i] = 1;
  const Positions fitted = fit_vertices_to_normals(noisy, m.faces, targets, 20, fixed);
  int moved = 0;
  for (Eigen::Index i = 0; i < noisy.rows(); ++i) {
    if (fixed[static_cast<size_t>(i)]) EXPECT_EQ(fitted.row(i), noisy.row(i)) << i;
    else moved += fitted.row(i) != noisy.row(i);
  }
  EXPECT_GT(moved, noisy.rows() / 2);
  EXPECT_EQ(fit_vertices_to_normals(noisy, m.faces, targets, 20, std::vector<unsigned char>(fixed.size(), 0)),
            fit_vertices_to_normals(noisy, m.faces, targets, 20));
}

}  // namespace
}  // namespace hht
