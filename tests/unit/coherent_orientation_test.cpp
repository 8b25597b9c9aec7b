#include "mesh/coherent_orientation.h"

#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht::test {
namespace {

Faces reversed(Faces faces, const std::vector<int>& which) {
  for (int f : which) std::swap(faces(f, 1), faces(f, 2));
  return faces;
}

int inconsistent_edges(const Faces& faces, int vertices) {
  CornerTable table;
  int inconsistent = -1;
  std::string error;
  EXPECT_TRUE(build_corner_table(faces, vertices, table, inconsistent, error)) << error;
  return inconsistent;
}

// Two parts: on the sphere a third of the faces run the wrong way, on the torus 70%, so there the
// other 30% are the ones turned and the torus comes out reversed as a whole (each part keeps the
// orientation most of its faces have).
TEST(CoherentOrientation, TurnsTheFacesAgainstMostOfTheirPart) {
  const ArrayMesh s = sphere(3), t = torus(3, 1, 40, 16);
  const ArrayMesh both = disjoint_union(s, t);
  const int ns = static_cast<int>(s.faces.rows()), nt = static_cast<int>(t.faces.rows());
  std::vector<int> wrong, torus_right;
  for (int f = 0; f < ns; f += 3) wrong.push_back(f);
  for (int f = 0; f < nt; ++f) (f % 10 < 7 ? wrong : torus_right).push_back(ns + f);
  Faces faces = reversed(both.faces, wrong);
  ASSERT_GT(inconsistent_edges(faces, both.vertices()), 0);

  const OrientationRepair repair = orient_as_most_faces(faces, both.vertices());
  EXPECT_TRUE(repair.done) << repair.why_not;
  EXPECT_EQ(repair.components, 2);
  EXPECT_EQ(repair.flipped, static_cast<int>((ns + 2) / 3 + torus_right.size()));
  EXPECT_EQ(inconsistent_edges(faces, both.vertices()), 0);
  std::vector<int> torus_all;
  for (int f = 0; f < nt; ++f) torus_all.push_back(ns + f);
  EXPECT_TRUE(faces == reversed(both.faces, torus_all)) << "the sphere as it was, the torus reversed";
}

TEST(CoherentOrientation, LeavesACoherentMeshAsItIs) {
  const ArrayMesh m = load_data_mesh("fandisk");
  Faces faces = m.faces;
  const OrientationRepair repair = orient_as_most_faces(faces, m.vertices());
  EXPECT_TRUE(repair.done);
  EXPECT_EQ(repair.flipped, 0);
  EXPECT_EQ(repair.components, 0);
  EXPECT_TRUE(faces == m.faces);
}

// A Moebius strip has no coherent orientation, and an edge of three faces no single one: the
// faces stay as they were and the reason is given.
TEST(CoherentOrientation, LeavesWhatCannotBeOrientedAsItWas) {
  const int n = 12;
  Faces strip(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const int a = i, b = i + n, c = (i + 1) % n, d = (i + 1) % n + n;
    // The last quad joins the two rails crossed: a half twist.
    const int c2 = i + 1 < n ? c : d, d2 = i + 1 < n ? d : c;
    strip.row(2 * i) << a, b, c2;
    strip.row(2 * i + 1) << b, d2, c2;
  }
  Faces faces = strip;
  OrientationRepair repair = orient_as_most_faces(faces, 2 * n);
  EXPECT_FALSE(repair.done);
  EXPECT_NE(repair.why_not.find("orientable"), std::string::npos) << repair.why_not;
  EXPECT_TRUE(faces == strip);

  Faces fin(3, 3);
  fin << 0, 1, 2, 1, 0, 3, 0, 1, 4;  // three faces on the edge 0-1, the last against the first
  faces = fin;
  repair = orient_as_most_faces(faces, 5);
  EXPECT_FALSE(repair.done);
  EXPECT_NE(repair.why_not.find("non-manifold"), std::string::npos) << repair.why_not;
  EXPECT_TRUE(faces == fin);
}

}  // namespace
}  // namespace hht::test
