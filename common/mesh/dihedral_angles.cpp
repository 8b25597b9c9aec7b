#include "mesh/dihedral_angles.h"

#include "mesh/vertex_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace hht {

std::vector<DihedralAngle> dihedral_angles(const Positions& positions, const Faces& faces) {
  const Positions normals = unit_face_normals(positions, faces);
  std::unordered_map<uint64_t, Eigen::Index> first_face;
  first_face.reserve(static_cast<size_t>(faces.rows()) * 3 / 2);
  std::vector<DihedralAngle> angles;
  angles.reserve(static_cast<size_t>(faces.rows()) * 3 / 2);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      const uint64_t key = static_cast<uint64_t>(static_cast<uint32_t>(std::min(a, b))) << 32 | static_cast<uint32_t>(std::max(a, b));
      const auto found = first_face.emplace(key, f);
      if (found.second) continue;
      const Eigen::Index g = found.first->second;
      if (normals.row(f).squaredNorm() > 0 && normals.row(g).squaredNorm() > 0)
        angles.push_back({a, b, std::acos(std::clamp(normals.row(f).dot(normals.row(g)), -1.0, 1.0))});
    }
  return angles;
}

}  // namespace hht
