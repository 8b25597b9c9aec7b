// The whole HHT smoothing / enhancement of a mesh (the paper's Fig. 1): Hamiltonian cycle ->
// curvature signal -> EMD -> Hilbert spectra -> filter on instantaneous frequency (or keep the
// coarsest IMFs) -> positions rebuilt by the Laplacian least-squares solve.
#pragma once

#include "cycle/cycle_decomposition.h"
#include "reconstruction/laplacian_reconstruction.h"
#include "util/stage_clock.h"

#include <functional>
#include <string>

namespace hht {

struct SpectralMeshFilterOptions {
  CycleOptions cycle;
  // Filtering along one cycle leaves stripes: spatial neighbours that are far apart on the
  // cycle are filtered independently. With cycles > 1 the filtered signal is averaged over
  // that many cycles of different seeds (1 = the paper's method; docs/benchmarks.md measures it).
  int cycles = 1;
  EmdOptions emd;
  bool keep_coarsest = false;  // false: filter `band` by `gain`; true: residue + `coarsest` IMFs
  FrequencyBand band{0.1, 0.5, false};
  double gain = 0.0;
  int coarsest = 0;
  ReconstructionOptions reconstruction;
  // The mesh's own triangles (the paper's); the intrinsic Delaunay ones were measured no better here
  // (docs/quality.md item 45; the lab's `spec` and `e` modes with LAB_IDT=1).
  LaplacianTriangles laplacian_triangles = LaplacianTriangles::Mesh;
};

struct SpectralMeshFilterReport {
  HamiltonianCycle cycle;
  std::vector<ImfSummary> imfs;
  ReconstructionReport reconstruction;
  std::vector<StageTime> stages;
  double signal_change_rms = 0;  // RMS of G~ - G
  double max_displacement = 0;   // largest vertex move
  int restored_vertices = 0;     // enhancement only: put back where a face would have turned over
};

using Progress = std::function<void(int percent, const char* stage)>;

// `result` gets the new positions; on failure the message says why and nothing else is valid.
bool spectral_mesh_filter(const Positions& positions, const Faces& faces, const SpectralMeshFilterOptions& options,
                          Positions& result, SpectralMeshFilterReport& report, std::string& error,
                          const Progress& progress = {});

}  // namespace hht
