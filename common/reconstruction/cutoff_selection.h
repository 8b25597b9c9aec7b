// Chooses the cut-off mu of the biharmonic low-pass (biharmonic_low_pass.h) from the data, by
// generalized cross-validation (Craven and Wahba 1979), with no noise level needed (ours; why and
// the measurements: docs/quality.md, "The cut-off chosen by cross-validation").
//
// For X = A(mu) V the risk that matters for face normals is the error of the normal displacement's
// edge differences, sum over edges (n_i . e_i - n_j . e_j)^2. Its GCV score is
//   G(mu) = D(mu) / (1 - tr(K A) / tr(K))^2,
// D the same sum over the removed part X - V, K the graph Laplacian (the edge-difference form);
// tr(K A) is estimated with Rademacher probes (Hutchinson), the same probes at every mu so that the
// curve is smooth in mu. G is minimised over a geometric grid of mu, refined by a parabola in log mu.
// A noise estimate could stand in for the GCV denominator (Stein's unbiased risk), but its argmin
// moves far with a 10% error in sigma (measured); GCV's does not depend on it. With a noise level
// known to be right (the user's), Stein's risk is the one to use (noise_sigma):
//   S(mu) = D(mu) - sigma^2 tr(K) + 2 sigma^2 tr(K A),
// unbiased for the same edge-difference error, with no 0/0 near the identity.
//
// Large meshes: the score is computed on breadth-first patches of at most `sample_vertices`
// vertices in all, spread over the mesh, so the choice costs the same on any size.
#pragma once

#include "mesh/vertex_adjacency.h"

#include <functional>
#include <vector>

namespace hht {

struct CutoffSelectionOptions {
  double mu_largest = 4;      // weakest filter tried (keeps 94% of the mode k = 2, the finest)
  double mu_smallest = 0.15;  // strongest filter tried
  double step = 1.41421356;   // ratio of successive mu on the grid
  int sample_vertices = 30000;
  int patches = 8;            // patches of a sampled (large) mesh
  double max_error = 1e-4;    // of each solve, in the positions' unit (a mean edge)
  double first_order = 0;     // the low-pass's first-order weight (biharmonic_low_pass.h)
  double noise_sigma = 0;     // > 0: Stein's unbiased risk with this noise sigma (positions' unit) instead of GCV
};

struct CutoffSelection {
  double mu = 0;
  struct Point {
    double mu, score;
  };
  std::vector<Point> curve;  // the grid points scored, weakest filter first
  int sampled_vertices = 0;
  int iterations = 0;        // conjugate gradient iterations of all the solves
};

// positions: scaled to a unit mean edge; normals: unit vertex normals (of a smoothed surface: they
// only project the removed part). False with `error` if a solve did not converge.
bool select_cutoff(const VertexAdjacency& adjacency, const Positions& positions, const Positions& normals,
                   const CutoffSelectionOptions& options, CutoffSelection& selection, std::string& error,
                   const std::function<void(double)>& progress = {});

}  // namespace hht
