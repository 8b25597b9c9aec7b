// The paper's feature processing (sec. 4.3): each feature line is its own 1D signal,
// decomposed by EMD when it is long enough. On the cube and the elephant every line is too
// short and takes the 1D Laplacian instead, so this needs a mesh with long creases: a long box.
#include "filters/feature_preserving_denoise.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/mean_curvature.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

namespace hht {
namespace {

// The surface of an nx x ny x nz box of unit cells, each face of a cell split in two triangles,
// outward oriented.
test::ArrayMesh box(int nx, int ny, int nz) {
  std::map<std::tuple<int, int, int>, int> index;
  std::vector<Eigen::RowVector3d> points;
  std::vector<Eigen::RowVector3i> faces;
  auto vertex = [&](int x, int y, int z) {
    const auto [it, added] = index.emplace(std::make_tuple(x, y, z), static_cast<int>(points.size()));
    if (added) points.emplace_back(x, y, z);
    return it->second;
  };
  const int size[3] = {nx, ny, nz};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int a = 0; a < size[u]; ++a)
        for (int b = 0; b < size[w]; ++b) {
          int corner[4];
          for (int k = 0; k < 4; ++k) {
            int c[3];
            c[axis] = side * size[axis];
            c[u] = a + (k == 1 || k == 2);
            c[w] = b + (k >= 2);
            corner[k] = vertex(c[0], c[1], c[2]);
          }
          // corners in the (u, w) plane: 0 (a, b), 1 (a+1, b), 2 (a+1, b+1), 3 (a, b+1);
          // counter-clockwise about +axis, so reversed on the low side
          if (side == 1) {
            faces.emplace_back(corner[0], corner[1], corner[2]);
            faces.emplace_back(corner[0], corner[2], corner[3]);
          } else {
            faces.emplace_back(corner[0], corner[2], corner[1]);
            faces.emplace_back(corner[0], corner[3], corner[2]);
          }
        }
    }
  test::ArrayMesh m;
  m.positions.resize(points.size(), 3);
  for (size_t i = 0; i < points.size(); ++i) m.positions.row(i) = points[i];
  m.faces.resize(faces.size(), 3);
  for (size_t i = 0; i < faces.size(); ++i) m.faces.row(i) = faces[i];
  return m;
}

TEST(FeatureLineSignals, LongCreasesAreDecomposedByEmd) {
  const test::ArrayMesh m = box(6, 6, 160);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Random, 3);
  DenoiseOptions o;
  o.paper_stage = true;
  Positions result;
  DenoiseReport report;
  std::string error;
  ASSERT_TRUE(feature_preserving_denoise(noisy, m.faces, o, result, report, error)) << error;
  EXPECT_EQ(report.corners, 8);
  EXPECT_EQ(report.lines, 12);
  // the four long edges (159 vertices between their corners) by EMD, the eight short ones not
  EXPECT_EQ(report.lines_by_emd, 4);
}

// The mean-curvature signal G of positions `p`.
Eigen::VectorXd signal_of(const Positions& p, const Faces& faces) {
  MeanCurvature h;
  std::string error;
  EXPECT_TRUE(mean_curvature(p, faces, h, error)) << error;
  return h.signal;
}

// The paper's method alone (the refinement off: the mesh is rebuilt from the filtered signal) on
// `noisy`; the result's mean-curvature signal G.
Eigen::VectorXd paper_stage_signal(const Positions& noisy, const Faces& faces, DenoiseReport& report) {
  DenoiseOptions o;
  o.paper_stage = true;
  o.refine_normal_passes = 0;
  Positions result;
  std::string error;
  EXPECT_TRUE(feature_preserving_denoise(noisy, faces, o, result, report, error)) << error;
  return signal_of(result, faces);
}

// Roughness of G along the lines of at least `min_length` vertices: the RMS of its second
// difference along each line, over the RMS of G there.
double roughness(const Eigen::VectorXd& g, const FeatureLines& lines, size_t min_length) {
  double second = 0, level = 0;
  for (const auto& line : lines.lines) {
    if (line.size() < min_length) continue;
    for (size_t i = 1; i + 1 < line.size(); ++i) {
      const double d = g[line[i - 1]] - 2 * g[line[i]] + g[line[i + 1]];
      second += d * d;
      level += g[line[i]] * g[line[i]];
    }
  }
  return std::sqrt(second / level);
}

// Each long crease's signal is low-pass filtered along the line: G read along the long creases
// of the result is much smoother than on the noisy input.
TEST(FeatureLineSignals, LongCreaseSignalsAreLowPassFiltered) {
  const test::ArrayMesh m = box(6, 6, 160);
  const Positions noisy = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Random, 3);
  DenoiseReport report;
  const Eigen::VectorXd g = paper_stage_signal(noisy, m.faces, report);
  // measured 0.336 -> 0.145; with the lines' signals left unfiltered 0.336 -> 0.315
  EXPECT_LT(roughness(g, report.feature_lines, 100), 0.5 * roughness(signal_of(noisy, m.faces), report.feature_lines, 100));
}

// A cube of `size` cells a side with 10% noise, and G of the paper's method alone on it.
struct NoisyCube {
  test::ArrayMesh m;
  Positions noisy;
  DenoiseReport report;
  Eigen::VectorXd g, noisy_g;
};

NoisyCube paper_stage_on_noisy_cube(int size) {
  NoisyCube c;
  c.m = box(size, size, size);
  c.noisy = add_gaussian_noise(c.m.positions, c.m.faces, 10.0, NoiseDirection::Random, 3);
  c.g = paper_stage_signal(c.noisy, c.m.faces, c.report);
  c.noisy_g = signal_of(c.noisy, c.m.faces);
  return c;
}

// Lines too short for EMD (every edge of a cube) take the 1D Laplacian along the line: measured
// 0.43 -> 0.23 and 0.42 -> 0.20 (cubes of 8 and 12 cells a side), 0.44 and 0.39 without it.
TEST(FeatureLineSignals, ShortLinesAreSmoothedAlongTheLine) {
  for (int size : {8, 12}) {
    const NoisyCube c = paper_stage_on_noisy_cube(size);
    ASSERT_EQ(c.report.lines, 12);
    ASSERT_EQ(c.report.lines_by_emd, 0);
    EXPECT_LT(roughness(c.g, c.report.feature_lines, 0), 0.65 * roughness(c.noisy_g, c.report.feature_lines, 0));
  }
}

// Corners of one type (valence and convexity: here all eight of a cube) take their mean signal,
// so the result's corners come closer to each other: the spread of G over them measured 0.30 ->
// 0.21 and 0.36 -> 0.22, and 0.28 and 0.32 with each corner keeping its own value (the rebuild
// reaches the targets only in the least-squares sense).
TEST(FeatureLineSignals, CornersOfOneTypeTakeTheirMean) {
  auto spread = [](const Eigen::VectorXd& g, const std::vector<int>& corners) {
    Eigen::VectorXd at(static_cast<Eigen::Index>(corners.size()));
    for (size_t c = 0; c < corners.size(); ++c) at[static_cast<Eigen::Index>(c)] = g[corners[c]];
    return std::sqrt((at.array() - at.mean()).square().mean());
  };
  for (int size : {8, 12}) {
    const NoisyCube c = paper_stage_on_noisy_cube(size);
    ASSERT_EQ(c.report.corners, 8);
    EXPECT_LT(spread(c.g, c.report.feature_lines.corners), 0.8 * spread(c.noisy_g, c.report.feature_lines.corners));
  }
}

}  // namespace
}  // namespace hht
