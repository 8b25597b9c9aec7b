#include "mesh/breadth_first_patches.h"
#include "mesh/vertex_adjacency.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <set>

namespace hht {
namespace {

TEST(BreadthFirstPatches, SamplesConnectedPatchesWithinTheBudget) {
  const test::ArrayMesh s = test::sphere(4);
  const VertexAdjacency adjacency = vertex_adjacency(s.faces, s.vertices());
  const std::vector<int> kept = breadth_first_patches(adjacency, 400, 4);
  EXPECT_EQ(kept.size(), 400u);
  EXPECT_EQ(std::set<int>(kept.begin(), kept.end()).size(), kept.size());  // no vertex twice
  // Each patch is grown over the one-rings: every vertex after a patch's seed has a neighbour
  // sampled before it.
  const VertexAdjacency among = adjacency_among(adjacency, kept);
  int seeds = 0;
  for (size_t i = 0; i < kept.size(); ++i) {
    bool reached = false;
    for (const int* j = among.begin(static_cast<int>(i)); j != among.end(static_cast<int>(i)); ++j) reached |= *j < static_cast<int>(i);
    seeds += !reached;
  }
  EXPECT_LE(seeds, 4);
  // The faces among the sample: corners re-indexed into it, and only faces wholly inside.
  const Faces inside = faces_among(s.faces, s.vertices(), kept);
  EXPECT_GT(inside.rows(), 400);
  const Positions sampled = rows_at(s.positions, kept);
  for (Eigen::Index f = 0; f < inside.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      ASSERT_LT(inside(f, k), static_cast<int>(kept.size()));
      EXPECT_EQ(sampled.row(inside(f, k)), s.positions.row(kept[inside(f, k)]));
    }
  // A budget above the mesh takes it all.
  EXPECT_EQ(breadth_first_patches(adjacency, 10 * s.vertices(), 1).size(), static_cast<size_t>(s.vertices()));
}

}  // namespace
}  // namespace hht
