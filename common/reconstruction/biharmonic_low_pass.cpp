#include "reconstruction/biharmonic_low_pass.h"

#include "mesh/uniform_laplacian.h"
#include "util/parallel_for.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <utility>

namespace hht {

namespace {

// Preconditioned, the solves take 6-46 iterations (mu 2 to 0.001); a cap ten times that keeps a
// pathological mesh from running for an hour (each iteration is up to 68 sweeps).
constexpr int kMaxIterations = 500;

// Vertices renumbered in breadth-first order, so that the neighbours a sweep reads sit near each
// other in memory: `order` lists old indices by new index.
VertexAdjacency breadth_first_renumbered(const VertexAdjacency& adjacency, std::vector<int>& order) {
  const int n = adjacency.vertices();
  std::vector<int> new_index(n, -1);
  order.clear();
  order.reserve(n);
  for (int seed = 0; seed < n; ++seed) {
    if (new_index[seed] >= 0) continue;
    new_index[seed] = static_cast<int>(order.size());
    order.push_back(seed);
    for (size_t head = order.size() - 1; head < order.size(); ++head)
      for (const int* j = adjacency.begin(order[head]); j != adjacency.end(order[head]); ++j)
        if (new_index[*j] < 0) {
          new_index[*j] = static_cast<int>(order.size());
          order.push_back(*j);
        }
  }
  VertexAdjacency out;
  out.offsets.assign(n + 1, 0);
  out.neighbours.resize(adjacency.neighbours.size());
  out.boundary.resize(n);
  for (int i = 0; i < n; ++i) {
    const int old = order[i];
    out.offsets[i + 1] = out.offsets[i] + adjacency.valence(old);
    out.boundary[i] = adjacency.boundary[old];
    int* dst = out.neighbours.data() + out.offsets[i];
    for (const int* j = adjacency.begin(old); j != adjacency.end(old); ++j) *dst++ = new_index[*j];
    std::sort(out.neighbours.data() + out.offsets[i], dst);
  }
  return out;
}

// The preconditioner's polynomial: Chebyshev coefficients (in s - 1) of the q of least degree
// with |1 - q(s) p(s)| <= kPolynomialFit on [0, 2], p(s) = s^4 + g mu^2 s^2 + mu^4, fitted by least
// squares at Chebyshev nodes (which crowd near s = 0, where p is small). kMaxDegree reaches mu
// 0.008 with g = 1, the strongest cut-off the filters choose (noise given at 10 mean edges,
// strength 10; with g = 0 the fit there is 0.40); beyond it the largest degree's fit is used (mu
// 0.001: the solve still converges, in 44 iterations on the unit test's mesh).
constexpr int kMaxDegree = 64;
constexpr double kPolynomialFit = 0.35;

double chebyshev_series(const Eigen::VectorXd& c, double x) {
  double b1 = 0, b2 = 0;
  for (Eigen::Index k = c.size() - 1; k >= 1; --k) {
    const double b = c[k] + 2 * x * b1 - b2;
    b2 = b1;
    b1 = b;
  }
  return c[0] + x * b1 - b2;
}

Eigen::VectorXd inverse_polynomial(double mu, double first_order) {
  const auto p = [&](double s) { return s * s * s * s + first_order * mu * mu * s * s + std::pow(mu, 4); };
  constexpr int kNodes = 2000, kChecks = 8000;
  Eigen::VectorXd c;
  for (int degree = 2; degree <= kMaxDegree; degree += degree < 16 ? 1 : 4) {
    Eigen::MatrixXd basis(kNodes, degree + 1);
    for (int i = 0; i < kNodes; ++i) {
      const double x = std::cos(M_PI * (i + 0.5) / kNodes), px = p(1 + x);
      double previous = 1, current = x;
      basis(i, 0) = px;
      basis(i, 1) = x * px;
      for (int k = 2; k <= degree; ++k) {
        const double next = 2 * x * current - previous;
        previous = current;
        current = next;
        basis(i, k) = next * px;
      }
    }
    c = basis.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(kNodes));
    double worst = 0;
    for (int i = 0; i <= kChecks; ++i) {
      const double s = 2.0 * i / kChecks;
      worst = std::max(worst, std::abs(1 - chebyshev_series(c, s - 1) * p(s)));
    }
    if (worst <= kPolynomialFit) break;
  }
  return c;
}

}  // namespace

bool biharmonic_low_pass(const VertexAdjacency& input_adjacency, const Positions& input, double mu, double first_order,
                         double max_error, Positions& result, BiharmonicLowPassReport& report,
                         const std::function<void(double)>& progress) {
  report = BiharmonicLowPassReport{};
  std::vector<int> order;
  const VertexAdjacency adjacency = breadth_first_renumbered(input_adjacency, order);
  Positions v(input.rows(), 3);
  for (size_t i = 0; i < order.size(); ++i) v.row(i) = input.row(order[i]);
  Positions x;
  const int n = adjacency.vertices();
  const double mu4 = std::pow(mu, 4);
  Eigen::VectorXd inverse_valence(n);
  for (int i = 0; i < n; ++i) inverse_valence[i] = adjacency.valence(i) > 0 ? 1.0 / adjacency.valence(i) : 0.0;
  const Eigen::VectorXd inverse_valence_squared = inverse_valence.cwiseAbs2();

  const double first_order_weight = first_order * mu * mu;
  Positions a, b, c;  // work vectors of the product, reused
  // out = K D^-1 K D^-2 K D^-1 K y + first_order mu^2 K D^-2 K y + mu^4 y
  //     = K (D^-1 K D^-2 K D^-1 a + first_order mu^2 D^-2 a) + mu^4 y,  a = K y
  //     = ((L^2)^T L^2 + first_order mu^2 L^T L + mu^4 I) y: four sweeps either way
  auto apply = [&](const Positions& y, Positions& out) {
    apply_graph_laplacian(adjacency, y, a);
    b = inverse_valence.asDiagonal() * a;
    apply_graph_laplacian(adjacency, b, c);
    c = inverse_valence_squared.asDiagonal() * c;
    apply_graph_laplacian(adjacency, c, b);
    b = inverse_valence.asDiagonal() * b;
    if (first_order_weight > 0) b += first_order_weight * (inverse_valence_squared.asDiagonal() * a);
    apply_graph_laplacian(adjacency, b, out);
    out += mu4 * y;
  };

  // M^-1 r = D^-1/2 d q(S) D^-1/2 r by Clenshaw's recurrence on S - I = -D^-1/2 A D^-1/2 (A the
  // adjacency), one sweep per degree, in the product's work vectors; a vertex of no face is
  // solved exactly (its row of the system is mu^4).
  const Eigen::VectorXd q_coefficients = inverse_polynomial(mu, first_order);
  Eigen::VectorXd inverse_root_valence(n);
  double inverse_valence_sum = 0;
  int connected = 0;
  for (int i = 0; i < n; ++i) {
    inverse_root_valence[i] = std::sqrt(inverse_valence[i]);
    inverse_valence_sum += inverse_valence[i];
    connected += adjacency.valence(i) > 0;
  }
  const double mean_valence = connected > 0 ? connected / inverse_valence_sum : 1.0;  // harmonic mean
  auto precondition = [&](const Positions& r, Positions& z) {
    Positions& scaled = a;
    Positions* b1 = &b;
    Positions* b2 = &c;
    scaled = inverse_root_valence.asDiagonal() * r;
    const Eigen::Index degree = q_coefficients.size() - 1;  // at least 2
    *b1 = q_coefficients[degree] * scaled;
    b2->setZero(n, 3);
    z.resize(n, 3);
    for (Eigen::Index k = degree - 1; k >= 0; --k) {
      const double ck = q_coefficients[k];
      // k >= 1: b_k = c_k y + 2 (S - I) b_k+1 - b_k+2, written over b_k+2; k = 0: q(S) y =
      // c_0 y + (S - I) b_1 - b_2, scaled back by d D^-1/2 into z.
      parallel_for(0, n, [&](int first, int last) {
        for (int i = first; i < last; ++i) {
          Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
          for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) sum += inverse_root_valence[*j] * b1->row(*j);
          if (k > 0) {
            b2->row(i) = ck * scaled.row(i) - 2 * inverse_root_valence[i] * sum - b2->row(i);
          } else {
            const Eigen::RowVector3d qy = ck * scaled.row(i) - inverse_root_valence[i] * sum - b2->row(i);
            z.row(i) = adjacency.valence(i) > 0 ? Eigen::RowVector3d(mean_valence * inverse_root_valence[i] * qy)
                                                : Eigen::RowVector3d(r.row(i) / mu4);
          }
        }
      });
      std::swap(b1, b2);
    }
  };

  // q holds each product A p until r is updated, then the preconditioned residual M^-1 r.
  x = v;
  Positions r(n, 3), p, q(n, 3);
  apply(x, q);
  r = mu4 * v - q;
  v.resize(0, 3);  // the right-hand side is in r now: one vector less at the solve's peak
  precondition(r, q);
  p = q;
  Eigen::RowVector3d rz = (r.array() * q.array()).colwise().sum();
  auto bound = [&] { return r.norm() / mu4; };
  report.error_bound = bound();
  const double start = std::max(report.error_bound, max_error);
  for (; report.error_bound > max_error; ++report.iterations) {
    if (report.iterations == kMaxIterations) return false;
    apply(p, q);
    const Eigen::RowVector3d pq = (p.array() * q.array()).colwise().sum();
    Eigen::RowVector3d alpha, beta;
    for (int k = 0; k < 3; ++k) alpha[k] = pq[k] > 0 ? rz[k] / pq[k] : 0.0;
    x += p * alpha.asDiagonal();
    r -= q * alpha.asDiagonal();
    precondition(r, q);
    const Eigen::RowVector3d rz_next = (r.array() * q.array()).colwise().sum();
    for (int k = 0; k < 3; ++k) beta[k] = rz[k] > 0 ? rz_next[k] / rz[k] : 0.0;
    p = q + p * beta.asDiagonal();
    rz = rz_next;
    report.error_bound = bound();
    if (progress)
      progress(std::log(start / std::max(report.error_bound, max_error)) / std::log(start / max_error));
  }
  for (Positions* work : {&r, &p, &q, &a, &b, &c}) work->resize(0, 3);
  result.resize(x.rows(), 3);
  for (size_t i = 0; i < order.size(); ++i) result.row(order[i]) = x.row(i);
  return true;
}

}  // namespace hht
