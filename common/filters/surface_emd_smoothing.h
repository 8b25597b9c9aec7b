// Smoothing by the surface EMD, as in the paper's Figs. 9b/10b (3D-EMD, Wang et al. 2012) and
// 9d/10d (feature-centric EMD, Hu, Wang & Qin 2014): the curvature signal G is decomposed on the
// surface (surface_emd.h), the k finest IMFs are dropped (G~ = the k-th residue, signal minus
// IMFs 1..k; the final residue when there are fewer IMFs), and the mesh is rebuilt from G~ by
// the same Laplacian least-squares solve as the spectral filter (laplacian_reconstruction.h).
// Feature-centric: the sharp feature detector's vertices (sharp_features.h) are kept out of the
// envelope fitting and every IMF is zero on them, so their curvature stays in the residue.
#pragma once

#include "reconstruction/laplacian_reconstruction.h"
#include "mesh/sharp_features.h"
#include "util/stage_clock.h"
#include "filters/surface_emd.h"

#include <string>
#include <vector>

namespace hht {

struct SurfaceEmdSmoothingOptions {
  SurfaceEmdOptions emd;  // its feature_vertices is ignored: set by feature_centric
  int residue = 3;        // rebuild from the k-th residue
  bool feature_centric = false;
  SharpFeatureOptions features;
  ReconstructionOptions reconstruction = [] {
    ReconstructionOptions r;
    r.lambda = 0.1;  // as resources/smooth.mlx
    return r;
  }();
};

struct SurfaceEmdSmoothingReport {
  int imfs = 0;                // IMFs found
  int residue_used = 0;        // IMFs dropped
  int feature_vertices = 0;    // feature-centric only
  std::vector<int> sifts;
  SurfaceEmdReport emd;
  ReconstructionReport reconstruction;
  std::vector<StageTime> stages;
  double signal_change_rms = 0;
  double max_displacement = 0;
};

// `result` gets the new positions; on failure the message says why.
bool surface_emd_smoothing(const Positions& positions, const Faces& faces, const SurfaceEmdSmoothingOptions& options,
                           Positions& result, SurfaceEmdSmoothingReport& report, std::string& error);

}  // namespace hht
