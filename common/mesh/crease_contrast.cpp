#include "mesh/crease_contrast.h"

#include <algorithm>

namespace hht {

namespace {
constexpr double kFlat = 0.01;  // radians (0.57 degrees); the corpus's smoothed medians are 2-11 degrees
}  // namespace

double crease_contrast(const std::vector<DihedralAngle>& dihedral) {
  std::vector<double> angles;
  angles.reserve(dihedral.size());
  for (const DihedralAngle& d : dihedral) angles.push_back(d.radians);
  if (angles.empty()) return 0;
  const size_t median = (angles.size() - 1) / 2, high = static_cast<size_t>(0.98 * static_cast<double>(angles.size() - 1));
  std::nth_element(angles.begin(), angles.begin() + high, angles.end());
  const double upper = angles[high];
  std::nth_element(angles.begin(), angles.begin() + median, angles.begin() + high);
  // Flat pieces make the median 0 on a clean CAD mesh: it counts as at least kFlat.
  return upper / std::max(angles[median], kFlat);
}

double crease_contrast(const Positions& positions, const Faces& faces) {
  return crease_contrast(dihedral_angles(positions, faces));
}

}  // namespace hht
