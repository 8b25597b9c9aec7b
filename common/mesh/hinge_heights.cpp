#include "mesh/hinge_heights.h"

#include <algorithm>
#include <cmath>

namespace hht {

void for_each_hinge(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                    const std::function<void(const Hinge&)>& visit) {
  // The two vertices facing each edge (a, b), a < b, kept in a's slot for b of the adjacency:
  // linear in the mesh and no larger than the adjacency itself, even on millions of vertices.
  constexpr int kNone = -1, kMore = -2;  // no face yet; a third face (non-manifold)
  std::vector<int> first(adjacency.neighbours.size(), kNone), second(adjacency.neighbours.size(), kNone);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(faces(f, (k + 1) % 3), faces(f, (k + 2) % 3));
      const int b = std::max(faces(f, (k + 1) % 3), faces(f, (k + 2) % 3));
      const int* at = std::lower_bound(adjacency.begin(a), adjacency.end(a), b);
      if (a == b || at == adjacency.end(a) || *at != b) continue;
      const size_t slot = static_cast<size_t>(at - adjacency.neighbours.data());
      if (first[slot] == kNone) first[slot] = faces(f, k);
      else if (second[slot] == kNone) second[slot] = faces(f, k);
      else second[slot] = kMore;
    }

  for (int a = 0; a < adjacency.vertices(); ++a)
    for (const int* at = adjacency.begin(a); at != adjacency.end(a); ++at) {
      const size_t slot = static_cast<size_t>(at - adjacency.neighbours.data());
      if (*at < a || second[slot] < 0) continue;  // each edge once; boundary or non-manifold
      const Eigen::Vector3d A = positions.row(a), B = positions.row(*at);
      const Eigen::Vector3d C = positions.row(first[slot]), D = positions.row(second[slot]);
      if (C == D) continue;  // a face and its duplicate (or a fold onto itself): no hinge
      Eigen::Vector3d normal = (B - A).cross(C - A);
      const double twice_area = normal.norm();
      const double other_area = (B - A).cross(D - A).norm();
      if (!(twice_area > 0 && other_area > 0 && std::isfinite(twice_area))) continue;
      normal /= twice_area;
      const double height = normal.dot(D - A);
      const Eigen::Vector3d foot = D - height * normal;
      const double beta = (foot - A).cross(C - A).dot(normal) / twice_area;
      const double gamma = (B - A).cross(foot - A).dot(normal) / twice_area;
      const double alpha = 1 - beta - gamma;
      visit(Hinge{a, *at, first[slot], second[slot], height / std::sqrt(1 + alpha * alpha + beta * beta + gamma * gamma)});
    }
}

std::vector<double> hinge_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  std::vector<double> heights;
  for_each_hinge(positions, faces, adjacency, [&](const Hinge& h) { heights.push_back(h.height); });
  return heights;
}

}  // namespace hht
