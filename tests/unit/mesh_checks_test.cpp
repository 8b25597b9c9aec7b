// The checks every filter runs: on its input (check_triangle_mesh) and on the positions it is
// about to write (check_result_positions, the plugin's single result check).
#include "mesh/mesh_checks.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <limits>

namespace hht::test {
namespace {

TEST(ResultCheck, AcceptsAMoveWithinTheDiagonal) {
  const ArrayMesh m = sphere(1);
  const double diagonal = bounding_box_diagonal(m.positions);
  EXPECT_NEAR(diagonal, 2 * std::sqrt(3.0), 1e-12);
  Positions moved = m.positions;
  moved(3, 0) += 0.99 * kMaxMoveDiagonals * diagonal;
  std::string error;
  EXPECT_TRUE(check_result_positions(m.positions, moved, error)) << error;
  EXPECT_TRUE(check_result_positions(m.positions, m.positions, error)) << error;
}

TEST(ResultCheck, RefusesAMoveBeyondTheDiagonal) {
  const ArrayMesh m = sphere(1);
  Positions moved = m.positions;
  moved(5, 2) -= 1.01 * kMaxMoveDiagonals * bounding_box_diagonal(m.positions);
  std::string error;
  EXPECT_FALSE(check_result_positions(m.positions, moved, error));
  EXPECT_NE(error.find("moved a vertex by"), std::string::npos) << error;
  EXPECT_NE(error.find("times the bounding-box diagonal"), std::string::npos) << error;
}

TEST(ResultCheck, RefusesNonFiniteAndBeyondSinglePrecision) {
  const ArrayMesh m = sphere(1);
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity(), 1e39}) {
    // at 1e38 the diagonal allows the move: only the coordinate's range is wrong
    const Positions input = m.positions * 1e38 / 4;
    Positions result = input;
    result(2, 1) = bad;
    std::string error;
    EXPECT_FALSE(check_result_positions(input, result, error)) << bad;
    EXPECT_NE(error.find("1 vertices with NaN or infinite coordinates"), std::string::npos) << error;
  }
}

TEST(ResultCheck, RefusesAResultOfAnotherSize) {
  const ArrayMesh m = sphere(1);
  std::string error;
  EXPECT_FALSE(check_result_positions(m.positions, m.positions.topRows(3), error));
  EXPECT_NE(error.find("returned 3 positions for"), std::string::npos) << error;
}

TEST(ResultCheck, HoldsAtExtremeScales) {
  for (double scale : {1e-30, 1e30}) {
    const ArrayMesh m = sphere(1);
    const Positions input = m.positions * scale;
    Positions result = input * 1.1;
    std::string error;
    EXPECT_TRUE(check_result_positions(input, result, error)) << scale << ": " << error;
    result(0, 0) += 10 * scale;
    EXPECT_FALSE(check_result_positions(input, result, error)) << scale;
  }
}

}  // namespace
}  // namespace hht::test
