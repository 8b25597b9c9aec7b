// Taubin's lambda|mu smoothing (Taubin, "A signal processing approach to fair surface design",
// SIGGRAPH 1995) with the uniform Laplacian, at MeshLab's Taubin Smooth defaults. Its pass band is
// flat and its roll-off sharp: it takes out the finest frequencies and leaves the coarser ones, so
// its slide along the surface removes tangential noise while moving an irregular triangulation's
// vertices less than a strong low-pass does (the adaptive smoothing's step 4b offers it as a
// candidate; docs/quality.md item 22).
#pragma once

#include "mesh/vertex_adjacency.h"

namespace hht {

constexpr double kTaubinLambda = 0.5;
constexpr double kTaubinMu = -0.53;
constexpr int kTaubinSteps = 10;

// `steps` pairs of moves p -= lambda L p, p -= mu L p, L the uniform Laplacian (uniform_laplacian.h).
Positions taubin_smoothing(const VertexAdjacency& adjacency, const Positions& positions, int steps = kTaubinSteps,
                           double lambda = kTaubinLambda, double mu = kTaubinMu);

}  // namespace hht
