// A robust display range: the p-th and (100-p)-th percentiles of the finite values, so that a
// colour ramp is not flattened by a few extreme vertices.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace hht {

template <class Values>
std::pair<double, double> percentile_range(const Values& values, double percent) {
  std::vector<double> v;
  v.reserve(values.size());
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(values.size()); ++i)
    if (std::isfinite(values[i])) v.push_back(values[i]);
  if (v.empty()) return {0.0, 0.0};
  const double p = std::clamp(percent, 0.0, 50.0) / 100.0;
  const size_t lo = static_cast<size_t>(std::floor(p * (v.size() - 1)));
  const size_t hi = static_cast<size_t>(std::ceil((1.0 - p) * (v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + lo, v.end());
  const double low = v[lo];
  std::nth_element(v.begin(), v.begin() + hi, v.end());
  return {low, v[hi]};
}

}  // namespace hht
