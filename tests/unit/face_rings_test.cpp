#include "mesh/face_rings.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <set>

namespace hht {
namespace {

// Each face's ring (one at a time, as the face-normal pass builds it, and in the whole list)
// against the faces that share a vertex with it, found face by face, on an irregular mesh with
// holes.
TEST(FaceRings, HoldTheFacesSharingAVertex) {
  const test::ArrayMesh m = test::remove_faces(test::flip_random_edges(test::sphere(3), 300, 2), 7);
  const int n = static_cast<int>(m.positions.rows());
  const IndexLists around = vertex_faces(m.faces, n);
  const IndexLists rings = face_rings(m.faces, n);
  std::vector<int> ring;
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f) {
    std::set<int> expected;
    for (Eigen::Index g = 0; g < m.faces.rows(); ++g)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          if (m.faces(f, k) == m.faces(g, l)) expected.insert(static_cast<int>(g));
    face_ring(m.faces, around, f, ring);
    EXPECT_EQ(ring, std::vector<int>(expected.begin(), expected.end())) << f;
    EXPECT_EQ(std::vector<int>(rings.items.begin() + rings.begin(static_cast<int>(f)),
                               rings.items.begin() + rings.end(static_cast<int>(f))),
              ring);
  }
}

}  // namespace
}  // namespace hht
