#include "mesh/hinge_heights.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hht {

std::vector<double> hinge_heights(const Positions& positions, const Faces& faces) {
  // Each corner faces one edge; sorting the corners by that edge pairs the two faces of it.
  struct Corner {
    std::uint64_t edge;
    int corner;
  };
  std::vector<Corner> corners;
  corners.reserve(3 * static_cast<size_t>(faces.rows()));
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = static_cast<std::uint32_t>(faces(f, (k + 1) % 3));
      const std::uint64_t b = static_cast<std::uint32_t>(faces(f, (k + 2) % 3));
      corners.push_back({std::min(a, b) << 32 | std::max(a, b), static_cast<int>(3 * f + k)});
    }
  std::sort(corners.begin(), corners.end(),
            [](const Corner& x, const Corner& y) { return x.edge != y.edge ? x.edge < y.edge : x.corner < y.corner; });

  std::vector<double> heights;
  heights.reserve(corners.size() / 2);
  for (size_t i = 0; i < corners.size();) {
    size_t j = i + 1;
    while (j < corners.size() && corners[j].edge == corners[i].edge) ++j;
    if (j - i == 2) {
      const int c = corners[i].corner, d = corners[i + 1].corner;
      const Eigen::Vector3d A = positions.row(faces(c / 3, (c % 3 + 1) % 3));
      const Eigen::Vector3d B = positions.row(faces(c / 3, (c % 3 + 2) % 3));
      const Eigen::Vector3d C = positions.row(faces(c / 3, c % 3));
      const Eigen::Vector3d D = positions.row(faces(d / 3, d % 3));
      Eigen::Vector3d normal = (B - A).cross(C - A);
      const double twice_area = normal.norm();
      const double other_area = (A - B).cross(D - B).norm();
      if (twice_area > 0 && other_area > 0 && std::isfinite(twice_area)) {
        normal /= twice_area;
        const double height = normal.dot(D - A);
        const Eigen::Vector3d foot = D - height * normal;
        const double beta = (foot - A).cross(C - A).dot(normal) / twice_area;
        const double gamma = (B - A).cross(foot - A).dot(normal) / twice_area;
        const double alpha = 1 - beta - gamma;
        heights.push_back(height / std::sqrt(1 + alpha * alpha + beta * beta + gamma * gamma));
      }
    }
    i = j;
  }
  return heights;
}

}  // namespace hht
