// Times the filters of the shipped scripts in the library (no file I/O), stage by stage, with the
// settings of resources/smooth.mlx (HHT: Adaptive Smooth), enhance.mlx (HHT: Spectral Filter,
// gain 2 above 0.1, lambda 0.1) or denoise.mlx (HHT: Feature-Preserving Denoise); prints one
// Markdown row per mesh: each stage's seconds, the total, the solver's iterations, the peak
// resident memory of the process (input arrays included) and the peak during each stage the
// progress callback names (the peak is reset at every change of stage). The first stage, input, is
// the plugin's preparation of the arrays (filter_input.h: seams merged, faces oriented, non-manifold vertices split).
//   smoothing_bench smooth|enhance|denoise mesh.ply [more meshes]
#include "bench_util.h"
#include "filters/feature_preserving_denoise.h"
#include "filters/noise_adaptive_smoothing.h"
#include "filters/spectral_mesh_filter.h"
#include "mesh/filter_input.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <cstring>

namespace {

struct Run {
  std::vector<hht::StageTime> stages;
  int iterations = 0;
  std::string note;
};

// Peak resident memory per progress stage, in order of first appearance.
struct StageMemory {
  std::vector<std::pair<std::string, double>> peaks;
  std::string current;
  void operator()(int, const char* stage) {
    if (stage == current) return;
    close();
    current = stage;
  }
  void close() {
    if (!current.empty()) {
      const double mb = hht::bench::memory_mb("VmHWM");
      auto it = std::find_if(peaks.begin(), peaks.end(), [&](const auto& p) { return p.first == current; });
      if (it == peaks.end()) peaks.emplace_back(current, mb);
      else it->second = std::max(it->second, mb);
    }
    hht::bench::reset_peak_memory();
  }
};

bool run(const char* method, const hht::Positions& positions, const hht::Faces& faces, hht::Positions& result, Run& out,
         std::string& error, const std::function<void(int, const char*)>& progress) {
  if (!std::strcmp(method, "smooth")) {
    hht::NoiseAdaptiveSmoothingReport report;
    const bool ok = hht::noise_adaptive_smooth(positions, faces, {}, result, report, error, progress);
    out = {report.stages, report.iterations, "sigma " + std::to_string(report.sigma_used)};
    return ok;
  }
  if (!std::strcmp(method, "enhance")) {
    hht::SpectralMeshFilterOptions options;
    options.gain = 2;
    options.reconstruction.lambda = 0.1;
    hht::SpectralMeshFilterReport report;
    const bool ok = hht::spectral_mesh_filter(positions, faces, options, result, report, error, progress);
    out = {report.stages, report.reconstruction.iterations, std::to_string(report.imfs.size()) + " IMFs"};
    return ok;
  }
  hht::DenoiseReport report;
  const bool ok = hht::feature_preserving_denoise(positions, faces, {}, result, report, error, progress);
  out = {report.stages, report.reconstruction.iterations,
         "sigma " + std::to_string(report.sigma_used) + (report.untangled ? ", untangled" : "")};
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || (std::strcmp(argv[1], "smooth") && std::strcmp(argv[1], "enhance") && std::strcmp(argv[1], "denoise"))) {
    std::fprintf(stderr, "usage: smoothing_bench smooth|enhance|denoise mesh.ply [more meshes]\n");
    return 2;
  }
  std::printf("| mesh | vertices | method | stages (s) | total (s) | solver iterations | peak memory (MB) | peak per stage (MB) | note |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (int i = 2; i < argc; ++i) {
    hht::Positions positions, result;
    hht::Faces faces;
    if (!hht::bench::load_mesh(argv[i], positions, faces)) {
      std::fprintf(stderr, "cannot read %s\n", argv[i]);
      return 1;
    }
    Run r;
    std::string error;
    bool ok = false;
    StageMemory memory;
    double peak = 0;
    hht::bench::reset_peak_memory();
    double input_seconds = 0;
    const double total = hht::bench::seconds([&] {
      hht::InputMap map;
      hht::FilterInputReport input;
      input_seconds = hht::bench::seconds([&] { hht::prepare_filter_input(positions, faces, true, map, input); });
      ok = run(argv[1], positions, faces, result, r, error, [&](int percent, const char* stage) {
        peak = std::max(peak, hht::bench::memory_mb("VmHWM"));
        memory(percent, stage);
      });
    });
    peak = std::max(peak, hht::bench::memory_mb("VmHWM"));
    memory.close();
    if (!ok) std::fprintf(stderr, "%s: %s\n", argv[i], error.c_str());
    std::string stages = "input " + std::to_string(input_seconds).substr(0, 5);
    for (const auto& s : r.stages) stages += std::string(stages.empty() ? "" : ", ") + s.stage + " " + std::to_string(s.seconds).substr(0, 5);
    std::string peaks;
    for (const auto& [stage, mb] : memory.peaks) peaks += (peaks.empty() ? "" : ", ") + stage + " " + std::to_string(static_cast<int>(mb));
    std::printf("| %s | %lld | %s | %s | %.2f | %d | %.0f | %s | %s |\n", argv[i], static_cast<long long>(positions.rows()), argv[1],
                stages.c_str(), total, r.iterations, peak, peaks.c_str(), r.note.c_str());
    std::fflush(stdout);
  }
  return 0;
}
