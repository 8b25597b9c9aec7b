#include "filters/spectral_mesh_filter.h"

#include "reconstruction/flip_guard.h"
#include "mesh/mesh_checks.h"


namespace hht {

bool spectral_mesh_filter(const Positions& positions, const Faces& faces, const SpectralMeshFilterOptions& options,
                          Positions& result, SpectralMeshFilterReport& report, std::string& error,
                          const Progress& progress) {
  report = SpectralMeshFilterReport{};
  StageClock clock(report.stages);
  auto step = [&](int percent, const char* what) {
    if (progress) progress(percent, what);
  };
  if (!check_triangle_mesh(positions, faces, error)) return false;

  step(2, "Hamiltonian cycle");
  if (!hamiltonian_cycle(faces, static_cast<int>(positions.rows()), options.cycle, report.cycle, error)) return false;
  clock.done("cycle");

  step(10, "Curvature signal");
  MeanCurvature curvature;
  if (!mean_curvature(positions, faces, curvature, error, options.laplacian_triangles)) return false;
  clock.done("signal");

  // One decomposition and filtered signal per cycle; the first cycle is the one reported.
  Eigen::VectorXd filtered = Eigen::VectorXd::Zero(curvature.signal.size());
  CycleDecomposition decomposition;
  const int cycles = std::max(1, options.cycles);
  for (int k = 0; k < cycles; ++k) {
    HamiltonianCycle other;
    if (k > 0) {
      CycleOptions seeded = options.cycle;
      seeded.seed = options.cycle.seed + 7919 * k;
      if (!hamiltonian_cycle(faces, static_cast<int>(positions.rows()), seeded, other, error)) return false;
      clock.done("cycle");
    }
    const HamiltonianCycle& cycle = k == 0 ? report.cycle : other;
    step(15 + 40 * k / cycles, "Empirical mode decomposition");
    CycleDecomposition d;
    if (!decompose_along_cycle(cycle, curvature.signal, options.emd, d, error)) return false;
    clock.done("emd");
    if (options.keep_coarsest) {
      filtered += coarsest_on_vertices(cycle, d, std::max(0, options.coarsest), faces, curvature.signal);
      clock.done("filter");
    } else {
      step(15 + 40 * k / cycles + 20 / cycles, "Hilbert spectra");
      compute_spectra(d);
      clock.done("spectra");
      filtered += filtered_on_vertices(cycle, d, options.band, options.gain, faces, curvature.signal);
      clock.done("filter");
    }
    if (k == 0) decomposition = std::move(d);
  }
  filtered /= cycles;
  report.imfs = summarize_imfs(decomposition);
  report.signal_change_rms = std::sqrt((filtered - curvature.signal).squaredNorm() / std::max<Eigen::Index>(1, filtered.size()));

  step(55, "Reconstruction (Laplacian least squares)");
  if (!reconstruct_positions(positions, faces, curvature, filtered, options.reconstruction, result, report.reconstruction, error,
                             [&](double done) { step(55 + static_cast<int>(44 * done), "Reconstruction (Laplacian least squares)"); }))
    return false;
  clock.done("reconstruction");
  // Enhancement amplifies the curvature signal where slivers make it erratic: undo the folds.
  if (!options.keep_coarsest && options.gain > 1) report.restored_vertices = restore_turned_faces(positions, faces, result);
  report.max_displacement = (result - positions).rowwise().norm().maxCoeff();
  step(100, "Done");
  return true;
}

}  // namespace hht
