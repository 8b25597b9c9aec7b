// Splits [begin, end) into one contiguous block per hardware thread and runs body(first, last)
// on each; small ranges run on the calling thread (a thread costs more than they do). Blocks
// write disjoint outputs, so results do not depend on the thread count.
#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace hht {

template <class Body>
void parallel_for(int begin, int end, const Body& body, int min_per_thread = 16384) {
  const int count = end - begin;
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::clamp(count / std::max(1, min_per_thread), 1, hardware);
  if (threads <= 1) {
    if (count > 0) body(begin, end);
    return;
  }
  std::vector<std::thread> helpers;
  helpers.reserve(threads - 1);
  const int block = (count + threads - 1) / threads;
  for (int t = 1; t < threads; ++t) {
    const int first = begin + t * block, last = std::min(end, first + block);
    if (first < last) helpers.emplace_back([&body, first, last] { body(first, last); });
  }
  body(begin, std::min(end, begin + block));
  for (std::thread& h : helpers) h.join();
}

}  // namespace hht
