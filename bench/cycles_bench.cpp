// Why smooth.mlx averages several cycles: a sphere (10242 vertices) with 10% noise along the
// normals is low-pass filtered along K cycles; printed are the RMS error of the filtered
// signal against the clean sphere's G, and the mean distance to the clean sphere (in mean edge
// lengths) after the reconstruction, for two lambdas.
//   cycles_bench
#include "evaluation/gaussian_noise.h"
#include "filters/spectral_mesh_filter.h"
#include "mesh/tri_mesh.h"

#include <vcg/complex/algorithms/create/platonic.h>

#include <cstdio>

int main() {
  hht::TriMesh sphere;
  vcg::tri::Sphere(sphere, 5);
  hht::Positions clean, result;
  hht::Faces faces;
  hht::mesh_to_arrays(sphere, clean, faces);
  const double edge = hht::mean_edge_length(clean, faces);
  const hht::Positions noisy = hht::add_gaussian_noise(clean, faces, 10.0, hht::NoiseDirection::Normal, 1);
  auto error = [&](const hht::Positions& p) {  // mean |radius - 1| in edge lengths
    return (p.rowwise().norm().array() - 1.0).abs().mean() / edge;
  };
  std::printf("noisy input: mean distance to the sphere %.4f edge lengths\n\n", error(noisy));
  std::printf("| cut-off | cycles | RMS error of G~ (clean G = 2) | distance, lambda 0.01 | distance, lambda 0.1 |\n|---|---|---|---|---|\n");
  hht::MeanCurvature h;
  std::string message;
  hht::mean_curvature(noisy, faces, h, message);
  for (double cut : {0.05, 0.1, 0.2})
    for (int cycles : {1, 4, 16}) {
      Eigen::VectorXd filtered = Eigen::VectorXd::Zero(h.signal.size());
      for (int k = 0; k < cycles; ++k) {
        hht::HamiltonianCycle cycle;
        hht::CycleOptions o;
        o.seed = 1 + 7919 * k;
        hht::hamiltonian_cycle(faces, static_cast<int>(clean.rows()), o, cycle, message);
        hht::CycleDecomposition d;
        hht::decompose_along_cycle(cycle, h.signal, {}, d, message);
        hht::compute_spectra(d);
        filtered += hht::filtered_on_vertices(cycle, d, {cut, 0.5, false}, 0.0, faces, h.signal);
      }
      filtered /= cycles;
      std::printf("| %.2f | %d | %.2f |", cut, cycles, std::sqrt((filtered.array() - 2.0).square().mean()));
      for (double lambda : {0.01, 0.1}) {
        hht::ReconstructionOptions o;
        o.lambda = lambda;
        hht::ReconstructionReport report;
        hht::reconstruct_positions(noisy, faces, h, filtered, o, result, report, message);
        std::printf(" %.4f |", error(result));
      }
      std::printf("\n");
    }
  return 0;
}
