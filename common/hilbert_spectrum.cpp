#include "hilbert_spectrum.h"

#include <fftw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace hht {
namespace {

// FFTW's planner is not thread-safe: plan creation and destruction go through this lock.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

std::atomic<long> plan_count{0};

constexpr double kTwoPi = 6.283185307179586476925286766559;

}  // namespace

struct HilbertTransformer::Plans {
  int n;
  double* real;
  fftw_complex* spectrum;  // n entries: the r2c half spectrum, then the full analytic spectrum
  fftw_plan forward, backward;
};

HilbertTransformer::HilbertTransformer(int n) {
  if (n < 1) throw std::invalid_argument("HilbertTransformer: need at least one sample");
  plans_ = std::make_unique<Plans>();
  plans_->n = n;
  plans_->real = fftw_alloc_real(n);
  plans_->spectrum = fftw_alloc_complex(n);
  std::lock_guard<std::mutex> lock(planner_mutex());
  plans_->forward = fftw_plan_dft_r2c_1d(n, plans_->real, plans_->spectrum, FFTW_ESTIMATE);
  plans_->backward = fftw_plan_dft_1d(n, plans_->spectrum, plans_->spectrum, FFTW_BACKWARD,
                                      FFTW_ESTIMATE);
  plan_count += 2;
}

HilbertTransformer::~HilbertTransformer() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(plans_->forward);
  fftw_destroy_plan(plans_->backward);
  fftw_free(plans_->real);
  fftw_free(plans_->spectrum);
}

int HilbertTransformer::size() const { return plans_->n; }

long HilbertTransformer::plans_created() { return plan_count.load(); }

void HilbertTransformer::analytic_signal(const std::vector<double>& x,
                                         std::vector<std::complex<double>>& z) {
  const int n = plans_->n;
  if (static_cast<int>(x.size()) != n) {
    throw std::invalid_argument("HilbertTransformer: signal length differs from the plan's");
  }
  std::copy(x.begin(), x.end(), plans_->real);
  fftw_execute(plans_->forward);
  // Bins 1..(n-1)/2 are the positive frequencies; bin n/2 of an even n is Nyquist (weight 1).
  fftw_complex* X = plans_->spectrum;
  const int positive_end = (n + 1) / 2;
  for (int k = 1; k < positive_end; ++k) {
    X[k][0] *= 2.0;
    X[k][1] *= 2.0;
  }
  for (int k = n / 2 + 1; k < n; ++k) X[k][0] = X[k][1] = 0.0;
  fftw_execute(plans_->backward);
  z.resize(n);
  const double scale = 1.0 / n;  // FFTW's transforms are unnormalised
  for (int t = 0; t < n; ++t) z[t] = {X[t][0] * scale, X[t][1] * scale};
}

HilbertSpectrum HilbertTransformer::spectrum(const std::vector<double>& imf,
                                             SignalBoundary boundary) {
  analytic_signal(imf, z_);
  const int n = plans_->n;
  HilbertSpectrum s;
  s.amplitude.resize(n);
  s.phase.resize(n);
  s.frequency.resize(n);
  double squares = 0.0;
  for (int t = 0; t < n; ++t) {
    s.amplitude[t] = std::abs(z_[t]);
    s.phase[t] = std::arg(z_[t]);
    squares += s.amplitude[t] * s.amplitude[t];
  }
  // Open signals have no successor for the last sample: it copies its predecessor at the end.
  const int own = boundary == SignalBoundary::Open && n > 1 ? n - 1 : n;
  for (int t = 0; t < own; ++t) {
    const int next = t + 1 < n ? t + 1 : 0;
    s.frequency[t] = std::arg(z_[next] * std::conj(z_[t])) / kTwoPi;
  }
  // arg() lies in [-pi, pi], so a meaningful frequency already lies in [0, 0.5].
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
                                             SignalBoundary boundary) {
  std::vector<HilbertSpectrum> spectra;
  if (imfs.empty()) return spectra;
  HilbertTransformer transformer(static_cast<int>(imfs.front().size()));
  spectra.reserve(imfs.size());
  for (const std::vector<double>& imf : imfs) spectra.push_back(transformer.spectrum(imf, boundary));
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
