#include "mesh/crease_contrast.h"

#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace hht {

namespace {
constexpr double kFlat = 0.01;  // radians (0.57 degrees); the corpus's smoothed medians are 2-11 degrees
}  // namespace

double crease_contrast(const Positions& positions, const Faces& faces) {
  const Positions normals = unit_face_normals(positions, faces);
  std::unordered_map<uint64_t, Eigen::Index> first_face;
  first_face.reserve(static_cast<size_t>(faces.rows()) * 3 / 2);
  std::vector<double> angles;
  angles.reserve(static_cast<size_t>(faces.rows()) * 3 / 2);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const uint64_t a = static_cast<uint32_t>(faces(f, k)), b = static_cast<uint32_t>(faces(f, (k + 1) % 3));
      const uint64_t key = std::min(a, b) << 32 | std::max(a, b);
      const auto found = first_face.emplace(key, f);
      if (found.second) continue;
      const Eigen::Index g = found.first->second;
      if (normals.row(f).squaredNorm() > 0 && normals.row(g).squaredNorm() > 0)
        angles.push_back(std::acos(std::clamp(normals.row(f).dot(normals.row(g)), -1.0, 1.0)));
    }
  if (angles.empty()) return 0;
  const size_t median = (angles.size() - 1) / 2, high = static_cast<size_t>(0.98 * static_cast<double>(angles.size() - 1));
  std::nth_element(angles.begin(), angles.begin() + high, angles.end());
  const double upper = angles[high];
  std::nth_element(angles.begin(), angles.begin() + median, angles.begin() + high);
  // Flat pieces make the median 0 on a clean CAD mesh: it counts as at least kFlat.
  return upper / std::max(angles[median], kFlat);
}

}  // namespace hht
