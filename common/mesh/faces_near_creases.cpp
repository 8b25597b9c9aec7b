#include "mesh/faces_near_creases.h"

#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace hht {

std::vector<unsigned char> faces_near_creases(const Positions& positions, const Faces& faces, double degrees) {
  const Positions normals = unit_face_normals(positions, faces);
  const double min_cosine = std::cos(degrees * M_PI / 180);
  std::vector<unsigned char> on_crease(positions.rows(), 0), near(faces.rows(), 0);
  std::unordered_map<uint64_t, Eigen::Index> first_face;
  first_face.reserve(static_cast<size_t>(faces.rows()) * 3 / 2);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const uint64_t a = static_cast<uint32_t>(faces(f, k)), b = static_cast<uint32_t>(faces(f, (k + 1) % 3));
      const auto found = first_face.emplace(std::min(a, b) << 32 | std::max(a, b), f);
      if (found.second) continue;
      const Eigen::Index g = found.first->second;
      if (normals.row(f).squaredNorm() > 0 && normals.row(g).squaredNorm() > 0 && normals.row(f).dot(normals.row(g)) < min_cosine)
        on_crease[a] = on_crease[b] = 1;
    }
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    near[f] = on_crease[faces(f, 0)] || on_crease[faces(f, 1)] || on_crease[faces(f, 2)];
  return near;
}

}  // namespace hht
