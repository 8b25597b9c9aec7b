// Times the whole HHT smoothing (cycle, signal, EMD, spectra, filter, reconstruction) on mesh
// files with the defaults of resources/smooth.mlx; prints one Markdown row per mesh.
//   smoothing_bench mesh.ply [more meshes]
#include "bench_util.h"
#include "filters/spectral_mesh_filter.h"

#include <cstdio>

int main(int argc, char** argv) {
  std::printf("| mesh | vertices | cycle | signal | EMD | spectra | filter | reconstruction | total (s) | IMFs | CG iterations | peak memory (MB) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 1; i < argc; ++i) {
    hht::Positions positions, result;
    hht::Faces faces;
    if (!hht::bench::load_mesh(argv[i], positions, faces)) {
      std::fprintf(stderr, "cannot read %s\n", argv[i]);
      return 1;
    }
    hht::SpectralMeshFilterOptions options;  // low-pass: frequencies above 0.1 removed
    hht::SpectralMeshFilterReport report;
    std::string error;
    hht::bench::reset_peak_memory();
    const double total = hht::bench::seconds([&] {
      if (!hht::spectral_mesh_filter(positions, faces, options, result, report, error))
        std::fprintf(stderr, "%s: %s\n", argv[i], error.c_str());
    });
    std::printf("| %s | %lld |", argv[i], static_cast<long long>(positions.rows()));
    for (const auto& s : report.stages) std::printf(" %.2f |", s.seconds);
    std::printf(" %.2f | %zu | %d | %.0f |\n", total, report.imfs.size(), report.reconstruction.iterations,
                hht::bench::memory_mb("VmHWM"));
  }
  return 0;
}
