#include "mesh/hinge_heights.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace hht {
namespace {

// A planar k x k grid of unit squares, each split by a diagonal.
void grid(int k, Positions& p, Faces& f) {
  p.resize((k + 1) * (k + 1), 3);
  for (int y = 0; y <= k; ++y)
    for (int x = 0; x <= k; ++x) p.row(y * (k + 1) + x) << x, y, 0;
  f.resize(2 * k * k, 3);
  int t = 0;
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x) {
      const int a = y * (k + 1) + x, b = a + 1, c = a + k + 1, d = c + 1;
      f.row(t++) << a, b, d;
      f.row(t++) << a, d, c;
    }
}

TEST(HingeHeights, FlatGridHasOneZeroPerInteriorEdge) {
  Positions p;
  Faces f;
  grid(4, p, f);
  const std::vector<double> h = hinge_heights(p, f, vertex_adjacency(f, static_cast<int>(p.rows())));
  // 4 x 4 squares: 16 diagonals, 2 * 4 * 3 interior grid edges
  EXPECT_EQ(h.size(), 16u + 24u);
  for (double x : h) EXPECT_EQ(x, 0.0);
}

TEST(HingeHeights, LiftedCornerOfASquareGivesItsHeightOverTheNoiseSpread) {
  // D = (0, 1) lifted by 0.3 over the plane of A, B, C: its foot is A + B - C, barycentric
  // (1, 1, -1), so the height is divided by sqrt(1 + 3) = 2
  Positions p(4, 3);
  p << 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0.3;
  Faces f(2, 3);
  f << 0, 2, 1, 0, 1, 3;
  const std::vector<double> h = hinge_heights(p, f, vertex_adjacency(f, static_cast<int>(p.rows())));
  ASSERT_EQ(h.size(), 1u);
  EXPECT_NEAR(std::abs(h[0]), 0.15, 1e-12);
}

TEST(HingeHeights, NormalNoiseOfSigmaReadsSigma) {
  // first order: unit noise normal to a flat surface gives hinge heights of unit spread
  Positions p;
  Faces f;
  grid(60, p, f);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gauss(0.0, 0.01);
  for (Eigen::Index i = 0; i < p.rows(); ++i) p(i, 2) += gauss(rng);
  std::vector<double> h = hinge_heights(p, f, vertex_adjacency(f, static_cast<int>(p.rows())));
  for (double& x : h) x = std::abs(x);
  std::nth_element(h.begin(), h.begin() + h.size() / 2, h.end());
  EXPECT_NEAR(h[h.size() / 2] / 0.6745, 0.01, 0.0005);
}

TEST(HingeHeights, SkipsBoundaryNonManifoldDegenerateAndDuplicateEdges) {
  // three faces on edge 0-1: non-manifold; every other edge is on the boundary
  Positions p(5, 3);
  p << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1;
  Faces f(3, 3);
  f << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  EXPECT_TRUE(hinge_heights(p, f, vertex_adjacency(f, static_cast<int>(p.rows()))).empty());
  // two faces on edge 0-1, either of them of zero area (vertex 2 on the line of the edge)
  p.row(2) << 2, 0, 0;
  for (bool first : {true, false}) {
    Faces g(2, 3);
    if (first) g << 0, 1, 2, 1, 0, 3;
    else g << 1, 0, 3, 0, 1, 2;
    EXPECT_TRUE(hinge_heights(p, g, vertex_adjacency(g, static_cast<int>(p.rows()))).empty()) << first;
  }
  // a face and its duplicate, turned over (a double-sided triangle): no hinge, not a flat one
  p.row(2) << 0, 1, 0;
  Faces twice(2, 3);
  twice << 0, 1, 2, 1, 0, 2;
  EXPECT_TRUE(hinge_heights(p, twice, vertex_adjacency(twice, static_cast<int>(p.rows()))).empty());
}

}  // namespace
}  // namespace hht
