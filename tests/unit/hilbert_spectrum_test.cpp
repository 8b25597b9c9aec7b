#include "signal/hilbert_spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using hht::HilbertSpectrum;
using hht::HilbertTransformer;
using hht::SignalBoundary;

const double kPi = std::acos(-1.0);

std::vector<double> cosine(int n, double f, double phase = 0.0) {
  std::vector<double> x(n);
  for (int t = 0; t < n; ++t) x[t] = std::cos(2.0 * kPi * f * t + phase);
  return x;
}

// Distance between two angles, in (-pi, pi].
double angle_gap(double a, double b) { return std::remainder(a - b, 2.0 * kPi); }

TEST(HilbertSpectrum, PureToneWithWholeCyclesEvenAndOddLength) {
  for (int n : {1024, 1023}) {
    const double f = 37.0 / n;
    const std::vector<double> x = cosine(n, f, 0.4);
    HilbertTransformer h(n);
    const HilbertSpectrum s = h.spectrum(x, SignalBoundary::Periodic);
    ASSERT_EQ(s.amplitude.size(), static_cast<size_t>(n));
    for (int t = 0; t < n; ++t) {
      EXPECT_NEAR(s.amplitude[t], 1.0, 1e-9) << n << " " << t;
      EXPECT_NEAR(s.frequency[t], f, 1e-9) << n << " " << t;
      EXPECT_NEAR(angle_gap(s.phase[t], 2.0 * kPi * f * t + 0.4), 0.0, 1e-9) << n << " " << t;
    }
    EXPECT_NEAR(hht::mean_frequency(s), f, 1e-9);
  }
}

TEST(HilbertSpectrum, RealPartIsTheSignalAndSineIsTheTransformOfCosine) {
  std::mt19937 rng(4);
  std::normal_distribution<double> noise;
  for (int n : {256, 255}) {
    std::vector<double> x(n);
    for (double& v : x) v = 3.0 + noise(rng);  // DC and, for even n, Nyquist content
    HilbertTransformer h(n);
    std::vector<std::complex<double>> z;
    h.analytic_signal(x, z);
    for (int t = 0; t < n; ++t) EXPECT_NEAR(z[t].real(), x[t], 1e-12);
    h.analytic_signal(cosine(n, 5.0 / n), z);
    for (int t = 0; t < n; ++t) EXPECT_NEAR(z[t].imag(), std::sin(2.0 * kPi * 5.0 * t / n), 1e-12);
  }
}

TEST(HilbertSpectrum, DcAndNyquistKeepWeightOne) {
  const int n = 64;
  HilbertTransformer h(n);
  std::vector<std::complex<double>> z;
  h.analytic_signal(std::vector<double>(n, 2.0), z);
  for (const auto& v : z) EXPECT_NEAR(std::abs(v - std::complex<double>(2.0, 0.0)), 0.0, 1e-12);
  const std::vector<double> nyquist = cosine(n, 0.5);  // (-1)^t
  const HilbertSpectrum s = h.spectrum(nyquist, SignalBoundary::Periodic);
  for (int t = 0; t < n; ++t) {
    EXPECT_NEAR(s.amplitude[t], 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(s.frequency[t], 0.5);
  }
}

TEST(HilbertSpectrum, AmplitudeModulatedToneGivesItsEnvelope) {
  const int n = 4096;
  const double fc = 300.0 / n, fm = 7.0 / n;
  std::vector<double> x(n), envelope(n);
  for (int t = 0; t < n; ++t) {
    envelope[t] = 1.0 + 0.5 * std::cos(2.0 * kPi * fm * t);
    x[t] = envelope[t] * std::cos(2.0 * kPi * fc * t);
  }
  const HilbertSpectrum s = HilbertTransformer(n).spectrum(x, SignalBoundary::Periodic);
  // All spectral lines are at positive frequencies: the envelope and carrier come out exactly.
  for (int t = 0; t < n; ++t) {
    EXPECT_NEAR(s.amplitude[t], envelope[t], 1e-9 * envelope[t]) << t;
    EXPECT_NEAR(s.frequency[t], fc, 1e-9) << t;
  }
}

TEST(HilbertSpectrum, FrequencyModulatedToneGivesItsInstantaneousFrequency) {
  const int n = 4096;
  const double fc = 410.0 / n, fm = 8.0 / n, beta = 5.0;  // whole cycles; deviation beta fm = 0.0098
  auto theta = [&](double t) { return 2.0 * kPi * fc * t + beta * std::sin(2.0 * kPi * fm * t); };
  std::vector<double> x(n);
  for (int t = 0; t < n; ++t) x[t] = std::cos(theta(t));
  const HilbertSpectrum s = HilbertTransformer(n).spectrum(x, SignalBoundary::Periodic);
  double worst = 0.0;
  for (int t = 0; t < n; ++t) {
    // The phase advance from t to t+1, the discrete counterpart of d theta / dt.
    const double expected = (theta(t + 1) - theta(t)) / (2.0 * kPi);
    worst = std::max(worst, std::abs(s.frequency[t] - expected) / expected);
    EXPECT_NEAR(s.amplitude[t], 1.0, 1e-3) << t;
  }
  // Carson's bandwidth 2 (beta + 1) fm = 0.023 is far from 0 and 0.5: the FFT sees no
  // negative-frequency leak beyond the Bessel tails.
  EXPECT_LT(worst, 1e-3);
}

TEST(HilbertSpectrum, NearZeroAmplitudeTakesTheMeanFrequency) {
  const int n = 2048;
  std::vector<double> x = cosine(n, 100.0 / n);
  for (int t = 1000; t < 1600; ++t) x[t] = 0.0;  // a silent stretch
  const HilbertSpectrum s = HilbertTransformer(n).spectrum(x, SignalBoundary::Periodic);
  double squares = 0.0;
  for (double a : s.amplitude) squares += a * a;
  const double floor = 1e-3 * std::sqrt(squares / n);
  const double mean = hht::mean_frequency(s);
  int silent = 0;
  for (int t = 0; t < n; ++t) {
    EXPECT_GE(s.frequency[t], 0.0);
    EXPECT_LE(s.frequency[t], 0.5);
    if (s.amplitude[t] < floor) {
      ++silent;
      EXPECT_NEAR(s.frequency[t], mean, 1e-12) << t;  // same mean, summed in another order
    }
  }
  // The cut's Hilbert transform decays like 1 / distance, so only the middle of the stretch
  // falls below the floor (86 of its 600 samples here).
  EXPECT_GT(silent, 50);
  EXPECT_NEAR(mean, 100.0 / n, 2e-3);

  const HilbertSpectrum zero = HilbertTransformer(16).spectrum(std::vector<double>(16, 0.0), SignalBoundary::Periodic);
  for (int t = 0; t < 16; ++t) {
    EXPECT_EQ(zero.amplitude[t], 0.0);
    EXPECT_EQ(zero.frequency[t], 0.0);
  }
}

// Two tones of whole cycles, the faster one 0.9 as strong: z = e^(i w1 t) + 0.9 e^(i w2 t)
// exactly, and where the two are in opposition its phase steps backwards (down to about
// -0.4 cycles per sample). There the frequency must be the amplitude-weighted mean over the
// other samples; elsewhere the phase step itself.
TEST(HilbertSpectrum, BackwardPhaseStepTakesTheMeanFrequency) {
  const int n = 1000;
  const double f1 = 50.0 / n, f2 = 100.0 / n;
  std::vector<std::complex<double>> z(n);
  std::vector<double> x(n);
  for (int t = 0; t < n; ++t) {
    z[t] = std::polar(1.0, 2.0 * kPi * f1 * t) + std::polar(0.9, 2.0 * kPi * f2 * t);
    x[t] = z[t].real();
  }
  std::vector<double> step(n);
  double weighted = 0.0, weights = 0.0;
  int backwards = 0;
  for (int t = 0; t < n; ++t) {
    step[t] = std::arg(z[(t + 1) % n] * std::conj(z[t])) / (2.0 * kPi);
    if (step[t] < 0) {
      ++backwards;
    } else {
      weighted += std::abs(z[t]) * step[t];
      weights += std::abs(z[t]);
    }
  }
  ASSERT_GT(backwards, 20);  // 50 oppositions, a few samples each
  const double mean = weighted / weights;
  const HilbertSpectrum s = HilbertTransformer(n).spectrum(x, SignalBoundary::Periodic);
  for (int t = 0; t < n; ++t) {
    ASSERT_NEAR(s.amplitude[t], std::abs(z[t]), 1e-9) << t;
    ASSERT_NEAR(s.frequency[t], step[t] < 0 ? mean : step[t], 1e-9) << t;
  }
}

TEST(HilbertSpectrum, OpenSignalLastSampleCopiesItsPredecessor) {
  const int n = 500;
  const std::vector<double> x = cosine(n, 0.0731);  // not whole cycles: the ends disagree
  const HilbertSpectrum open = HilbertTransformer(n).spectrum(x, SignalBoundary::Open);
  const HilbertSpectrum cyclic = HilbertTransformer(n).spectrum(x, SignalBoundary::Periodic);
  EXPECT_EQ(open.frequency[n - 1], open.frequency[n - 2]);
  EXPECT_NE(cyclic.frequency[n - 1], cyclic.frequency[n - 2]);
  EXPECT_NEAR(open.frequency[n / 2], 0.0731, 1e-3);  // far from the ends
}

TEST(HilbertSpectrum, PlansAreCreatedOnceAndReused) {
  const int n = 1000;
  const long before = HilbertTransformer::plans_created();
  HilbertTransformer h(n);
  EXPECT_EQ(h.size(), n);
  const long after_construction = HilbertTransformer::plans_created();
  EXPECT_EQ(after_construction - before, 2);
  const std::vector<double> a = cosine(n, 0.01), b = cosine(n, 0.2, 1.0);
  const HilbertSpectrum first = h.spectrum(a, SignalBoundary::Periodic);
  for (int i = 0; i < 10; ++i) h.spectrum(i % 2 ? a : b, SignalBoundary::Periodic);
  const HilbertSpectrum again = h.spectrum(a, SignalBoundary::Periodic);
  EXPECT_EQ(HilbertTransformer::plans_created(), after_construction);
  EXPECT_EQ(first.amplitude, again.amplitude);
  EXPECT_EQ(first.frequency, again.frequency);

  // One transformer (two plans) per thread, whatever the number of IMFs; same result.
  const long before_all = HilbertTransformer::plans_created();
  const std::vector<HilbertSpectrum> serial = hht::hilbert_spectra({a, b, a, b, a}, SignalBoundary::Periodic, 1);
  EXPECT_EQ(HilbertTransformer::plans_created() - before_all, 2);
  const std::vector<HilbertSpectrum> parallel = hht::hilbert_spectra({a, b, a, b, a}, SignalBoundary::Periodic, 2);
  EXPECT_EQ(HilbertTransformer::plans_created() - before_all, 2 + 4);
  ASSERT_EQ(serial.size(), 5u);
  ASSERT_EQ(parallel.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(serial[i].frequency, (i % 2 ? h.spectrum(b, SignalBoundary::Periodic) : first).frequency);
    EXPECT_EQ(parallel[i].amplitude, serial[i].amplitude);
    EXPECT_EQ(parallel[i].phase, serial[i].phase);
    EXPECT_EQ(parallel[i].frequency, serial[i].frequency);
  }
  EXPECT_THROW(h.spectrum(std::vector<double>(n + 1, 0.0), SignalBoundary::Periodic), std::invalid_argument);
  EXPECT_THROW(hht::hilbert_spectra({a, std::vector<double>(10, 0.0)}, SignalBoundary::Periodic),
               std::invalid_argument);
  EXPECT_THROW(HilbertTransformer(0), std::invalid_argument);
}

TEST(HilbertSpectrum, EnergyAndFrequencyHistogram) {
  const int n = 1000;
  const std::vector<double> low = cosine(n, 0.025), high = cosine(n, 0.315);  // mid-bin
  EXPECT_NEAR(hht::energy(low), n / 2.0, 1e-9);
  EXPECT_EQ(hht::energy({3.0, -4.0}), 25.0);
  const std::vector<HilbertSpectrum> spectra = hht::hilbert_spectra({low, high}, SignalBoundary::Periodic);
  const int bins = 50;  // 0.01 cycles per sample each
  const std::vector<std::vector<double>> h = hht::frequency_histogram(spectra, bins);
  ASSERT_EQ(h.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(h[i].size(), static_cast<size_t>(bins));
    const int peak = i == 0 ? 2 : 31;
    for (int b = 0; b < bins; ++b) {
      if (b == peak) {
        EXPECT_NEAR(h[i][b], n, 1e-6);  // amplitude 1 at every sample
      } else {
        EXPECT_EQ(h[i][b], 0.0) << i << " " << b;
      }
    }
  }
  HilbertSpectrum top;
  top.amplitude = {1.0, 2.0};
  top.frequency = {0.5, 0.0};
  EXPECT_EQ(hht::frequency_histogram({top}, 4)[0], std::vector<double>({2.0, 0.0, 0.0, 1.0}));
  EXPECT_THROW(hht::frequency_histogram(spectra, 0), std::invalid_argument);
}

}  // namespace
