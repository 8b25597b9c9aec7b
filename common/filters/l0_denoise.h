// Mesh denoising via L0 minimization (He and Schaefer, "Mesh denoising via L0 minimization",
// SIGGRAPH 2013): the vertices p minimise
//   |p - p*|^2 + alpha |R(p)|^2 + beta |D(p) - delta|^2 + lambda |delta|_0,
// p* the noisy input. D is the paper's edge operator: on each interior edge (i, j) with apexes k
// and l, the area-weighted sum of the apexes' offsets from the edge's line,
//   D_e(p) = (A_l (p_k - proj p_k) + A_k (p_l - proj p_l)) / (A_k + A_l),
// A_k the area of the triangle (i, j, k); it vanishes on a flat hinge, so |delta|_0 counts the
// edges that bend. R_e(p) = p_i + p_j - p_k - p_l (zero on a parallelogram) is a second
// regulariser, its weight alpha decaying towards 0. The problem is solved by alternation: delta
// by hard thresholding each edge's D_e(p) (kept where |D_e(p)|^2 >= lambda / beta), then p by a
// sparse linear solve, while beta grows by kappa from beta0 to beta_max and alpha decays; D's
// coefficients are taken from the current positions at each step.
// The defaults are those of the implementation by the group of Zhang et al. 2015 (repository
// bldeng/GuidedDenoising, MeshDenoisingViaL0Minimization.cpp), the baseline the field compares
// against. No HHT: a reference point for the denoisers of this project.
#pragma once

#include "mesh/mesh_arrays.h"

#include <functional>
#include <optional>
#include <string>

namespace hht {

// How the mean dihedral angle behind the default alpha and lambda is taken. The reference code
// averages OpenMesh's signed angle (positive on convex edges, negative on concave ones, for
// faces oriented outwards) over all edges, boundary edges counting 0; noise on a flat part then
// cancels out. Unsigned averages the angle between the normals instead, which grows with noise.
enum class DihedralMean { Signed, Unsigned };

struct L0DenoiseOptions {
  double beta0 = 1e-3;        // reference code: "beta", initial weight of the D(p) = delta term
  double beta_max = 1e3;      // reference code: "beta_max", the iterations stop when beta reaches it
  double kappa = 1.414;       // reference code: "mu_beta", beta's growth per iteration (~sqrt 2)
  double alpha_decay = 0.5;   // reference code: "mu_alpha", alpha's factor per iteration
  std::optional<double> alpha;   // unset: kAlphaPerDihedral x the mean dihedral angle (reference code)
  std::optional<double> lambda;  // unset: kLambdaPerDihedral x mean edge length^2 x mean dihedral angle
  DihedralMean dihedral_mean = DihedralMean::Signed;  // reference code: signed (see above)
};

constexpr double kAlphaPerDihedral = 0.1;   // reference code: alpha = 0.1 x mean dihedral angle
constexpr double kLambdaPerDihedral = 0.2;  // reference code: lambda = 0.2 x l^2 x mean dihedral angle

// The weights the options leave unset, from the mesh as the reference code derives them: the
// mean length of the edges and their mean dihedral angle (radians), each edge counted once.
// Fails on broken input (see l0_denoise) and, with the signed mean, on a mesh whose faces
// cannot be oriented coherently. A negative signed mean (faces oriented inwards, or a mostly
// concave mesh) gives negative weights, which l0_denoise refuses; a plane gives 0 (nothing to
// threshold: the result stays close to the input).
struct L0Weights {
  double alpha = 0;
  double lambda = 0;
  double mean_edge_length = 0;
  double mean_dihedral = 0;
};
bool l0_default_weights(const Positions& positions, const Faces& faces, DihedralMean mean, L0Weights& weights,
                        std::string& error);

// Fails, leaving `result` untouched, on a mesh without faces, with non-finite coordinates or
// non-manifold edges, on bad options (beta0 > 0, beta_max >= beta0, kappa > 1, alpha_decay in
// [0, 1], alpha >= 0, lambda >= 0), when a default weight comes out negative, and when the solve
// fails. progress(fraction done) after each iteration.
bool l0_denoise(const Positions& positions, const Faces& faces, const L0DenoiseOptions& options, Positions& result,
                std::string& error, const std::function<void(double)>& progress = {});

}  // namespace hht
