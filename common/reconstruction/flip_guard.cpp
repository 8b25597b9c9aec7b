#include "reconstruction/flip_guard.h"

#include <vector>

namespace hht {

namespace {

Eigen::RowVector3d area_vector(const Positions& p, const Faces& faces, Eigen::Index f) {
  const Eigen::RowVector3d a = p.row(faces(f, 0));
  return (p.row(faces(f, 1)) - a).cross(p.row(faces(f, 2)) - a);
}

}  // namespace

int restore_turned_faces(const Positions& input, const Faces& faces, Positions& result) {
  std::vector<unsigned char> restored(input.rows(), 0);
  int count = 0;
  // Each pass restores at least one vertex or stops, so this ends; a few passes suffice.
  for (bool changed = true; changed;) {
    changed = false;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d before = area_vector(input, faces, f);
      if (before.squaredNorm() == 0 || before.dot(area_vector(result, faces, f)) >= 0) continue;
      for (int k = 0; k < 3; ++k) {
        const int v = faces(f, k);
        if (restored[v]) continue;
        result.row(v) = input.row(v);
        restored[v] = 1;
        ++count;
        changed = true;
      }
    }
  }
  return count;
}

}  // namespace hht
