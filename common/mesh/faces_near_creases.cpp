#include "mesh/faces_near_creases.h"

#include <cmath>

namespace hht {

std::vector<unsigned char> faces_near_creases(const std::vector<DihedralAngle>& angles, const Faces& faces,
                                              Eigen::Index vertex_count, double degrees) {
  const double threshold = degrees * M_PI / 180;
  std::vector<unsigned char> on_crease(vertex_count, 0), near(faces.rows(), 0);
  for (const DihedralAngle& d : angles)
    if (d.radians > threshold) on_crease[d.a] = on_crease[d.b] = 1;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    near[f] = on_crease[faces(f, 0)] || on_crease[faces(f, 1)] || on_crease[faces(f, 2)];
  return near;
}

}  // namespace hht
