#include "signal/emd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using hht::EmdOptions;
using hht::EmdResult;
using hht::SignalBoundary;

const double kPi = std::acos(-1.0);

std::vector<double> tone(int n, double period, double amplitude = 1.0, double phase = 0.0) {
  std::vector<double> s(n);
  for (int t = 0; t < n; ++t) s[t] = amplitude * std::cos(2.0 * kPi * t / period + phase);
  return s;
}

std::vector<double> add(std::vector<double> a, const std::vector<double>& b) {
  for (size_t t = 0; t < a.size(); ++t) a[t] += b[t];
  return a;
}

double norm(const std::vector<double>& a) {
  double s = 0.0;
  for (double v : a) s += v * v;
  return std::sqrt(s);
}

double relative_error(const std::vector<double>& got, const std::vector<double>& want) {
  double d = 0.0;
  for (size_t t = 0; t < got.size(); ++t) d += (got[t] - want[t]) * (got[t] - want[t]);
  return std::sqrt(d) / norm(want);
}

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double v : a) m = std::max(m, std::abs(v));
  return m;
}

// Random walk plus two tones: many scales, reproducible.
std::vector<double> rich_signal(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> step(0.0, 1.0);
  std::vector<double> s(n);
  double walk = 0.0;
  for (int t = 0; t < n; ++t) {
    walk += step(rng);
    s[t] = 0.05 * walk + std::sin(2.0 * kPi * t / 37.0) + 0.5 * std::sin(2.0 * kPi * t / 300.0);
  }
  return s;
}

// max |sum of IMFs + residue - signal|
double reconstruction_error(const EmdResult& r, const std::vector<double>& signal) {
  double worst = 0.0;
  for (size_t t = 0; t < signal.size(); ++t) {
    double sum = r.residue[t];
    for (const auto& imf : r.imfs) sum += imf[t];
    worst = std::max(worst, std::abs(sum - signal[t]));
  }
  return worst;
}

TEST(FindExtrema, FlatRunsCountOnceAtTheirMiddle) {
  // Max over the run 1..3, min over the run 5..6 (even length: the left middle).
  const std::vector<double> s = {0, 1, 1, 1, 0, -1, -1, 0};
  hht::Extrema e;
  hht::find_extrema(s, SignalBoundary::Periodic, nullptr, e);
  EXPECT_EQ(e.maxima, std::vector<int>({2}));
  EXPECT_EQ(e.minima, std::vector<int>({5}));
}

TEST(FindExtrema, PeriodicComparesTheLastSampleWithTheFirst) {
  // The run of 5s is 5, 6, 7, 0 across the wrap: one maximum, at 6.
  const std::vector<double> s = {5, 0, 1, 2, 3, 5, 5, 5};
  hht::Extrema e;
  hht::find_extrema(s, SignalBoundary::Periodic, nullptr, e);
  EXPECT_EQ(e.maxima, std::vector<int>({6}));
  EXPECT_EQ(e.minima, std::vector<int>({1}));
  // Rotated so that the run's middle falls on the other side of sample 0.
  const std::vector<double> r = {5, 5, 5, 0, 1, 2, 3, 5};  // run 7, 0, 1, 2: middle 0
  hht::find_extrema(r, SignalBoundary::Periodic, nullptr, e);
  EXPECT_EQ(e.maxima, std::vector<int>({0}));
  EXPECT_EQ(e.minima, std::vector<int>({3}));
  const std::vector<double> q = {5, 5, 0, 1, 2, 3, 5, 5};  // run 6, 7, 0, 1: middle 7
  hht::find_extrema(q, SignalBoundary::Periodic, nullptr, e);
  EXPECT_EQ(e.maxima, std::vector<int>({7}));
  EXPECT_EQ(e.minima, std::vector<int>({2}));
  const hht::ExtremaCount ramp = hht::count_extrema({0, 1, 2, 3}, SignalBoundary::Periodic);
  EXPECT_EQ(ramp.maxima, 1);
  EXPECT_EQ(ramp.minima, 1);
}

TEST(FindExtrema, OpenSignalEndsAreNeverExtrema) {
  const std::vector<double> s = {5, 0, 1, 2, 3, 5, 5, 5};
  hht::Extrema e;
  hht::find_extrema(s, SignalBoundary::Open, nullptr, e);
  EXPECT_TRUE(e.maxima.empty());
  EXPECT_EQ(e.minima, std::vector<int>({1}));
  const hht::ExtremaCount ramp = hht::count_extrema({0, 1, 2, 3}, SignalBoundary::Open);
  EXPECT_EQ(ramp.maxima, 0);
  EXPECT_EQ(ramp.minima, 0);
}

TEST(FindExtrema, FlaggedSamplesAreSkipped) {
  const std::vector<double> s = tone(64, 8.0);  // maxima at 0, 8, ..; minima at 4, 12, ..
  std::vector<unsigned char> never(64, 0);
  never[8] = never[12] = never[60] = 1;
  hht::Extrema e;
  hht::find_extrema(s, SignalBoundary::Periodic, &never, e);
  EXPECT_EQ(e.maxima, std::vector<int>({0, 16, 24, 32, 40, 48, 56}));
  EXPECT_EQ(e.minima, std::vector<int>({4, 20, 28, 36, 44, 52}));
  const hht::ExtremaCount c = hht::count_extrema(s, SignalBoundary::Periodic, &never);
  EXPECT_EQ(c.maxima, 7);
  EXPECT_EQ(c.minima, 6);
  std::vector<unsigned char> wrong_size(10, 0);
  EXPECT_THROW(hht::find_extrema(s, SignalBoundary::Periodic, &wrong_size, e), std::invalid_argument);
}

TEST(Emd, SeparatesThreeTonesOfWellSeparatedPeriods) {
  const int n = 8192;
  const std::vector<double> fast = tone(n, 8.0), middle = tone(n, 64.0, 1.0, 0.7),
                            slow = tone(n, 512.0, 1.0, 2.1);
  const std::vector<double> signal = add(add(fast, middle), slow);
  const EmdResult r = hht::emd(signal);
  ASSERT_EQ(r.status, hht::EmdStatus::Ok);
  ASSERT_GE(r.imfs.size(), 3u);
  // Finest first; each tone in its own IMF, to 0.2% in the L2 sense (measured: 4e-5, 3e-4, 5e-4).
  EXPECT_LT(relative_error(r.imfs[0], fast), 2e-3);
  EXPECT_LT(relative_error(r.imfs[1], middle), 2e-3);
  EXPECT_LT(relative_error(r.imfs[2], slow), 2e-3);
  EXPECT_LT(reconstruction_error(r, signal), 1e-12 * max_abs(signal));
}

// The IMFs are known: a fast and a slow tone on a cycle plus an offset. Only sifting that
// really subtracts the envelope mean finds them (the residue is defined as the signal minus
// the IMFs, so the sum alone proves nothing).
TEST(Emd, TwoTonesAndAnOffsetOnACycle) {
  const int n = 4096;
  const std::vector<double> fast = tone(n, 16.0, 1.0, 0.4), slow = tone(n, 256.0, 2.0, 1.3);
  const std::vector<double> signal = add(add(fast, slow), std::vector<double>(n, 0.7));
  const EmdResult r = hht::emd(signal);
  ASSERT_EQ(r.imfs.size(), 2u);
  EXPECT_LT(relative_error(r.imfs[0], fast), 5e-5);  // measured 5.0e-6
  EXPECT_LT(relative_error(r.imfs[1], slow), 5e-5);  // measured 2.5e-6
  for (double v : r.residue) ASSERT_NEAR(v, 0.7, 1e-9);  // measured 9e-16
  for (int s : r.sifts) EXPECT_GT(s, 0);
}

// Every IMF of a many-scale signal oscillates about zero: its extrema and its zero crossings
// agree to 3% (measured: 2.4% at worst, IMF 3 of 5; the signal itself, a random walk plus two
// tones, has 15 times more extrema than crossings), while the residue is the trend.
TEST(Emd, EveryImfCrossesZeroBetweenItsExtrema) {
  for (SignalBoundary b : {SignalBoundary::Periodic, SignalBoundary::Open}) {
    SCOPED_TRACE(b == SignalBoundary::Periodic ? "periodic" : "open");
    const std::vector<double> signal = rich_signal(20000, 3);
    EmdOptions o;
    o.boundary = b;
    const EmdResult r = hht::emd(signal, o);
    ASSERT_GE(r.imfs.size(), 4u);
    for (size_t i = 0; i < r.imfs.size(); ++i) {
      const std::vector<double>& imf = r.imfs[i];
      const hht::ExtremaCount c = hht::count_extrema(imf, b);
      int crossings = 0;
      for (size_t t = 0; t + 1 < imf.size(); ++t) crossings += (imf[t] < 0) != (imf[t + 1] < 0);
      EXPECT_LE(std::abs(c.maxima + c.minima - crossings), 0.03 * (c.maxima + c.minima)) << "IMF " << i;
    }
    const hht::ExtremaCount rc = hht::count_extrema(r.residue, b);
    EXPECT_LT(std::min(rc.maxima, rc.minima), o.min_extrema);
  }
}

TEST(Emd, StopsWhenTheResidueHasTooFewExtrema) {
  const std::vector<double> signal = rich_signal(20000, 11);
  for (int min_extrema : {15, 4, 40}) {
    EmdOptions o;
    o.min_extrema = min_extrema;
    const EmdResult r = hht::emd(signal, o);
    ASSERT_FALSE(r.imfs.empty());
    const hht::ExtremaCount c = hht::count_extrema(r.residue, SignalBoundary::Periodic);
    EXPECT_TRUE(c.maxima < min_extrema || c.minima < min_extrema)
        << min_extrema << ": " << c.maxima << " maxima, " << c.minima << " minima";
    // ... and the residue before the last IMF had enough.
    std::vector<double> before = r.residue;
    for (size_t t = 0; t < before.size(); ++t) before[t] += r.imfs.back()[t];
    const hht::ExtremaCount p = hht::count_extrema(before, SignalBoundary::Periodic);
    EXPECT_GE(std::min(p.maxima, p.minima), min_extrema);
  }
}

TEST(Emd, RespectsMaxImfsAndMaxSifts) {
  const std::vector<double> signal = rich_signal(5000, 5);
  EmdOptions o;
  o.max_imfs = 2;
  EXPECT_EQ(hht::emd(signal, o).imfs.size(), 2u);
  o.max_imfs = 0;
  o.sd_threshold = 0.0;  // never met: every IMF takes exactly max_sifts sifts
  for (int cap : {1, 3, 7}) {
    o.max_sifts = cap;
    const EmdResult r = hht::emd(signal, o);
    ASSERT_FALSE(r.imfs.empty());
    for (int s : r.sifts) EXPECT_EQ(s, cap);
    EXPECT_LT(reconstruction_error(r, signal), 1e-12 * max_abs(signal));
  }
}

// SD between the first IMF candidates after k - 1 and k sifts.
double sd_of_sift(const std::vector<double>& signal, int k) {
  EmdOptions o;
  o.max_imfs = 1;
  o.sd_threshold = 0.0;
  o.max_sifts = k - 1;
  const std::vector<double> previous = k == 1 ? signal : hht::emd(signal, o).imfs[0];
  o.max_sifts = k;
  const std::vector<double> current = hht::emd(signal, o).imfs[0];
  double change = 0.0, before = 0.0;
  for (size_t t = 0; t < signal.size(); ++t) {
    change += (previous[t] - current[t]) * (previous[t] - current[t]);
    before += previous[t] * previous[t];
  }
  return change / before;
}

TEST(Emd, SiftingStopsAtTheFirstSiftWhoseSdIsBelowTheThreshold) {
  const std::vector<double> signal = rich_signal(4000, 9);
  int previous_sifts = 0;
  for (double threshold : {0.3, 0.05, 0.002}) {
    EmdOptions o;
    o.sd_threshold = threshold;
    o.max_imfs = 1;
    const int k = hht::emd(signal, o).sifts[0];
    ASSERT_LT(k, o.max_sifts);
    EXPECT_LT(sd_of_sift(signal, k), threshold);
    if (k > 1) {
      EXPECT_GE(sd_of_sift(signal, k - 1), threshold);
    }
    EXPECT_GE(k, previous_sifts);  // a smaller threshold never sifts less
    previous_sifts = k;
  }
  EXPECT_GT(previous_sifts, 1);
}

TEST(Emd, RotatingACyclicSignalRotatesItsImfs) {
  const int n = 4096, shift = 1234;
  const std::vector<double> signal = rich_signal(n, 21);
  std::vector<double> rotated(n);
  for (int t = 0; t < n; ++t) rotated[(t + shift) % n] = signal[t];
  const EmdResult a = hht::emd(signal), b = hht::emd(rotated);
  ASSERT_EQ(a.imfs.size(), b.imfs.size());
  EXPECT_EQ(a.sifts, b.sifts);
  const double scale = max_abs(signal);
  for (size_t i = 0; i < a.imfs.size(); ++i) {
    for (int t = 0; t < n; ++t) {
      ASSERT_NEAR(b.imfs[i][(t + shift) % n], a.imfs[i][t], 1e-9 * scale) << "IMF " << i << " t " << t;
    }
  }
  for (int t = 0; t < n; ++t) ASSERT_NEAR(b.residue[(t + shift) % n], a.residue[t], 1e-9 * scale);
}

TEST(Emd, TwoThreadsGiveTheSameResultAsOne) {
  const std::vector<double> signal = rich_signal(100000, 17);  // long enough for two threads
  for (SignalBoundary b : {SignalBoundary::Periodic, SignalBoundary::Open}) {
    EmdOptions o;
    o.boundary = b;
    o.threads = 1;
    const EmdResult serial = hht::emd(signal, o);
    o.threads = 2;
    const EmdResult parallel = hht::emd(signal, o);
    ASSERT_GE(serial.imfs.size(), 5u);
    EXPECT_EQ(parallel.imfs, serial.imfs);
    EXPECT_EQ(parallel.residue, serial.residue);
    EXPECT_EQ(parallel.sifts, serial.sifts);
    EXPECT_LT(reconstruction_error(parallel, signal), 1e-12 * max_abs(signal));
  }
}

TEST(Emd, OpenBoundarySeparatesASineFromATrend) {
  const int n = 3000;
  std::vector<double> trend(n), sine(n), signal(n);
  for (int t = 0; t < n; ++t) {
    trend[t] = 2.0 * t / n + 0.5 * std::pow(t / double(n), 2);
    sine[t] = std::sin(2.0 * kPi * t / 50.0 + 0.3);
    signal[t] = trend[t] + sine[t];
  }
  EmdOptions o;
  o.boundary = SignalBoundary::Open;
  const EmdResult r = hht::emd(signal, o);
  ASSERT_GE(r.imfs.size(), 1u);
  // Measured: 1.9e-3 and 1.0e-3; the mirrored ends cost a little accuracy near both ends.
  EXPECT_LT(relative_error(r.imfs[0], sine), 0.01);
  std::vector<double> rest = r.residue;
  for (size_t i = 1; i < r.imfs.size(); ++i) rest = add(rest, r.imfs[i]);
  EXPECT_LT(relative_error(rest, trend), 0.01);
  EXPECT_LT(reconstruction_error(r, signal), 1e-12 * max_abs(signal));
}

TEST(Emd, OpenBoundaryFollowsAChirp) {
  // Frequency rising from 1/100 to 1/12 cycles per sample, plus a slow tone.
  const int n = 4000;
  std::vector<double> chirp(n), slow = tone(n, 1500.0, 2.0), signal(n);
  for (int t = 0; t < n; ++t) {
    const double f0 = 0.01, f1 = 1.0 / 12.0;
    chirp[t] = std::cos(2.0 * kPi * (f0 * t + 0.5 * (f1 - f0) / n * t * t));
    signal[t] = chirp[t] + slow[t];
  }
  EmdOptions o;
  o.boundary = SignalBoundary::Open;
  const EmdResult r = hht::emd(signal, o);
  ASSERT_GE(r.imfs.size(), 1u);
  EXPECT_LT(relative_error(r.imfs[0], chirp), 0.02);  // measured 4.8e-3
  EXPECT_LT(reconstruction_error(r, signal), 1e-12 * max_abs(signal));
}

TEST(Emd, OpenBoundaryWithALongRampBeforeTheFirstExtremum) {
  // The first maximum lies at 100, its neighbours 5 to 20 samples further: mirrored about it
  // they would stay inside the ramp and the end pieces would extrapolate over ~80 samples
  // (IMFs up to 26 here, measured); mirroring about the end sample keeps them within the
  // signal's range (0.94 measured, the signal reaching 2.3).
  const int n = 1000;
  std::vector<double> signal(n);
  for (int t = 0; t < n; ++t) {
    const double u = t - 100.0;
    signal[t] = t <= 100 ? t / 100.0
                         : (1.0 + 0.8 * std::sin(2.0 * kPi * u / 150.0)) * std::cos(2.0 * kPi * u / 10.0) +
                               0.5 * std::sin(2.0 * kPi * u / 200.0);
  }
  EmdOptions o;
  o.boundary = SignalBoundary::Open;
  o.min_extrema = 5;
  const EmdResult r = hht::emd(signal, o);
  ASSERT_GE(r.imfs.size(), 1u);
  for (const auto& imf : r.imfs) {
    for (int t = 0; t <= 100; ++t) ASSERT_LT(std::abs(imf[t]), max_abs(signal)) << t;
  }
  EXPECT_LT(reconstruction_error(r, signal), 1e-12 * max_abs(signal));
}

TEST(Emd, FlaggedSamplesNeverShapeTheEnvelopes) {
  // A tone with a spike on one of its peaks. When the peak is flagged, the spike's height
  // cannot reach the envelopes: changing it changes the IMF at that sample only.
  const int n = 2048, peak = 64 * 10;
  std::vector<double> low = tone(n, 64.0), high = low;
  low[peak] += 0.5;
  high[peak] += 5.0;
  std::vector<unsigned char> never(n, 0);
  never[peak] = 1;
  EmdOptions o;
  o.max_imfs = 1;
  o.max_sifts = 5;
  o.sd_threshold = 0.0;
  o.min_extrema = 1;
  o.never_extremum = &never;
  const EmdResult a = hht::emd(low, o), b = hht::emd(high, o);
  ASSERT_EQ(a.imfs.size(), 1u);
  ASSERT_EQ(b.imfs.size(), 1u);
  for (int t = 0; t < n; ++t) {
    if (t == peak) {
      EXPECT_NEAR(b.imfs[0][t] - a.imfs[0][t], 4.5, 1e-12);
    } else {
      ASSERT_NEAR(b.imfs[0][t], a.imfs[0][t], 1e-12) << t;
    }
  }
  // Without the flag the spike is a maximum and its height bends the upper envelope.
  o.never_extremum = nullptr;
  const EmdResult c = hht::emd(low, o), d = hht::emd(high, o);
  int changed = 0;
  for (int t = 0; t < n; ++t) changed += std::abs(d.imfs[0][t] - c.imfs[0][t]) > 1e-3;
  EXPECT_GT(changed, 50);

  std::vector<unsigned char> all(n, 1);
  o.never_extremum = &all;
  const EmdResult none = hht::emd(high, o);
  EXPECT_TRUE(none.imfs.empty());
  EXPECT_EQ(none.residue, high);
  std::vector<unsigned char> wrong_size(n - 1, 0);
  o.never_extremum = &wrong_size;
  EXPECT_THROW(hht::emd(high, o), std::invalid_argument);
}

TEST(Emd, EmptyConstantAndShortSignals) {
  for (SignalBoundary b : {SignalBoundary::Periodic, SignalBoundary::Open}) {
    EmdOptions o;
    o.boundary = b;
    const EmdResult empty = hht::emd({}, o);
    EXPECT_EQ(empty.status, hht::EmdStatus::Ok);
    EXPECT_TRUE(empty.imfs.empty());
    EXPECT_TRUE(empty.residue.empty());

    const std::vector<double> constant(1000, 3.25);
    const EmdResult c = hht::emd(constant, o);
    EXPECT_TRUE(c.imfs.empty());
    EXPECT_EQ(c.residue, constant);

    o.min_extrema = 1;
    for (int n = 1; n < 4; ++n) {
      std::vector<double> s(n);
      for (int t = 0; t < n; ++t) s[t] = std::sin(1.0 + 2.0 * t);
      const EmdResult r = hht::emd(s, o);
      EXPECT_EQ(r.status, hht::EmdStatus::Ok);
      ASSERT_EQ(r.residue.size(), s.size());
      EXPECT_LT(reconstruction_error(r, s), 1e-15);
    }
  }
}

TEST(Emd, ThreeSampleCycleSplitsIntoOscillationAndMean) {
  EmdOptions o;
  o.min_extrema = 1;
  const EmdResult r = hht::emd({0.0, 1.0, 0.0}, o);
  // Maximum at 1, minimum over the run 2, 0 across the wrap: constant envelopes 1 and 0.
  ASSERT_EQ(r.imfs.size(), 1u);
  EXPECT_EQ(r.imfs[0], std::vector<double>({-0.5, 0.5, -0.5}));
  EXPECT_EQ(r.residue, std::vector<double>({0.5, 0.5, 0.5}));
}

TEST(Emd, TooFewExtremaFromTheStartGivesNoImf) {
  const std::vector<double> s = tone(1000, 100.0);  // 10 maxima, 10 minima < 15
  const EmdResult r = hht::emd(s);
  EXPECT_EQ(r.status, hht::EmdStatus::Ok);
  EXPECT_TRUE(r.imfs.empty());
  EXPECT_TRUE(r.sifts.empty());
  EXPECT_EQ(r.residue, s);
}

TEST(Emd, RejectsNonFiniteSamples) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    std::vector<double> s = rich_signal(500, 1);
    s[321] = bad;
    const EmdResult r = hht::emd(s);
    EXPECT_EQ(r.status, hht::EmdStatus::NonFiniteInput);
    EXPECT_TRUE(r.imfs.empty());
    EXPECT_TRUE(r.residue.empty());
  }
}

}  // namespace
