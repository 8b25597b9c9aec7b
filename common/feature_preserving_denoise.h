// Feature-preserving denoising by the HHT (the paper's sec. 4.3, Figs. 4, 8-10): sharp
// features are detected and linked into feature lines; the curvature signal is then processed
// by divide and conquer:
//   - the cycle's signal is sifted with feature vertices never taken as extrema, so the
//     envelopes, and thus the IMFs of the smooth regions, are not bent by the creases, and is
//     low-pass filtered on instantaneous frequency (averaged over several cycles);
//   - each feature line is its own 1D signal (periodic when the line is closed), decomposed and
//     low-pass filtered the same way; a line too short for EMD is smoothed by a 1D Laplacian;
//   - corners take the mean signal of the corners of their type (same number of lines, same sign);
// then the mesh is rebuilt from the recombined signal by the Laplacian least-squares solve.
//
// Refinement (not in the paper; docs/benchmarks.md measures both): the rebuilt mesh's face
// normals are cleaned by guided normal filtering, which keeps creases, and the vertices are
// fitted to them (Sun et al. 2007). The curvature signal alone leaves the face normals noisier
// than bilateral filtering does; this step is what brings the normal error below it.
#pragma once

#include "feature_lines.h"
#include "sharp_features.h"
#include "spectral_mesh_filter.h"

namespace hht {

struct DenoiseOptions {
  bool detect_features = true;  // false: the torus-like case, no feature separation (Fig. 8)
  SharpFeatureOptions features;
  CycleOptions cycle;
  int cycles = 4;             // cycles whose filtered non-feature signals are averaged
  EmdOptions emd;
  double cutoff = 0.05;       // instantaneous frequencies above this are removed (cycles per sample)
  int short_line_passes = 10; // 1D Laplacian passes on feature lines too short for EMD
  ReconstructionOptions reconstruction = [] {
    ReconstructionOptions o;
    o.lambda = 1.0;
    return o;
  }();
  int refine_normal_passes = 8;       // guided normal filtering passes; 0: no refinement (the paper's method)
  double refine_normal_sigma = 0.35;  // range width of that filter, on unit normals (~20 degrees)
  int refine_vertex_iterations = 20;  // vertex update iterations towards the filtered normals
};

struct DenoiseReport {
  int feature_vertices = 0;
  int corners = 0;
  int lines = 0;
  int lines_by_emd = 0;        // long enough for EMD; the others were smoothed by a 1D Laplacian
  HamiltonianCycle cycle;      // the first cycle
  std::vector<ImfSummary> imfs;  // of the first cycle's non-feature signal
  ReconstructionReport reconstruction;
  std::vector<StageTime> stages;
  std::vector<FeatureType> type;  // per vertex
  FeatureLines feature_lines;
};

bool feature_preserving_denoise(const Positions& positions, const Faces& faces, const DenoiseOptions& options,
                                Positions& result, DenoiseReport& report, std::string& error,
                                const Progress& progress = {});

}  // namespace hht
