#pragma once
// Interpolating cubic splines through knots, evaluated on every integer sample 0..n-1.
//
// Both splines are stored as second derivatives M_k at the knots and evaluated piece by piece
// in local coordinates u = t - x_k (never as a polynomial in the absolute sample index t, which
// loses all precision at indices around 1e6-1e7). Evaluation is one sweep over the samples of
// each interval, so a fit costs O(knots + n) with no search.

#include <vector>

namespace hht {

// Scratch buffers of the tridiagonal solves. Keep one alive across fits (one fit per EMD sift):
// once its capacity has grown, a fit allocates nothing. The members are internal.
struct CubicSplineWorkspace {
  std::vector<double> h, slope, factor, rhs, rhs2, second_derivative;
};

// Periodic spline with period n through knots (x[k], y[k]).
//   x: strictly increasing, 0 <= x.front() and x.back() < n; the piece after the last knot
//      wraps around to x.front() + n. Knot positions may be fractional; samples are integers.
//   One knot gives a constant, two or more a C2 periodic cubic (cyclic tridiagonal solve).
// out is resized to n. Throws std::invalid_argument on malformed knots.
void periodic_cubic_spline(const std::vector<double>& x, const std::vector<double>& y, int n,
                           std::vector<double>& out, CubicSplineWorkspace& ws);
std::vector<double> periodic_cubic_spline(const std::vector<double>& x,
                                          const std::vector<double>& y, int n);

// Not-a-knot spline through knots (x[k], y[k]) for an open signal of n samples.
//   x: strictly increasing, anywhere on the real line (EMD passes extrema mirrored beyond
//      both ends); samples left of x.front() / right of x.back() continue the end pieces.
//   1 knot: constant; 2: straight line; 3: the parabola through them; >= 4: the C2 cubic whose
//   third derivative is also continuous at the second and the second-to-last knot.
// out is resized to n. Throws std::invalid_argument on malformed knots.
void not_a_knot_cubic_spline(const std::vector<double>& x, const std::vector<double>& y, int n,
                             std::vector<double>& out, CubicSplineWorkspace& ws);
std::vector<double> not_a_knot_cubic_spline(const std::vector<double>& x,
                                            const std::vector<double>& y, int n);

}  // namespace hht
