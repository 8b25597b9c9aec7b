#include "evaluation/gaussian_noise.h"
#include "mesh/vertex_adjacency.h"
#include "reconstruction/taubin_smoothing.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

double mean_radius(const Positions& p) { return p.rowwise().norm().mean(); }
double radial_rms_error(const Positions& p) { return std::sqrt((p.rowwise().norm().array() - 1).square().mean()); }

// The lambda step takes the noise out, the mu step undoes the shrinking it causes: on a noisy unit
// sphere the result is nearer the sphere than the input, and keeps its size where ten lambda steps
// alone shrink it. Fails with either step left out or with the sign of mu turned.
TEST(TaubinSmoothing, RemovesNoiseWithoutShrinking) {
  const test::ArrayMesh s = test::sphere(4);
  const VertexAdjacency adjacency = vertex_adjacency(s.faces, static_cast<int>(s.positions.rows()));
  const Positions noisy = add_gaussian_noise(s.positions, s.faces, 20, NoiseDirection::Isotropic, 5);
  const Positions smoothed = taubin_smoothing(adjacency, noisy);
  EXPECT_LT(radial_rms_error(smoothed), 0.5 * radial_rms_error(noisy));
  const Positions lambda_only = taubin_smoothing(adjacency, noisy, kTaubinSteps, kTaubinLambda, 0);
  const double shrink = 1 - mean_radius(lambda_only), kept = std::abs(1 - mean_radius(smoothed));
  EXPECT_GT(shrink, 0);
  EXPECT_LT(kept, 0.1 * shrink);
}

// A regular planar grid is a fixed point of the uniform Laplacian (each interior vertex at its
// neighbours' centroid): a step moves only what the rim's pull reaches, two rings in. Fails with a
// Laplacian that is not the uniform one (a weight per neighbour other than 1 / valence).
TEST(TaubinSmoothing, LeavesARegularGridsInteriorInPlace) {
  const int n = 12;
  const test::ArrayMesh g = test::grid(n, n);
  const VertexAdjacency adjacency = vertex_adjacency(g.faces, static_cast<int>(g.positions.rows()));
  const Positions smoothed = taubin_smoothing(adjacency, g.positions, 1);
  EXPECT_GT((smoothed - g.positions).rowwise().norm().maxCoeff(), 1e-3);  // the rim moves
  for (int y = 3; y < n - 3; ++y)
    for (int x = 3; x < n - 3; ++x)
      EXPECT_LT((smoothed.row(y * n + x) - g.positions.row(y * n + x)).norm(), 1e-12) << x << " " << y;
}

}  // namespace
}  // namespace hht
