#include "reconstruction/flip_guard.h"
#include "filters/spectral_mesh_filter.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

int turned_faces(const Positions& a, const Positions& b, const Faces& faces) {
  int count = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const auto normal = [&](const Positions& p) {
      const Eigen::RowVector3d o = p.row(faces(f, 0));
      return Eigen::RowVector3d((p.row(faces(f, 1)) - o).cross(p.row(faces(f, 2)) - o));
    };
    count += normal(a).dot(normal(b)) < 0;
  }
  return count;
}

TEST(FlipGuard, RestoresOnlyTheVerticesOfTurnedFaces) {
  const test::ArrayMesh m = test::sphere(3);
  Positions moved = m.positions * 1.01;
  EXPECT_EQ(restore_turned_faces(m.positions, m.faces, moved), 0);
  EXPECT_EQ(moved, m.positions * 1.01);
  // mirror one vertex across the opposite edge of its face, within the face: that face turns over
  const int v = m.faces(0, 0);
  const Eigen::RowVector3d a = moved.row(m.faces(0, 1)), b = moved.row(m.faces(0, 2));
  const Eigen::RowVector3d d = moved.row(v) - a, edge = (b - a).normalized();
  moved.row(v) = a + 2 * d.dot(edge) * edge - d;
  ASSERT_GT(turned_faces(m.positions, moved, m.faces), 0);
  const int restored = restore_turned_faces(m.positions, m.faces, moved);
  EXPECT_GE(restored, 1);
  EXPECT_LE(restored, 10);
  EXPECT_EQ(moved.row(v), m.positions.row(v));
  EXPECT_EQ(turned_faces(m.positions, moved, m.faces), 0);
}

// Mirrors a face's first vertex across the opposite edge, within the face: the face turns over.
Positions with_face_turned(const Positions& p, const Faces& faces, Eigen::Index f) {
  Positions out = p;
  const Eigen::RowVector3d a = p.row(faces(f, 1)), b = p.row(faces(f, 2));
  const Eigen::RowVector3d d = p.row(faces(f, 0)) - a, edge = (b - a).normalized();
  out.row(faces(f, 0)) = a + 2 * d.dot(edge) * edge - d;
  return out;
}

TEST(FlipGuard, PutsBackAFaceTurnedOverThatFitsTheSurface) {
  const test::ArrayMesh m = test::sphere(3);
  Positions result = with_face_turned(m.positions, m.faces, 0);
  ASSERT_GT(turned_faces(m.positions, result, m.faces), 0);
  EXPECT_GE(restore_turned_faces_that_fit(m.positions, m.faces, 60, result), 1);
  EXPECT_EQ(result, m.positions);
}

// A smoothing must turn over what noise folded: a face folded in the input stays turned.
TEST(FlipGuard, LeavesAFoldOfTheInputTurned) {
  const test::ArrayMesh m = test::sphere(3);
  const Positions folded = with_face_turned(m.positions, m.faces, 0);
  Positions result = m.positions;
  ASSERT_GT(turned_faces(folded, result, m.faces), 0);
  EXPECT_EQ(restore_turned_faces_that_fit(folded, m.faces, 60, result), 0);
  EXPECT_EQ(result, m.positions);
}

// A wrinkle laid over: the face goes back only part of the way, enough to stand the right way up.
TEST(FlipGuard, UnturnsAFewTurnedFacesPartway) {
  const test::ArrayMesh m = test::sphere(3);
  Positions result = with_face_turned(m.positions, m.faces, 0);
  ASSERT_EQ(turned_faces(m.positions, result, m.faces), 1);
  EXPECT_EQ(unturn_few_turned_faces(m.positions, m.faces, 0.01, result), 1);
  EXPECT_EQ(turned_faces(m.positions, result, m.faces), 0);
  const int v = m.faces(0, 0);
  EXPECT_NE(result.row(v), m.positions.row(v));  // part of the way, not all of it
  for (Eigen::Index i = 0; i < result.rows(); ++i) {
    if (i == v) continue;
    EXPECT_EQ(result.row(i), m.positions.row(i)) << i;
  }
}

// Many faces turned over is what noise does: the smoothing's turning stays.
TEST(FlipGuard, LeavesManyTurnedFacesAlone) {
  const test::ArrayMesh m = test::sphere(3);
  Positions result = m.positions;
  for (Eigen::Index f = 0; f < m.faces.rows(); f += 97) result = with_face_turned(result, m.faces, f);
  const int turned = turned_faces(m.positions, result, m.faces);
  ASSERT_GT(turned, 5);
  const Positions before = result;
  EXPECT_EQ(unturn_few_turned_faces(m.positions, m.faces, 5.0 / static_cast<double>(m.faces.rows()), result), 0);
  EXPECT_EQ(result, before);
  // allowed more, it un-turns them all (a move often un-turns a neighbour as well)
  EXPECT_GT(unturn_few_turned_faces(m.positions, m.faces, 0.5, result), 0);
  EXPECT_EQ(turned_faces(m.positions, result, m.faces), 0);
}

TEST(FlipGuard, UnturnLeavesAFoldOfTheInputTurned) {
  const test::ArrayMesh m = test::sphere(3);
  const Positions folded = with_face_turned(m.positions, m.faces, 0);
  Positions result = m.positions;
  EXPECT_EQ(unturn_few_turned_faces(folded, m.faces, 0.5, result), 0);
  EXPECT_EQ(result, m.positions);
}

// enhance.mlx on a clean irregular mesh turned 171 of bull's faces over before the guard.
TEST(FlipGuard, EnhancementTurnsNoFaceOver) {
  const test::ArrayMesh bull = test::load_data_mesh("bull");
  SpectralMeshFilterOptions o;
  o.band = {0.1, 0.5, false};
  o.gain = 2;
  o.reconstruction.lambda = 0.1;
  Positions result;
  SpectralMeshFilterReport report;
  std::string error;
  ASSERT_TRUE(spectral_mesh_filter(bull.positions, bull.faces, o, result, report, error)) << error;
  EXPECT_GT(report.restored_vertices, 0);
  EXPECT_EQ(turned_faces(bull.positions, result, bull.faces), 0);
  EXPECT_GT((result - bull.positions).rowwise().norm().maxCoeff(), 0);  // it still enhanced
}

}  // namespace
}  // namespace hht
