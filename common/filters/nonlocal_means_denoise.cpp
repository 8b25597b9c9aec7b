#include "filters/nonlocal_means_denoise.h"

#include "evaluation/gaussian_noise.h"
#include "filters/surface_emd.h"
#include "mesh/vertex_normals.h"

#include <array>
#include <cmath>
#include <vector>

namespace hht {

namespace {

constexpr int kAnnuli = 3;

// Breadth-first walk from v over mesh edges, staying within `radius` of v (v's one-ring always
// taken); calls visit(q) for every vertex reached, v excluded.
template <class Visit>
void walk(int v, const Positions& p, const std::vector<int>& offset, const std::vector<int>& neighbours, double radius,
          std::vector<int>& stamp, std::vector<int>& queue, Visit&& visit) {
  const double radius2 = radius * radius;
  stamp[v] = v;
  queue.assign(1, v);
  for (size_t head = 0; head < queue.size(); ++head) {
    const int u = queue[head];
    for (int k = offset[u]; k < offset[u + 1]; ++k) {
      const int q = neighbours[k];
      if (stamp[q] == v) continue;
      const bool inside = (p.row(q) - p.row(v)).squaredNorm() < radius2;
      if (!inside && u != v) continue;
      stamp[q] = v;
      if (inside) queue.push_back(q);
      visit(q);
    }
  }
}

}  // namespace

Positions nonlocal_means_denoise(const Positions& positions, const Faces& faces, const NonLocalMeansOptions& options) {
  if (faces.rows() == 0 || !positions.allFinite() || options.iterations <= 0 || !(options.eta1 > 0) ||
      !(options.eta2 > 0) || !(options.eta3 > 0))
    return positions;
  const int n = static_cast<int>(positions.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (faces(f, k) < 0 || faces(f, k) >= n) return positions;
  const double l = mean_edge_length(positions, faces);
  if (!(l > 0)) return positions;
  const double eta1 = options.eta1 * l, eta2 = options.eta2 * l, eta3 = options.eta3 * l;
  const double spatial = 2.0 / (eta1 * eta1);  // 1 / (2 (eta1/2)^2)
  std::vector<int> offset, neighbours;
  one_ring_adjacency(faces, n, offset, neighbours);

  Positions current = positions, next = positions;
  std::vector<int> stamp(n), queue;
  // centroid[v][a]: mean position of the vertices in annulus a around v.
  std::vector<std::array<Eigen::RowVector3d, kAnnuli>> centroid(n);
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    const Positions normals = area_weighted_vertex_normals(current, faces);
    std::fill(stamp.begin(), stamp.end(), -1);
    for (int v = 0; v < n; ++v) {
      std::array<Eigen::RowVector3d, kAnnuli> sum;
      std::array<int, kAnnuli> count{};
      for (auto& s : sum) s.setZero();
      const Eigen::RowVector3d pv = current.row(v);
      walk(v, current, offset, neighbours, (kAnnuli + 0.5) * eta3, stamp, queue, [&](int r) {
        const double x = (current.row(r) - pv).norm() / eta3;  // annuli [0, 1.5), [1.5, 2.5), [2.5, 3.5)
        const int annulus = x < 1.5 ? 0 : static_cast<int>(x - 0.5);
        if (annulus >= kAnnuli) return;
        sum[annulus] += current.row(r);
        ++count[annulus];
      });
      for (int a = 0; a < kAnnuli; ++a)
        centroid[v][a] = count[a] > 0 ? Eigen::RowVector3d(sum[a] / count[a]) : (a > 0 ? centroid[v][a - 1] : pv);
    }
    std::fill(stamp.begin(), stamp.end(), -1);
    for (int v = 0; v < n; ++v) {
      const Eigen::RowVector3d nv = normals.row(v), pv = current.row(v);
      if (nv.squaredNorm() == 0) continue;
      double sum_wh = 0, sum_w = 0;
      walk(v, current, offset, neighbours, eta1, stamp, queue, [&](int q) {
        const Eigen::RowVector3d d = current.row(q) - pv;
        double d2 = 0;
        for (int a = 0; a < kAnnuli; ++a) {
          const double h = nv.dot(centroid[q][a] - centroid[v][a]);
          d2 += h * h;
        }
        const double w = std::exp(-d.squaredNorm() * spatial - d2 / (eta2 * eta2));
        sum_wh += w * nv.dot(d);
        sum_w += w;
      });
      if (sum_w > 0) next.row(v) = pv + nv * (sum_wh / sum_w);
    }
    current = next;
  }
  return current;
}

}  // namespace hht
