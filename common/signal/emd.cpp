#include "signal/emd.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <stdexcept>
#include <thread>

#include "signal/cubic_spline.h"

namespace hht {
namespace {

// Extrema of s[0..n-1]. A sign change of the first difference between difference indices a and b
// (all differences strictly between them are zero) is an extremum over the flat run a+1..b,
// placed at its middle.
void find_extrema(const double* s, int n, SignalBoundary boundary, const unsigned char* never,
                  Extrema& out) {
  out.maxima.clear();
  out.minima.clear();
  if (n < 2) return;
  const bool periodic = boundary == SignalBoundary::Periodic;
  // Periodic: difference n-1 is s[0] - s[n-1]; start after the last non-zero difference,
  // unwrapped to a negative index, so that the cycle is walked once from sample 0 on.
  // Open: start after the first non-zero difference; the end samples are never extrema.
  long a, stop;
  long b = 0;
  double first_difference;
  if (periodic) {
    long last = n - 1;
    first_difference = s[0] - s[n - 1];
    while (first_difference == 0.0) {
      if (--last < 0) return;  // constant
      first_difference = s[last + 1] - s[last];
    }
    a = last - n;
    stop = last + 1;
  } else {
    while (b < n - 1 && s[b + 1] == s[b]) ++b;
    if (b == n - 1) return;  // constant
    first_difference = s[b + 1] - s[b];
    a = b++;
    stop = n - 1;
  }
  int sign = first_difference > 0.0 ? 1 : -1;
  bool first_wrapped = false, first_is_max = false;
  auto emit = [&](bool is_max) {
    long mid = a + 1 + (b - a - 1) / 2;
    if (mid < 0) {  // the run straddles sample 0; only the first extremum can
      mid += n;
      first_wrapped = true;
      first_is_max = is_max;
    }
    if (never != nullptr && never[mid] != 0) return;
    (is_max ? out.maxima : out.minima).push_back(static_cast<int>(mid));
  };
  const long inner_stop = std::min<long>(stop, n - 1);
  for (; b < inner_stop; ++b) {
    const double d = s[b + 1] - s[b];
    if (d > 0.0) {
      if (sign < 0) emit(false);
      sign = 1;
      a = b;
    } else if (d < 0.0) {
      if (sign > 0) emit(true);
      sign = -1;
      a = b;
    }
  }
  if (b < stop) {  // periodic: the difference across the wrap, s[0] - s[n-1]
    const double d = s[0] - s[n - 1];
    if (d > 0.0 && sign < 0) emit(false);
    if (d < 0.0 && sign > 0) emit(true);
  }
  if (first_wrapped) {  // it was pushed first but lies last
    std::vector<int>& v = first_is_max ? out.maxima : out.minima;
    if (!v.empty() && v.front() > v.back()) std::rotate(v.begin(), v.begin() + 1, v.end());
  }
}

// Below this length a thread's start costs about what fitting one envelope takes.
constexpr int kParallelFrom = 1 << 16;
constexpr int kMirrored = 2;  // extrema of each kind mirrored beyond each end of an open signal

// Knots beyond one end of an open signal, innermost first.
struct EndKnots {
  int max_count = 0, min_count = 0;
  double max_x[kMirrored], max_y[kMirrored], min_x[kMirrored], min_y[kMirrored];
};

// near_max / near_min: up to kMirrored + 1 maxima / minima nearest to the end, from the end
// inward, at least one of each. dir is -1 at the left end, +1 at the right end.
EndKnots mirror_end(const double* s, const int* near_max, int nmax, const int* near_min, int nmin,
                    int end, int dir) {
  const bool max_first = std::abs(near_max[0] - end) < std::abs(near_min[0] - end);
  long centre = end;
  int max_from = 0, min_from = 0;
  bool end_is_max = false, end_is_min = false;
  if (max_first) {
    // Mirror about the first maximum, unless the end lies below the first minimum: then the end
    // acts as a minimum, so that the lower envelope does not cross the signal there.
    if (s[end] > s[near_min[0]]) {
      centre = near_max[0];
      max_from = 1;
    } else {
      end_is_min = true;
    }
  } else {
    if (s[end] < s[near_max[0]]) {
      centre = near_min[0];
      min_from = 1;
    } else {
      end_is_max = true;
    }
  }
  int max_count = std::min(kMirrored - (end_is_max ? 1 : 0), nmax - max_from);
  int min_count = std::min(kMirrored - (end_is_min ? 1 : 0), nmin - min_from);
  auto reaches_past_end = [&](const int* near, int from, int count) {
    return count > 0 && (2 * centre - near[from + count - 1] - end) * dir >= 0;
  };
  if (centre != end && (!reaches_past_end(near_max, max_from, max_count) ||
                        !reaches_past_end(near_min, min_from, min_count))) {
    // Mirroring about the extremum would leave the end to extrapolation: mirror about the end.
    centre = end;
    max_from = min_from = 0;
    max_count = std::min(kMirrored, nmax);
    min_count = std::min(kMirrored, nmin);
  }
  EndKnots k;
  if (end_is_max) {
    k.max_x[k.max_count] = end;
    k.max_y[k.max_count++] = s[end];
  }
  if (end_is_min) {
    k.min_x[k.min_count] = end;
    k.min_y[k.min_count++] = s[end];
  }
  for (int j = 0; j < max_count; ++j) {
    const int i = near_max[max_from + j];
    k.max_x[k.max_count] = static_cast<double>(2 * centre - i);
    k.max_y[k.max_count++] = s[i];
  }
  for (int j = 0; j < min_count; ++j) {
    const int i = near_min[min_from + j];
    k.min_x[k.min_count] = static_cast<double>(2 * centre - i);
    k.min_y[k.min_count++] = s[i];
  }
  return k;
}

// One sift's worth of buffers, reused across all sifts of all IMFs.
class Sifter {
 public:
  Sifter(int n, const EmdOptions& options)
      : n_(n),
        boundary_(options.boundary),
        never_(options.never_extremum != nullptr ? options.never_extremum->data() : nullptr),
        parallel_(options.threads >= 2 && n >= kParallelFrom) {
    upper_.resize(n);
    lower_.resize(n);
  }

  ExtremaCount count(const std::vector<double>& s) {
    find_extrema(s.data(), n_, boundary_, never_, extrema_);
    return {static_cast<int>(extrema_.maxima.size()), static_cast<int>(extrema_.minima.size())};
  }

  // s -= mean envelope; sd receives SD. Returns false, leaving s alone, when s has no maximum or
  // no minimum.
  bool sift(std::vector<double>& s, double& sd) {
    const ExtremaCount c = count(s);
    if (c.maxima == 0 || c.minima == 0) return false;
    if (boundary_ == SignalBoundary::Periodic) {
      knots(s, extrema_.maxima, upper_x_, upper_y_);
      knots(s, extrema_.minima, lower_x_, lower_y_);
    } else {
      mirrored_knots(s);
    }
    auto fit = [this](bool upper) {
      const std::vector<double>& x = upper ? upper_x_ : lower_x_;
      const std::vector<double>& y = upper ? upper_y_ : lower_y_;
      std::vector<double>& out = upper ? upper_ : lower_;
      CubicSplineWorkspace& ws = upper ? upper_ws_ : lower_ws_;
      if (boundary_ == SignalBoundary::Periodic) {
        periodic_cubic_spline(x, y, n_, out, ws);
      } else {
        not_a_knot_cubic_spline(x, y, n_, out, ws);
      }
    };
    if (parallel_) {
      std::exception_ptr lower_failure;
      std::thread lower([&] {
        try {
          fit(false);
        } catch (...) {
          lower_failure = std::current_exception();
        }
      });
      try {
        fit(true);
      } catch (...) {
        lower.join();
        throw;
      }
      lower.join();
      if (lower_failure) std::rethrow_exception(lower_failure);
    } else {
      fit(true);
      fit(false);
    }
    double change = 0.0, before = 0.0;
    double* v = s.data();
    for (int t = 0; t < n_; ++t) {
      const double mean = 0.5 * (upper_[t] + lower_[t]);
      change += mean * mean;
      before += v[t] * v[t];
      v[t] -= mean;
    }
    sd = before > 0.0 ? change / before : 0.0;
    return true;
  }

 private:
  static void knots(const std::vector<double>& s, const std::vector<int>& at,
                    std::vector<double>& x, std::vector<double>& y) {
    x.resize(at.size());
    y.resize(at.size());
    for (size_t k = 0; k < at.size(); ++k) {
      x[k] = at[k];
      y[k] = s[at[k]];
    }
  }

  // Knots of both envelopes of an open signal: mirrored left end, extrema, mirrored right end.
  void mirrored_knots(const std::vector<double>& s) {
    const std::vector<int>& mx = extrema_.maxima;
    const std::vector<int>& mn = extrema_.minima;
    const int nmax = std::min<int>(kMirrored + 1, mx.size());
    const int nmin = std::min<int>(kMirrored + 1, mn.size());
    int left_max[kMirrored + 1], left_min[kMirrored + 1];
    int right_max[kMirrored + 1], right_min[kMirrored + 1];
    for (int j = 0; j < nmax; ++j) {
      left_max[j] = mx[j];
      right_max[j] = mx[mx.size() - 1 - j];
    }
    for (int j = 0; j < nmin; ++j) {
      left_min[j] = mn[j];
      right_min[j] = mn[mn.size() - 1 - j];
    }
    const EndKnots left = mirror_end(s.data(), left_max, nmax, left_min, nmin, 0, -1);
    const EndKnots right = mirror_end(s.data(), right_max, nmax, right_min, nmin, n_ - 1, 1);
    assemble(s, left.max_x, left.max_y, left.max_count, mx, right.max_x, right.max_y,
             right.max_count, upper_x_, upper_y_);
    assemble(s, left.min_x, left.min_y, left.min_count, mn, right.min_x, right.min_y,
             right.min_count, lower_x_, lower_y_);
  }

  static void assemble(const std::vector<double>& s, const double* lx, const double* ly, int nl,
                       const std::vector<int>& at, const double* rx, const double* ry, int nr,
                       std::vector<double>& x, std::vector<double>& y) {
    x.clear();
    y.clear();
    for (int j = nl - 1; j >= 0; --j) {  // outermost first
      x.push_back(lx[j]);
      y.push_back(ly[j]);
    }
    for (int i : at) {
      x.push_back(i);
      y.push_back(s[i]);
    }
    for (int j = 0; j < nr; ++j) {
      x.push_back(rx[j]);
      y.push_back(ry[j]);
    }
  }

  int n_;
  SignalBoundary boundary_;
  const unsigned char* never_;
  bool parallel_;
  Extrema extrema_;
  std::vector<double> upper_x_, upper_y_, lower_x_, lower_y_, upper_, lower_;
  CubicSplineWorkspace upper_ws_, lower_ws_;
};

}  // namespace

void find_extrema(const std::vector<double>& s, SignalBoundary boundary,
                  const std::vector<unsigned char>* never_extremum, Extrema& out) {
  if (never_extremum != nullptr && never_extremum->size() != s.size()) {
    throw std::invalid_argument("find_extrema: never_extremum must have the signal's size");
  }
  find_extrema(s.data(), static_cast<int>(s.size()), boundary,
               never_extremum != nullptr ? never_extremum->data() : nullptr, out);
}

ExtremaCount count_extrema(const std::vector<double>& s, SignalBoundary boundary,
                           const std::vector<unsigned char>* never_extremum) {
  Extrema e;
  find_extrema(s, boundary, never_extremum, e);
  return {static_cast<int>(e.maxima.size()), static_cast<int>(e.minima.size())};
}

EmdResult emd(const std::vector<double>& signal, const EmdOptions& options) {
  if (options.never_extremum != nullptr && options.never_extremum->size() != signal.size()) {
    throw std::invalid_argument("emd: never_extremum must have the signal's size");
  }
  EmdResult result;
  for (double v : signal) {
    if (!std::isfinite(v)) {
      result.status = EmdStatus::NonFiniteInput;
      return result;
    }
  }
  result.residue = signal;
  const int n = static_cast<int>(signal.size());
  const int min_extrema = std::max(options.min_extrema, 1);
  const int max_sifts = std::max(options.max_sifts, 1);
  Sifter sifter(n, options);
  long previous_extrema = std::numeric_limits<long>::max();
  std::vector<double>& r = result.residue;
  while (options.max_imfs <= 0 || static_cast<int>(result.imfs.size()) < options.max_imfs) {
    const ExtremaCount c = sifter.count(r);
    const long extrema = static_cast<long>(c.maxima) + c.minima;
    if (c.maxima < min_extrema || c.minima < min_extrema || extrema >= previous_extrema) break;
    previous_extrema = extrema;
    std::vector<double> s = r;
    int sifts = 0;
    double sd = 0.0;
    while (sifts < max_sifts && sifter.sift(s, sd)) {
      ++sifts;
      if (sd < options.sd_threshold) break;
    }
    for (int t = 0; t < n; ++t) r[t] -= s[t];
    result.imfs.push_back(std::move(s));
    result.sifts.push_back(sifts);
  }
  return result;
}

}  // namespace hht
