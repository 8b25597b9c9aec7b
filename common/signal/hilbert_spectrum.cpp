#include "signal/hilbert_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace hht {
namespace {

// FFTW's planner is not thread-safe: plan creation and destruction go through this lock.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

std::atomic<long> plan_count{0};

constexpr double kPi = 3.14159265358979323846264338327950288;

}  // namespace

struct HilbertTransformer::Plans {
  int n;
  double* signal;         // x
  fftw_complex* half;     // its half spectrum X[0..n/2], then -i sgn(k) X[k]
  double* transform;      // n H[x] (FFTW's transforms are unnormalised)
  fftw_plan forward, backward;
};

HilbertTransformer::HilbertTransformer(int n) {
  if (n < 1) throw std::invalid_argument("HilbertTransformer: need at least one sample");
  plans_ = std::make_unique<Plans>();
  plans_->n = n;
  plans_->signal = fftw_alloc_real(n);
  plans_->half = fftw_alloc_complex(n / 2 + 1);
  plans_->transform = fftw_alloc_real(n);
  std::lock_guard<std::mutex> lock(planner_mutex());
  plans_->forward = fftw_plan_dft_r2c_1d(n, plans_->signal, plans_->half, FFTW_ESTIMATE);
  plans_->backward = fftw_plan_dft_c2r_1d(n, plans_->half, plans_->transform, FFTW_ESTIMATE);
  plan_count += 2;
}

HilbertTransformer::~HilbertTransformer() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(plans_->forward);
  fftw_destroy_plan(plans_->backward);
  fftw_free(plans_->signal);
  fftw_free(plans_->half);
  fftw_free(plans_->transform);
}

int HilbertTransformer::size() const { return plans_->n; }

long HilbertTransformer::plans_created() { return plan_count.load(); }

// The analytic spectrum (DC, Nyquist x1; positive x2; negative x0) has x as its real part and
// H[x] as its imaginary part, where H multiplies X[k] by -i sgn(k) with sgn = 0 at DC and
// Nyquist. H[x] is real, so one real-to-complex and one complex-to-real transform give it, at
// about half the cost of a full complex inverse transform; and Re z is x itself, exactly.
const double* HilbertTransformer::hilbert_transform_times_n(const std::vector<double>& x) {
  const int n = plans_->n;
  if (static_cast<int>(x.size()) != n) {
    throw std::invalid_argument("HilbertTransformer: signal length differs from the plan's");
  }
  std::copy(x.begin(), x.end(), plans_->signal);
  fftw_execute(plans_->forward);
  fftw_complex* X = plans_->half;
  X[0][0] = X[0][1] = 0.0;
  const int positive_end = (n + 1) / 2;  // bins 1..(n-1)/2; bin n/2 of an even n is Nyquist
  for (int k = 1; k < positive_end; ++k) {
    const double re = X[k][0];
    X[k][0] = X[k][1];
    X[k][1] = -re;
  }
  if (n % 2 == 0) X[n / 2][0] = X[n / 2][1] = 0.0;
  fftw_execute(plans_->backward);
  return plans_->transform;
}

void HilbertTransformer::analytic_signal(const std::vector<double>& x,
                                         std::vector<std::complex<double>>& z) {
  const double* h = hilbert_transform_times_n(x);
  const int n = plans_->n;
  const double scale = 1.0 / n;
  z.resize(n);
  for (int t = 0; t < n; ++t) z[t] = {x[t], h[t] * scale};
}

HilbertSpectrum HilbertTransformer::spectrum(const std::vector<double>& imf,
                                             SignalBoundary boundary) {
  const double* h = hilbert_transform_times_n(imf);
  const int n = plans_->n;
  const double scale = 1.0 / n;
  HilbertSpectrum s;
  s.amplitude.resize(n);
  s.phase.resize(n);
  s.frequency.resize(n);
  double squares = 0.0;
  for (int t = 0; t < n; ++t) {
    const double re = imf[t], im = h[t] * scale;
    const double a2 = re * re + im * im;
    s.amplitude[t] = std::sqrt(a2);
    s.phase[t] = std::atan2(im, re);
    squares += a2;
  }
  // arg(z[t+1] conj z[t]) is the phase step wrapped into (-pi, pi]: computed from the phases,
  // it costs no second atan2 per sample. Open signals have no successor for the last sample:
  // it copies its predecessor at the end.
  const int own = boundary == SignalBoundary::Open && n > 1 ? n - 1 : n;
  for (int t = 0; t < own; ++t) {
    double step = s.phase[t + 1 < n ? t + 1 : 0] - s.phase[t];
    if (step > kPi) step -= 2.0 * kPi;
    if (step <= -kPi) step += 2.0 * kPi;
    s.frequency[t] = step / (2.0 * kPi);
  }
  // Steps lie in (-pi, pi], so a meaningful frequency already lies in [0, 0.5].
  const double amplitude_floor = 1e-3 * std::sqrt(squares / n);
  auto meaningful = [&](int t) {
    return s.amplitude[t] >= amplitude_floor && s.frequency[t] >= 0.0;
  };
  double weighted = 0.0, weight = 0.0;
  for (int t = 0; t < own; ++t) {
    if (meaningful(t)) {
      weighted += s.amplitude[t] * s.frequency[t];
      weight += s.amplitude[t];
    }
  }
  const double mean = weight > 0.0 ? weighted / weight : 0.0;
  for (int t = 0; t < own; ++t) {
    if (!meaningful(t)) s.frequency[t] = mean;
  }
  if (own < n) s.frequency[n - 1] = s.frequency[n - 2];
  return s;
}

std::vector<HilbertSpectrum> hilbert_spectra(const std::vector<std::vector<double>>& imfs,
                                             SignalBoundary boundary, int threads) {
  std::vector<HilbertSpectrum> spectra(imfs.size());
  if (imfs.empty()) return spectra;
  const size_t n = imfs.front().size();
  for (const std::vector<double>& imf : imfs) {
    if (imf.size() != n) throw std::invalid_argument("hilbert_spectra: IMFs of unequal lengths");
  }
  // IMFs are independent: worker w takes IMFs w, w + workers, ... with its own plans.
  const int workers = static_cast<int>(std::clamp<size_t>(std::max(threads, 1), 1, imfs.size()));
  std::vector<std::exception_ptr> failures(workers);
  auto work = [&](int w) {
    try {
      HilbertTransformer transformer(static_cast<int>(n));
      for (size_t i = w; i < imfs.size(); i += workers) {
        spectra[i] = transformer.spectrum(imfs[i], boundary);
      }
    } catch (...) {
      failures[w] = std::current_exception();
    }
  };
  std::vector<std::thread> helpers;
  for (int w = 1; w < workers; ++w) helpers.emplace_back(work, w);
  work(0);
  for (std::thread& h : helpers) h.join();
  for (const std::exception_ptr& f : failures) {
    if (f) std::rethrow_exception(f);
  }
  return spectra;
}

double mean_frequency(const HilbertSpectrum& spectrum) {
  double weighted = 0.0, weight = 0.0;
  for (size_t t = 0; t < spectrum.amplitude.size(); ++t) {
    weighted += spectrum.amplitude[t] * spectrum.frequency[t];
    weight += spectrum.amplitude[t];
  }
  return weight > 0.0 ? weighted / weight : 0.0;
}

double energy(const std::vector<double>& imf) {
  double e = 0.0;
  for (double v : imf) e += v * v;
  return e;
}

std::vector<std::vector<double>> frequency_histogram(const std::vector<HilbertSpectrum>& spectra,
                                                     int bins) {
  if (bins < 1) throw std::invalid_argument("frequency_histogram: need at least one bin");
  std::vector<std::vector<double>> histograms;
  histograms.reserve(spectra.size());
  for (const HilbertSpectrum& s : spectra) {
    std::vector<double> h(bins, 0.0);
    for (size_t t = 0; t < s.frequency.size(); ++t) {
      const int bin = std::clamp(static_cast<int>(s.frequency[t] * 2.0 * bins), 0, bins - 1);
      h[bin] += s.amplitude[t];
    }
    histograms.push_back(std::move(h));
  }
  return histograms;
}

}  // namespace hht
