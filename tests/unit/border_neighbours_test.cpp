#include "mesh/border_neighbours.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace hht {
namespace {

std::array<int, 2> sorted(std::array<int, 2> pair) {
  std::sort(pair.begin(), pair.end());
  return pair;
}

// On a 3 x 3 grid (vertex (i, j) = 3 j + i) every vertex but the centre is on the border, with
// its two neighbours along it; a vertex where two fans touch has four border edges and no one
// direction along them.
TEST(BorderNeighbours, AreTheTwoVerticesAlongTheBorder) {
  const test::ArrayMesh m = test::grid(3, 3);
  const BorderNeighbours border = border_neighbours(m.faces, vertex_adjacency(m.faces, m.vertices()));
  EXPECT_EQ(sorted(border[0]), (std::array<int, 2>{1, 3}));
  EXPECT_EQ(sorted(border[1]), (std::array<int, 2>{0, 2}));
  EXPECT_EQ(sorted(border[5]), (std::array<int, 2>{2, 8}));
  EXPECT_EQ(border[4], (std::array<int, 2>{-1, -1}));

  Faces bowtie(2, 3);
  bowtie << 0, 1, 2, 0, 3, 4;
  const BorderNeighbours pinched = border_neighbours(bowtie, vertex_adjacency(bowtie, 5));
  EXPECT_EQ(pinched[0], (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(sorted(pinched[1]), (std::array<int, 2>{0, 2}));
}

// A sample keeps a vertex's border neighbours only where both were sampled: the sample's own
// rims are no border.
TEST(BorderNeighbours, ASampleKeepsTheMeshsOwnBorderOnly) {
  const test::ArrayMesh m = test::grid(3, 3);
  const BorderNeighbours border = border_neighbours(m.faces, vertex_adjacency(m.faces, m.vertices()));
  const BorderNeighbours among = border_neighbours_among(border, {3, 0, 1, 4});
  ASSERT_EQ(among.size(), 4u);
  EXPECT_EQ(sorted(among[1]), (std::array<int, 2>{0, 2}));  // vertex 0: 1 and 3 both kept
  EXPECT_EQ(among[0], (std::array<int, 2>{-1, -1}));        // vertex 3: 6 not kept
  EXPECT_EQ(among[2], (std::array<int, 2>{-1, -1}));        // vertex 1: 2 not kept
  EXPECT_EQ(among[3], (std::array<int, 2>{-1, -1}));        // the centre
}

// On the flat grid's lower edge the border runs along x: a move keeps its parts along x and z and
// has its part along y clamped to the limit, both ways; an interior vertex keeps its move.
TEST(BorderNeighbours, OnlyTheMoveAcrossTheBorderIsClamped) {
  const test::ArrayMesh m = test::grid(5, 5);
  const BorderNeighbours border = border_neighbours(m.faces, vertex_adjacency(m.faces, m.vertices()));
  Positions normals = Positions::Zero(m.vertices(), 3);
  normals.col(2).setOnes();
  Positions x = m.positions;
  x.row(2) += Eigen::RowVector3d(0.3, 0.4, 0.1);
  x.row(22) += Eigen::RowVector3d(0.3, -0.4, 0.1);  // the upper edge: moved out of the sheet
  x.row(12) += Eigen::RowVector3d(0.3, 0.4, 0.1);   // interior
  EXPECT_EQ(clamp_moves_across_borders(m.positions, normals, border, x, 0.1), 16);
  EXPECT_TRUE((x.row(2) - m.positions.row(2)).isApprox(Eigen::RowVector3d(0.3, 0.1, 0.1)));
  EXPECT_TRUE((x.row(22) - m.positions.row(22)).isApprox(Eigen::RowVector3d(0.3, -0.1, 0.1)));
  EXPECT_TRUE((x.row(12) - m.positions.row(12)).isApprox(Eigen::RowVector3d(0.3, 0.4, 0.1)));
}

}  // namespace
}  // namespace hht
