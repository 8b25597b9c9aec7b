// Times the Hamiltonian cycle (Ring Expander) on mesh files; prints one Markdown row each.
//   cycle_bench mesh.off [mesh2.ply ...]
#include "bench_util.h"
#include "cycle/hamiltonian_cycle.h"

#include <algorithm>
#include <cstdio>

int main(int argc, char** argv) {
  std::printf("| mesh | vertices | faces | cycle time (s, best of 3) | on cycle | isolated | repaired | memory for the cycle (MB) |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (int i = 1; i < argc; ++i) {
    hht::Positions positions;
    hht::Faces faces;
    if (!hht::bench::load_mesh(argv[i], positions, faces)) {
      std::fprintf(stderr, "cannot read %s\n", argv[i]);
      return 1;
    }
    double best = 1e300, extra_mb = 0;
    hht::HamiltonianCycle cycle;
    for (int run = 0; run < 3; ++run) {
      cycle = hht::HamiltonianCycle{};
      hht::bench::reset_peak_memory();
      const double before = hht::bench::memory_mb("VmRSS");
      std::string error;
      const double t = hht::bench::seconds([&] {
        if (!hht::hamiltonian_cycle(faces, static_cast<int>(positions.rows()), {}, cycle, error))
          std::fprintf(stderr, "%s: %s\n", argv[i], error.c_str());
      });
      best = std::min(best, t);
      extra_mb = std::max(extra_mb, hht::bench::memory_mb("VmHWM") - before);
    }
    const double n = static_cast<double>(positions.rows());
    std::printf("| %s | %lld | %lld | %.3f | %.3f%% | %d | %d | %.0f |\n", argv[i], static_cast<long long>(positions.rows()),
                static_cast<long long>(faces.rows()), best, 100.0 * cycle.order.size() / n, cycle.isolated,
                cycle.repaired, extra_mb);
  }
  return 0;
}
