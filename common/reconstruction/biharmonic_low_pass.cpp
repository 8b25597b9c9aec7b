#include "reconstruction/biharmonic_low_pass.h"

#include "mesh/uniform_laplacian.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>

namespace hht {

namespace {

constexpr int kMaxIterations = 5000;

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

  x = v;
  Positions r(n, 3), p, q(n, 3);
  apply(x, q);
  r = mu4 * v - q;
  p = r;
  Eigen::RowVector3d rr = r.colwise().squaredNorm();
  auto bound = [&] { return r.norm() / mu4; };
  report.error_bound = bound();
  const double start = std::max(report.error_bound, max_error);
  for (; report.error_bound > max_error; ++report.iterations) {
    if (report.iterations == kMaxIterations) return false;
    apply(p, q);
    const Eigen::RowVector3d pq = (p.array() * q.array()).colwise().sum();
    Eigen::RowVector3d alpha, beta;
    for (int k = 0; k < 3; ++k) alpha[k] = pq[k] > 0 ? rr[k] / pq[k] : 0.0;
    x += p * alpha.asDiagonal();
    r -= q * alpha.asDiagonal();
    const Eigen::RowVector3d rr_next = r.colwise().squaredNorm();
    for (int k = 0; k < 3; ++k) beta[k] = rr[k] > 0 ? rr_next[k] / rr[k] : 0.0;
    p = r + p * beta.asDiagonal();
    rr = rr_next;
    report.error_bound = bound();
    if (progress && report.iterations % 8 == 0)
      progress(std::log(start / std::max(report.error_bound, max_error)) / std::log(start / max_error));
  }
  result.resize(x.rows(), 3);
  for (size_t i = 0; i < order.size(); ++i) result.row(order[i]) = x.row(i);
  return true;
}

}  // namespace hht
