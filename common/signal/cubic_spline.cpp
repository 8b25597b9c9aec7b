#include "signal/cubic_spline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hht {
namespace {

// The spline on one interval, a + u (b + u (c + u d)) with u = t - x_k: local coordinates keep
// full precision whatever the absolute sample index.
struct Piece {
  double a, b, c, d;
};

// From the end values and second derivatives of an interval of width h.
Piece make_piece(double y0, double y1, double m0, double m1, double h) {
  return {y0, (y1 - y0) / h - h * (2.0 * m0 + m1) / 6.0, 0.5 * m0, (m1 - m0) / (6.0 * h)};
}

// Writes the piece to the samples first..last-1, whose local coordinate is t - origin.
void sweep(const Piece& p, double origin, long first, long last, double* out) {
  for (long t = first; t < last; ++t) {
    const double u = static_cast<double>(t) - origin;
    out[t] = p.a + u * (p.b + u * (p.c + u * p.d));
  }
}

// Index of the first sample at or right of x, clamped to 0..n.
long first_sample_at(double x, int n) {
  return static_cast<long>(std::ceil(std::clamp(x, 0.0, static_cast<double>(n))));
}

void check_knots(const std::vector<double>& x, const std::vector<double>& y, int n) {
  if (x.empty() || x.size() != y.size()) {
    throw std::invalid_argument("cubic spline: need as many values as knots, and at least one");
  }
  if (n < 1) throw std::invalid_argument("cubic spline: need at least one sample");
  for (size_t k = 0; k < x.size(); ++k) {
    if (!std::isfinite(x[k]) || !std::isfinite(y[k])) {
      throw std::invalid_argument("cubic spline: knots must be finite");
    }
    if (k > 0 && !(x[k] > x[k - 1])) {
      throw std::invalid_argument("cubic spline: knot positions must be strictly increasing");
    }
  }
}

// Interval widths h[k] = x[k+1] - x[k] and slopes of the chords; with period > 0 the last
// interval wraps from x.back() to x.front() + period.
void chords(const std::vector<double>& x, const std::vector<double>& y, double period,
            CubicSplineWorkspace& ws) {
  const size_t m = x.size();
  const size_t intervals = period > 0.0 ? m : m - 1;
  ws.h.resize(intervals);
  ws.slope.resize(intervals);
  for (size_t k = 0; k < intervals; ++k) {
    const bool wraps = k + 1 == m;
    ws.h[k] = wraps ? x[0] + period - x[k] : x[k + 1] - x[k];
    ws.slope[k] = ((wraps ? y[0] : y[k + 1]) - y[k]) / ws.h[k];
  }
}

// Second derivatives of the periodic spline. Continuity of the first derivative at knot k gives
//   h[k-1] M[k-1] + 2 (h[k-1] + h[k]) M[k] + h[k] M[k+1] = 6 (slope[k] - slope[k-1]),
// indices modulo m: a cyclic tridiagonal system, solved by Sherman-Morrison around one
// tridiagonal (Thomas) factorisation shared by the two right-hand sides.
void solve_periodic(const std::vector<double>& x, const std::vector<double>& y, int n,
                    CubicSplineWorkspace& ws) {
  const size_t m = x.size();
  std::vector<double>& M = ws.second_derivative;
  M.assign(m, 0.0);
  if (m == 1) return;
  chords(x, y, n, ws);
  const std::vector<double>& h = ws.h;
  if (m == 2) {  // both off-diagonal couplings hit the same unknown; the 2x2 solution in closed form
    M[0] = 6.0 * (y[1] - y[0]) / (h[0] * h[1]);
    M[1] = -M[0];
    return;
  }
  // A = B + u v^T with u = (gamma, 0.., alpha), v = (1, 0.., alpha / gamma): B is tridiagonal.
  const double alpha = h[m - 1];
  const double gamma = -2.0 * (h[m - 1] + h[0]);
  std::vector<double>& cp = ws.factor;  // Thomas: modified super-diagonal
  std::vector<double>& w = ws.rhs;      // B w = r
  std::vector<double>& z = ws.rhs2;     // B z = u
  cp.resize(m);
  w.resize(m);
  z.resize(m);
  for (size_t i = 0; i < m; ++i) {
    const size_t prev = i == 0 ? m - 1 : i - 1;
    double diag = 2.0 * (h[prev] + h[i]);
    if (i == 0) diag -= gamma;
    if (i == m - 1) diag -= alpha * alpha / gamma;
    const double r = 6.0 * (ws.slope[i] - ws.slope[prev]);
    const double u = i == 0 ? gamma : (i == m - 1 ? alpha : 0.0);
    if (i == 0) {
      cp[0] = h[0] / diag;
      w[0] = r / diag;
      z[0] = u / diag;
    } else {
      const double inv = 1.0 / (diag - h[prev] * cp[prev]);
      cp[i] = h[i] * inv;
      w[i] = (r - h[prev] * w[prev]) * inv;
      z[i] = (u - h[prev] * z[prev]) * inv;
    }
  }
  for (size_t i = m - 1; i-- > 0;) {
    w[i] -= cp[i] * w[i + 1];
    z[i] -= cp[i] * z[i + 1];
  }
  const double ratio = alpha / gamma;
  const double scale = (w[0] + ratio * w[m - 1]) / (1.0 + z[0] + ratio * z[m - 1]);
  for (size_t i = 0; i < m; ++i) M[i] = w[i] - scale * z[i];
}

// Second derivatives of the not-a-knot spline (m >= 4). Equal third derivatives on both sides of
// knots 1 and m-2 give M[0] and M[m-1] in terms of their neighbours; substituting them into the
// first and last continuity rows leaves a diagonally dominant tridiagonal system in M[1..m-2].
void solve_not_a_knot(const std::vector<double>& x, const std::vector<double>& y,
                      CubicSplineWorkspace& ws) {
  const size_t m = x.size();
  std::vector<double>& M = ws.second_derivative;
  M.assign(m, 0.0);
  if (m <= 2) return;  // constant or straight line
  chords(x, y, 0.0, ws);
  const std::vector<double>& h = ws.h;
  const std::vector<double>& slope = ws.slope;
  if (m == 3) {  // the parabola through the three knots: constant second derivative
    const double curvature = 2.0 * (slope[1] - slope[0]) / (h[0] + h[1]);
    std::fill(M.begin(), M.end(), curvature);
    return;
  }
  std::vector<double>& cp = ws.factor;
  std::vector<double>& w = ws.rhs;
  cp.resize(m);
  w.resize(m);
  const size_t last = m - 2;
  for (size_t i = 1; i <= last; ++i) {
    double sub = h[i - 1], diag = 2.0 * (h[i - 1] + h[i]), sup = h[i];
    double r = 6.0 * (slope[i] - slope[i - 1]);
    if (i == 1) {
      diag = h[0] + 2.0 * h[1];
      sup = h[1] - h[0];
      r *= h[1] / (h[0] + h[1]);
    }
    if (i == last) {
      const double a = h[last - 1], b = h[last];
      sub = a - b;
      diag = 2.0 * a + b;
      r *= a / (a + b);
    }
    if (i == 1) {
      cp[i] = sup / diag;
      w[i] = r / diag;
    } else {
      const double inv = 1.0 / (diag - sub * cp[i - 1]);
      cp[i] = sup * inv;
      w[i] = (r - sub * w[i - 1]) * inv;
    }
  }
  M[last] = w[last];
  for (size_t i = last - 1; i >= 1; --i) M[i] = w[i] - cp[i] * M[i + 1];
  M[0] = M[1] + h[0] * (M[1] - M[2]) / h[1];
  M[m - 1] = M[last] + h[last] * (M[last] - M[last - 1]) / h[last - 1];
}

}  // namespace

void periodic_cubic_spline(const std::vector<double>& x, const std::vector<double>& y, int n,
                           std::vector<double>& out, CubicSplineWorkspace& ws) {
  check_knots(x, y, n);
  if (x.front() < 0.0 || !(x.back() < n)) {
    throw std::invalid_argument("periodic cubic spline: knots must lie in [0, n)");
  }
  solve_periodic(x, y, n, ws);
  const std::vector<double>& M = ws.second_derivative;
  const size_t m = x.size();
  out.resize(n);
  double* o = out.data();
  long first = first_sample_at(x[0], n);
  for (size_t k = 0; k + 1 < m; ++k) {
    const long next = first_sample_at(x[k + 1], n);
    sweep(make_piece(y[k], y[k + 1], M[k], M[k + 1], x[k + 1] - x[k]), x[k], first, next, o);
    first = next;
  }
  // The wrapping piece covers the tail after the last knot and the head before the first one.
  const Piece wrap = make_piece(y[m - 1], y[0], M[m - 1], M[0], x[0] + n - x[m - 1]);
  sweep(wrap, x[m - 1], first, n, o);
  sweep(wrap, x[m - 1] - n, 0, first_sample_at(x[0], n), o);
}

void not_a_knot_cubic_spline(const std::vector<double>& x, const std::vector<double>& y, int n,
                             std::vector<double>& out, CubicSplineWorkspace& ws) {
  check_knots(x, y, n);
  out.resize(n);
  const size_t m = x.size();
  if (m == 1) {
    std::fill(out.begin(), out.end(), y[0]);
    return;
  }
  solve_not_a_knot(x, y, ws);
  const std::vector<double>& M = ws.second_derivative;
  double* o = out.data();
  // The first and last pieces also extrapolate beyond the outer knots.
  for (size_t k = 0; k + 1 < m; ++k) {
    const long first = k == 0 ? 0 : first_sample_at(x[k], n);
    const long last = k + 2 == m ? n : first_sample_at(x[k + 1], n);
    sweep(make_piece(y[k], y[k + 1], M[k], M[k + 1], x[k + 1] - x[k]), x[k], first, last, o);
  }
}

std::vector<double> periodic_cubic_spline(const std::vector<double>& x,
                                          const std::vector<double>& y, int n) {
  CubicSplineWorkspace ws;
  std::vector<double> out;
  periodic_cubic_spline(x, y, n, out, ws);
  return out;
}

std::vector<double> not_a_knot_cubic_spline(const std::vector<double>& x,
                                            const std::vector<double>& y, int n) {
  CubicSplineWorkspace ws;
  std::vector<double> out;
  not_a_knot_cubic_spline(x, y, n, out, ws);
  return out;
}

}  // namespace hht
