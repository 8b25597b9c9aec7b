// Wall time per named stage of a pipeline, for the filters' logs and the benchmarks.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace hht {

struct StageTime {
  const char* stage;
  double seconds;
};

// Each done(stage) adds the time since the previous call (or construction) to that stage; a
// stage met again adds up (work repeated per cycle).
class StageClock {
 public:
  explicit StageClock(std::vector<StageTime>& stages) : stages_(stages) {}
  void done(const char* stage) {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    for (auto& s : stages_)
      if (std::string(s.stage) == stage) {
        s.seconds += seconds;
        return;
      }
    stages_.push_back({stage, seconds});
  }

 private:
  std::vector<StageTime>& stages_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace hht
