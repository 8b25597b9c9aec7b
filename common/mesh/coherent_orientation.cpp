#include "mesh/coherent_orientation.h"

#include <vector>

namespace hht {

OrientationRepair orient_as_most_faces(Faces& faces, int vertex_count) {
  CornerTable table;
  int inconsistent_edges = 0;
  OrientationRepair repair;
  if (!build_corner_table(faces, vertex_count, table, inconsistent_edges, repair.why_not)) return repair;
  return orient_as_most_faces(faces, table, inconsistent_edges);
}

OrientationRepair orient_as_most_faces(Faces& faces, const CornerTable& table, int inconsistent_edges) {
  OrientationRepair repair;
  repair.done = true;
  if (inconsistent_edges == 0) return repair;
  // One coherent orientation per component (its first face's), then per component the one of the
  // two that reverses fewer faces.
  Faces oriented = faces;
  if (!orient_faces_coherently(oriented, table, repair.why_not)) {
    repair.done = false;
    return repair;
  }
  std::vector<int> component;
  const int count = face_components(table, component);
  std::vector<int> size(count, 0), reversed(count, 0);
  const auto nf = faces.rows();
  for (Eigen::Index f = 0; f < nf; ++f) {
    ++size[component[f]];
    reversed[component[f]] += oriented(f, 1) != faces(f, 1);
  }
  for (Eigen::Index f = 0; f < nf; ++f) {
    const int c = component[f];
    const bool flip = 2 * reversed[c] > size[c] ? oriented(f, 1) == faces(f, 1) : oriented(f, 1) != faces(f, 1);
    if (flip) {
      std::swap(faces(f, 1), faces(f, 2));
      ++repair.flipped;
    }
  }
  for (int c = 0; c < count; ++c) repair.components += reversed[c] > 0;
  return repair;
}

}  // namespace hht
