#include "signal/cubic_spline.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using hht::not_a_knot_cubic_spline;
using hht::periodic_cubic_spline;

double cubic(double u) { return 0.5 - 1.25 * u + 0.3 * u * u - 0.02 * u * u * u; }

// Value, first and second derivative at u = 0 of the cubic through (u_j, v_j), j = 0..3.
Eigen::Vector3d derivatives_at_zero(const double u[4], const double v[4]) {
  Eigen::Matrix4d vandermonde;
  Eigen::Vector4d rhs;
  for (int j = 0; j < 4; ++j) {
    vandermonde.row(j) << 1.0, u[j], u[j] * u[j], u[j] * u[j] * u[j];
    rhs(j) = v[j];
  }
  const Eigen::Vector4d c = vandermonde.fullPivLu().solve(rhs);
  return {c(0), c(1), 2.0 * c(2)};
}

// Checks that the piecewise cubic sampled in `out` is C2 at integer knot `k` of a periodic
// signal: the cubic of the piece on the left (samples k-4..k-1) and the one on the right
// (samples k..k+3) agree in value, slope and curvature at k. Pieces must span >= 4 samples.
void expect_c2_at(const std::vector<double>& out, int k) {
  const int n = static_cast<int>(out.size());
  double ul[4], vl[4], ur[4], vr[4];
  for (int j = 0; j < 4; ++j) {
    ul[j] = -4 + j;
    vl[j] = out[((k - 4 + j) % n + n) % n];
    ur[j] = j;
    vr[j] = out[(k + j) % n];
  }
  const Eigen::Vector3d left = derivatives_at_zero(ul, vl);
  const Eigen::Vector3d right = derivatives_at_zero(ur, vr);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(left(d), right(d), 1e-8 * (1.0 + std::abs(right(d)))) << "knot " << k << " derivative " << d;
  }
}

TEST(CubicSpline, NotAKnotReproducesACubicExactly) {
  const std::vector<double> x = {0, 3, 4, 9, 15, 22, 30};
  std::vector<double> y;
  for (double xi : x) y.push_back(cubic(xi));
  const std::vector<double> out = not_a_knot_cubic_spline(x, y, 31);
  ASSERT_EQ(out.size(), 31u);
  for (int t = 0; t < 31; ++t) EXPECT_NEAR(out[t], cubic(t), 1e-11 * (1.0 + std::abs(cubic(t)))) << t;
}

TEST(CubicSpline, NotAKnotExtrapolatesWithTheEndPieces) {
  // Knots strictly inside the sample range and beyond it (as mirrored extrema are).
  const std::vector<double> x = {-7, -2, 5, 6, 11, 19};
  std::vector<double> y;
  for (double xi : x) y.push_back(cubic(xi));
  const std::vector<double> out = not_a_knot_cubic_spline(x, y, 30);
  for (int t = 0; t < 30; ++t) EXPECT_NEAR(out[t], cubic(t), 1e-10 * (1.0 + std::abs(cubic(t)))) << t;
}

TEST(CubicSpline, NotAKnotWithFewKnots) {
  const int n = 12;
  std::vector<double> out = not_a_knot_cubic_spline({4}, {2.5}, n);
  for (double v : out) EXPECT_EQ(v, 2.5);

  out = not_a_knot_cubic_spline({2, 7}, {1.0, 11.0}, n);  // line 1 + 2 (t - 2)
  for (int t = 0; t < n; ++t) EXPECT_NEAR(out[t], 1.0 + 2.0 * (t - 2), 1e-12);

  auto parabola = [](double t) { return 3.0 - 0.5 * t + 0.25 * t * t; };
  out = not_a_knot_cubic_spline({1, 4, 10}, {parabola(1), parabola(4), parabola(10)}, n);
  for (int t = 0; t < n; ++t) EXPECT_NEAR(out[t], parabola(t), 1e-12) << t;

  out = not_a_knot_cubic_spline({1, 2, 6, 11}, {cubic(1), cubic(2), cubic(6), cubic(11)}, n);
  for (int t = 0; t < n; ++t) EXPECT_NEAR(out[t], cubic(t), 1e-12) << t;
}

TEST(CubicSpline, PeriodicInterpolatesItsKnotsAndIsC2EverywhereIncludingTheWrap) {
  const int n = 200;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  // Irregular spacing, each piece at least 4 samples wide so that both sides can be fitted;
  // the wrapping piece runs from 191 to 200 + 6.
  const std::vector<double> x = {6, 11, 23, 30, 47, 60, 88, 120, 125, 150, 171, 191};
  std::vector<double> y;
  for (size_t k = 0; k < x.size(); ++k) y.push_back(value(rng));
  const std::vector<double> out = periodic_cubic_spline(x, y, n);
  ASSERT_EQ(out.size(), static_cast<size_t>(n));
  for (size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(out[static_cast<int>(x[k])], y[k], 1e-12);
  for (double xk : x) expect_c2_at(out, static_cast<int>(xk));
}

TEST(CubicSpline, PeriodicWithOneTwoAndThreeKnots) {
  const int n = 40;
  std::vector<double> out = periodic_cubic_spline({13}, {-1.5}, n);
  for (double v : out) EXPECT_EQ(v, -1.5);

  for (const std::vector<double>& x : {std::vector<double>{5, 22}, std::vector<double>{3, 17, 29}}) {
    std::vector<double> y;
    for (size_t k = 0; k < x.size(); ++k) y.push_back(k % 2 == 0 ? 1.0 + k : -2.0 * k);
    out = periodic_cubic_spline(x, y, n);
    for (size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(out[static_cast<int>(x[k])], y[k], 1e-12);
    for (double xk : x) expect_c2_at(out, static_cast<int>(xk));
  }
}

TEST(CubicSpline, PeriodicApproximatesASmoothPeriodicFunction) {
  const int n = 512;
  const double pi = std::acos(-1.0);
  auto f = [&](double t) { return std::cos(2 * pi * t / n) + 0.5 * std::sin(6 * pi * t / n); };
  std::vector<double> x, y;
  for (int t = 3; t < n; t += 8) {
    x.push_back(t);
    y.push_back(f(t));
  }
  const std::vector<double> out = periodic_cubic_spline(x, y, n);
  double worst = 0.0;
  for (int t = 0; t < n; ++t) worst = std::max(worst, std::abs(out[t] - f(t)));
  // Interpolation error bound of a periodic cubic spline: 5/384 h^4 max|f''''|, h = 8.
  const double f4 = std::pow(2 * pi / n, 4) * (1.0 + 0.5 * 81.0);
  EXPECT_LT(worst, 5.0 / 384.0 * std::pow(8.0, 4) * f4);
  EXPECT_GT(worst, 0.0);
}

TEST(CubicSpline, KeepsFullPrecisionAtLargeSampleIndices) {
  // A cubic centred near index 1e7: a global polynomial in t would need t^3 ~ 1e21.
  const double c = 1.0e7 + 12.0;
  auto f = [&](double t) { return cubic(t - c); };
  std::vector<double> x, y;
  for (double off : {0.0, 3.0, 7.0, 12.0, 20.0, 26.0}) {
    x.push_back(1.0e7 + off);
    y.push_back(f(1.0e7 + off));
  }
  const int n = 10000040;
  hht::CubicSplineWorkspace ws;
  std::vector<double> out;
  not_a_knot_cubic_spline(x, y, n, out, ws);
  for (int t = 10000000; t < n; ++t) EXPECT_NEAR(out[t], f(t), 1e-9 * (1.0 + std::abs(f(t)))) << t;

  // Periodic: the same knots shifted by 1e7 within a period of 1e7 + 1000 give the same samples
  // shifted, as the cyclic system only sees interval widths and values.
  const int period = 10001000;
  std::vector<double> near_zero;
  for (double xi : x) near_zero.push_back(xi - 1.0e7);
  std::vector<double> big, small;
  periodic_cubic_spline(x, y, period, big, ws);
  periodic_cubic_spline(near_zero, y, period, small, ws);
  for (int t = 0; t < 200; ++t) EXPECT_NEAR(big[10000000 + t - 50], small[((t - 50) % period + period) % period], 1e-9) << t;
}

TEST(CubicSpline, ReusedWorkspaceGivesTheSameResult) {
  hht::CubicSplineWorkspace ws;
  std::vector<double> a;
  const std::vector<double> x = {1, 5, 9, 14, 18}, y = {1, -2, 0.5, 3, -1};
  periodic_cubic_spline({0, 2, 4, 6, 8, 10, 12, 14, 16}, {1, 2, 3, 4, 5, 6, 7, 8, 9}, 20, a, ws);
  periodic_cubic_spline(x, y, 20, a, ws);
  EXPECT_EQ(a, periodic_cubic_spline(x, y, 20));
  not_a_knot_cubic_spline(x, y, 20, a, ws);
  EXPECT_EQ(a, not_a_knot_cubic_spline(x, y, 20));
}

TEST(CubicSpline, RejectsMalformedKnots) {
  EXPECT_THROW(periodic_cubic_spline({}, {}, 10), std::invalid_argument);
  EXPECT_THROW(periodic_cubic_spline({1, 2}, {1}, 10), std::invalid_argument);
  EXPECT_THROW(periodic_cubic_spline({1, 1, 3}, {1, 2, 3}, 10), std::invalid_argument);
  EXPECT_THROW(periodic_cubic_spline({1, 10}, {1, 2}, 10), std::invalid_argument);
  EXPECT_THROW(periodic_cubic_spline({-1, 3}, {1, 2}, 10), std::invalid_argument);
  EXPECT_THROW(not_a_knot_cubic_spline({3, 2}, {1, 2}, 10), std::invalid_argument);
  EXPECT_THROW(not_a_knot_cubic_spline({1, 2}, {1, NAN}, 10), std::invalid_argument);
  EXPECT_THROW(not_a_knot_cubic_spline({1, 2}, {1, 2}, 0), std::invalid_argument);
}

}  // namespace
