// Mesh denoising by the static/dynamic (SD) filter (Zhang, Deng, Hong, Peng, Qin, Liu,
// "Static/Dynamic Filtering for Mesh Geometry", IEEE TVCG 2019, arXiv:1712.03574), as its
// authors' MeshDenoiser runs it with DenoisingOptions.txt; a baseline of the field. Each outer
// iteration, on the current mesh:
//  1. the face normals n are filtered by minimising
//       sum_i a_i |n_i - n0_i|^2 + lambda sum_{i<j} s_ij (1 - exp(-|n_i - n_j|^2 / 2 nu^2)),
//       s_ij = (a_i + a_j) exp(-d_ij^2 / 2 eta^2) exp(-|g_i - g_j|^2 / 2 mu^2),
//     over unit normals: n0 the input normals, a the face areas over their mean, d_ij the
//     distance of the centroids, g the static guidance (the mean normal of the most consistent
//     patch around the face, as in guided normal filtering, Zhang et al. 2015), and the Welsch
//     penalty on the normals themselves the dynamic guidance. Pairs: faces whose centroids lie
//     within 3 eta of each other, reached through faces that do (both ways). Solved by the
//     authors' fixed-point (majorisation) iteration: n_i <- normalise(a_i (2 nu^2 / lambda) n0_i
//     + sum_j s_ij exp(-|n_i - n_j|^2 / 2 nu^2) n_j), all faces at once, until the area-weighted
//     RMS change of the normals falls to 2 sin(stop_angle / 2);
//  2. the vertices are fitted to the filtered normals by the authors' update
//     (closeness_vertex_update.h: a global fit, not Sun et al.'s local one).
// Read from the authors' code as AliceVision vendors it (src/dependencies/MeshSDFilter).
// Known limit: at these defaults the radius (4.5 mean centroid spacings) flattens coarse curved
// parts: noise-free, data/turbine.off (edges up to 14 mean edges) comes out at E_a 16.9 degrees
// with 108 faces turned, data/blade.off at 5.0, data/fandisk.off at 2.3.
// Departures from the authors' code: the input is not rescaled to a unit bounding-box diagonal
// and moved back (every parameter below is relative to the mesh, and the update keeps the
// vertices' mean, so this changes rounding only); the faces are oriented coherently on a copy
// first (OpenMesh would not load such a mesh); no OpenMP.
#pragma once

#include "mesh/mesh_arrays.h"

#include <functional>
#include <string>

namespace hht {

// Defaults: the authors' DenoisingOptions.txt, and the code's own values for what it leaves out.
struct SdNormalDenoiseOptions {
  int outer_iterations = 5;         // OuterIterations (DenoisingOptions.txt)
  double lambda = 2.0;              // Lambda; times sum(a) / sum_{i<j} (a_i + a_j) exp(-d_ij^2 / 2 eta^2) (SDFilter.h)
  double eta = 1.5;                 // Eta; times the mean centroid distance of faces sharing an edge (MeshNormalFilter.h)
  double mu = 1.5;                  // Mu: guidance width, on unit normals
  double nu = 0.3;                  // Nu: signal (Welsch) width, on unit normals
  int filter_iterations = 100;      // max fixed-point iterations (SDFilter.h Parameters, MaxFilterIterations)
  double stop_angle_degrees = 0.2;  // fixed-point stop, eps_angle_degree (MeshNormalFilter.h MeshFilterParameters)
  double closeness_weight = 0.001;  // MeshUpdateClosenessWeight; times faces / vertices (MeshNormalFilter.h)
  int vertex_iterations = 20;       // MeshUpdateIterations
};

// Step 1 alone: the SD-filtered unit normals of the faces of `positions` (one row per face).
// Fails like sd_normal_denoise.
bool sd_filter_face_normals(const Positions& positions, const Faces& faces, const SdNormalDenoiseOptions& options,
                            Positions& normals, std::string& error);

// Fails, with a message and `result` left as it was, on a mesh without faces, non-finite
// coordinates, bad indices, non-manifold edges, a non-orientable mesh, one where no two faces
// share an edge or all faces are degenerate, and on options out of range.
// progress(fraction done) after each outer iteration.
bool sd_normal_denoise(const Positions& positions, const Faces& faces, const SdNormalDenoiseOptions& options,
                       Positions& result, std::string& error, const std::function<void(double)>& progress = {});

}  // namespace hht
