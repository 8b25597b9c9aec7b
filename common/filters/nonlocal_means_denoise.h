// Non-local means mesh denoising after Yoshizawa, Belyaev & Seidel ("Smoothing by example",
// SMI 2006; the paper's ref. [32]). The original text was not at hand; the formulas chosen:
//
//   P' = P + n_P sum_Q w(P,Q) <n_P, Q - P> / sum_Q w(P,Q),
//   w(P,Q) = exp(-|P - Q|^2 / (2 (eta1/2)^2)) exp(-D(P,Q)^2 / eta2^2),
//
// over the vertices Q != P a breadth-first walk over mesh edges reaches from P without leaving
// the ball of radius eta1 (plus P's one-ring always, as in bilateral_denoise.h), so eta1 is the
// search radius and the spatial kernel falls to e^-2 at it. All vertices move at once; the
// area-weighted normals are recomputed before each iteration.
//
// Neighbourhood similarity D: each vertex's stencil is summarised by the centroids c_a of its
// vertices in three annuli, |R - P| in [0, 1.5), [1.5, 2.5), [2.5, 3.5) times eta3 (rings at
// about 1, 2 and 3 eta3; an empty annulus repeats the one inside it, the innermost defaults to
// the vertex), and the two stencils are compared as heights over P's tangent plane:
//   D(P,Q)^2 = sum_a <n_P, c_a(Q) - c_a(P)>^2.
// Why: averaging over an annulus takes the noise out of the comparison, heights over one common
// plane need neither a correspondence between the two stencils nor a rotation, and a stencil on
// the other side of a crease, or further round a curved part, lies off P's plane and weighs
// little, while stencils of the same smooth sheet (the "examples") dominate the average as in
// image NL-means. A first reading, heights of each stencil over its own tangent plane, made
// Fandisk worse than the noise (flat sheets on either side of a crease look alike).
//
// Measured (Fandisk with 10% / 30% noise along the normals, E_a in degrees, noisy 10.8 / 28.3):
// 1 iteration 9.6 / 12.5, 3 iterations 18.7 / 20.7; without the similarity term (eta2 huge)
// 11.7 / 15.4; bilateral_denoise.h's defaults 3.5 / 9.0. Torus (as in the paper's Fig. 8, 10% /
// 30%, noisy 11.9 / 30.4): 1.6 / 7.2, bilateral 2.4 / 4.7. Wider kernels shrink curved parts
// (E_v grows with each iteration), so the default is 1 iteration.
//
// Scale: eta1, eta2, eta3 are in mean edge lengths l of the input. The paper's torus settings:
// eta1 = 3, eta2 = 1.3, eta3 = 1.0. Bad input (no faces, non-finite coordinates, all vertices in
// one point, non-positive parameters or iterations): the positions come back unchanged.
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

struct NonLocalMeansOptions {
  double eta1 = 3.0;  // search radius, in mean edge lengths
  double eta2 = 1.3;  // width on the neighbourhood difference D, in mean edge lengths
  double eta3 = 1.0;  // stencil ring spacing of the neighbourhood profile, in mean edge lengths
  int iterations = 1;
};

Positions nonlocal_means_denoise(const Positions& positions, const Faces& faces, const NonLocalMeansOptions& options);

}  // namespace hht
