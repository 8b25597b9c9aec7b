#include "filters/bilateral_denoise.h"

#include "evaluation/gaussian_noise.h"
#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {

namespace {

// Vertex-to-vertex adjacency over the faces' edges, compressed: the neighbours of v are
// neighbours[start[v], start[v + 1]).
struct Adjacency {
  std::vector<int> start, neighbours;
};

Adjacency vertex_adjacency(const Faces& faces, Eigen::Index vertex_count) {
  std::vector<std::vector<int>> lists(vertex_count);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      lists[faces(f, k)].push_back(faces(f, (k + 1) % 3));
      lists[faces(f, (k + 1) % 3)].push_back(faces(f, k));
    }
  Adjacency a;
  a.start.push_back(0);
  for (auto& list : lists) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    a.neighbours.insert(a.neighbours.end(), list.begin(), list.end());
    a.start.push_back(static_cast<int>(a.neighbours.size()));
  }
  return a;
}

}  // namespace

Positions bilateral_denoise(const Positions& positions, const Faces& faces, const BilateralOptions& options) {
  if (faces.rows() == 0 || !positions.allFinite() || options.passes <= 0 || !(options.sigma_c > 0) ||
      !(options.sigma_s > 0))
    return positions;
  const double l = mean_edge_length(positions, faces);
  if (!(l > 0)) return positions;  // every vertex in one point: no scale to measure by
  const double sigma_c = options.sigma_c * l, sigma_s = options.sigma_s * l;
  const double radius2 = 4 * sigma_c * sigma_c;
  const Adjacency adjacency = vertex_adjacency(faces, positions.rows());

  Positions current = positions, next = positions;
  std::vector<int> stamp(positions.rows(), -1), queue;
  for (int pass = 0; pass < options.passes; ++pass) {
    const Positions normals = area_weighted_vertex_normals(current, faces);
    std::fill(stamp.begin(), stamp.end(), -1);
    for (Eigen::Index v = 0; v < current.rows(); ++v) {
      const Eigen::RowVector3d n = normals.row(v), p = current.row(v);
      if (n.squaredNorm() == 0) continue;
      double sum_wh = 0, sum_w = 0;
      // Stamped with the searching vertex: nothing to clear between the searches of a pass.
      const int id = static_cast<int>(v);
      stamp[v] = id;
      queue.assign(1, id);
      for (size_t head = 0; head < queue.size(); ++head) {
        const int u = queue[head];
        for (int k = adjacency.start[u]; k < adjacency.start[u + 1]; ++k) {
          const int q = adjacency.neighbours[k];
          if (stamp[q] == id) continue;
          const Eigen::RowVector3d d = current.row(q) - p;
          const double t2 = d.squaredNorm();
          const bool inside = t2 < radius2;
          if (!inside && u != v) continue;  // the one-ring always counts, see the header
          stamp[q] = id;
          if (inside) queue.push_back(q);
          const double h = n.dot(d);
          const double w = std::exp(-t2 / (2 * sigma_c * sigma_c)) * std::exp(-h * h / (2 * sigma_s * sigma_s));
          sum_wh += w * h;
          sum_w += w;
        }
      }
      if (sum_w > 0) next.row(v) = p + n * (sum_wh / sum_w);
    }
    current = next;
  }
  return current;
}

}  // namespace hht
