#include "signal/spectral_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <vector>

namespace {

using hht::EmdResult;
using hht::FrequencyBand;
using hht::SignalBoundary;

const double kPi = std::acos(-1.0);
const int kN = 8192;  // 16 cycles of the slowest tone: enough extrema for an IMF

std::vector<double> tone(double period, double amplitude = 1.0, double phase = 0.0) {
  std::vector<double> s(kN);
  for (int t = 0; t < kN; ++t) s[t] = amplitude * std::cos(2.0 * kPi * t / period + phase);
  return s;
}

std::vector<double> sum(const std::vector<std::vector<double>>& parts) {
  std::vector<double> s(parts[0].size(), 0.0);
  for (const auto& p : parts) {
    for (size_t t = 0; t < s.size(); ++t) s[t] += p[t];
  }
  return s;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (size_t t = 0; t < a.size(); ++t) m = std::max(m, std::abs(a[t] - b[t]));
  return m;
}

double max_abs(const std::vector<double>& a) { return max_abs_diff(a, std::vector<double>(a.size(), 0.0)); }

// |DFT coefficient| of x at `cycles` cycles over its length.
double dft_magnitude(const std::vector<double>& x, int cycles) {
  std::complex<double> c = 0.0;
  for (size_t t = 0; t < x.size(); ++t) c += x[t] * std::polar(1.0, -2.0 * kPi * cycles * t / x.size());
  return std::abs(c);
}

struct Decomposed {
  std::vector<double> signal;
  EmdResult emd;
  std::vector<hht::HilbertSpectrum> spectra;
};

Decomposed decompose(std::vector<double> signal) {
  Decomposed d;
  d.signal = std::move(signal);
  d.emd = hht::emd(d.signal);
  d.spectra = hht::hilbert_spectra(d.emd.imfs, SignalBoundary::Periodic);
  return d;
}

// Periods 8, 64 and 512 samples: 0.125, 0.0156 and 0.00195 cycles per sample.
const std::vector<double> kFast = tone(8.0), kMiddle = tone(64.0, 0.8, 0.7), kSlow = tone(512.0, 1.2, 2.1);

// Every band, with gains that remove, attenuate and enhance: the expected output is built from
// the known tones (the one whose frequency the band selects scaled by the gain, the others
// kept), not from the decomposition.
TEST(SpectralFilter, EveryBandWithNonUnitGains) {
  const Decomposed d = decompose(sum({kFast, kMiddle, kSlow}));
  ASSERT_GE(d.emd.imfs.size(), 3u);
  struct Case {
    FrequencyBand band;
    bool fast, middle, slow;  // which tones the band selects
  };
  const Case cases[] = {
      {{0.05, 0.5, false}, true, false, false},   // high frequencies
      {{0.0, 0.05, false}, false, true, true},    // low frequencies
      {{0.01, 0.03, false}, false, true, false},  // inside
      {{0.01, 0.03, true}, true, false, true},    // outside
  };
  for (const Case& c : cases) {
    for (double gain : {0.0, 0.5, 3.0}) {
      SCOPED_TRACE(testing::Message() << "band [" << c.band.low << ", " << c.band.high << "]"
                                      << (c.band.outside ? " outside" : "") << ", gain " << gain);
      auto scaled = [&](const std::vector<double>& x, bool selected) {
        std::vector<double> y = x;
        for (double& v : y) v *= selected ? gain : 1.0;
        return y;
      };
      const std::vector<double> expected = sum({scaled(kFast, c.fast), scaled(kMiddle, c.middle), scaled(kSlow, c.slow)});
      const std::vector<double> out = hht::filter_by_frequency(d.emd, d.spectra, c.band, gain);
      // EMD's separation error on these tones times the largest weight: measured 6.2e-4 at
      // gain 0, 1.25e-3 at gain 3
      EXPECT_LT(max_abs_diff(out, expected), 1e-3 * std::max(1.0, gain));
    }
  }
}

TEST(SpectralFilter, LowPassRemovesTheHighToneAndKeepsTheLowOne) {
  const Decomposed d = decompose(sum({kFast, kMiddle}));
  const std::vector<double> out = hht::filter_by_frequency(d.emd, d.spectra, {0.05, 0.5}, 0.0);
  // The DFT line of the period-8 tone (1024 cycles) loses more than 99.9% of its magnitude;
  // the period-64 line (128 cycles) keeps its magnitude to 0.1%.
  EXPECT_LT(dft_magnitude(out, 1024), 1e-3 * dft_magnitude(d.signal, 1024));
  EXPECT_NEAR(dft_magnitude(out, 128), dft_magnitude(d.signal, 128), 1e-3 * dft_magnitude(d.signal, 128));
  EXPECT_LT(max_abs_diff(out, kMiddle), 1e-3);  // measured 5e-5
}

TEST(SpectralFilter, HighPassBandPassBandStopAndEnhancement) {
  const Decomposed d = decompose(sum({kFast, kMiddle, kSlow}));
  ASSERT_GE(d.emd.imfs.size(), 3u);
  const double tolerance = 2e-3;  // EMD's separation error on these tones: measured up to 6e-4
  // High-pass: remove everything up to 0.05 (the residue, a near-zero trend, stays).
  std::vector<double> out = hht::filter_by_frequency(d.emd, d.spectra, {0.0, 0.05}, 0.0);
  EXPECT_LT(max_abs_diff(out, sum({kFast, d.emd.residue})), tolerance);
  // Band-pass around the middle tone: remove what lies outside [0.01, 0.03].
  out = hht::filter_by_frequency(d.emd, d.spectra, {0.01, 0.03, true}, 0.0);
  EXPECT_LT(max_abs_diff(out, sum({kMiddle, d.emd.residue})), tolerance);
  // Band-stop: remove [0.01, 0.03].
  out = hht::filter_by_frequency(d.emd, d.spectra, {0.01, 0.03}, 0.0);
  EXPECT_LT(max_abs_diff(out, sum({kFast, kSlow, d.emd.residue})), tolerance);
  // Enhancement: double the band above 0.05.
  out = hht::filter_by_frequency(d.emd, d.spectra, {0.05, 0.5}, 2.0);
  EXPECT_LT(max_abs_diff(out, sum({kFast, kFast, kMiddle, kSlow, d.emd.residue})), 2.0 * tolerance);
}

TEST(SpectralFilter, KeepCoarsest) {
  const Decomposed d = decompose(sum({kFast, kMiddle, kSlow}));
  const int count = static_cast<int>(d.emd.imfs.size());
  ASSERT_GE(count, 3);
  EXPECT_EQ(hht::keep_coarsest(d.emd, 0), d.emd.residue);
  EXPECT_LT(max_abs_diff(hht::keep_coarsest(d.emd, count), d.signal), 1e-12 * max_abs(d.signal));
  EXPECT_EQ(hht::keep_coarsest(d.emd, count + 5), hht::keep_coarsest(d.emd, count));
  std::vector<double> coarsest = d.emd.residue;
  for (int t = 0; t < kN; ++t) coarsest[t] += d.emd.imfs[count - 1][t];
  EXPECT_EQ(hht::keep_coarsest(d.emd, 1), coarsest);
  EXPECT_THROW(hht::keep_coarsest(d.emd, -1), std::invalid_argument);
}

TEST(SpectralFilter, RejectsMismatchedSpectra) {
  const Decomposed d = decompose(sum({kFast, kMiddle}));
  std::vector<hht::HilbertSpectrum> fewer(d.spectra.begin(), d.spectra.end() - 1);
  EXPECT_THROW(hht::filter_by_frequency(d.emd, fewer, {}, 0.0), std::invalid_argument);
  std::vector<hht::HilbertSpectrum> shorter = d.spectra;
  shorter[0].frequency.pop_back();
  EXPECT_THROW(hht::filter_by_frequency(d.emd, shorter, {}, 0.0), std::invalid_argument);
}

}  // namespace
