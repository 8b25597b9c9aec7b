#include "reconstruction/flip_guard.h"

#include "mesh/vertex_normals.h"

#include <cmath>
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

int restore_turned_faces_that_fit(const Positions& input, const Faces& faces, double max_degrees, Positions& result) {
  const Positions input_normals = area_weighted_vertex_normals(input, faces);
  const Positions surface = area_weighted_vertex_normals(result, faces);  // kept as it was before any restore
  auto corners = [&](const Positions& normals, Eigen::Index f) {
    return Eigen::RowVector3d(normals.row(faces(f, 0)) + normals.row(faces(f, 1)) + normals.row(faces(f, 2)));
  };
  std::vector<std::vector<int>> faces_of(input.rows());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) faces_of[faces(f, k)].push_back(static_cast<int>(f));
  const double min_cosine = std::cos(max_degrees * M_PI / 180);
  auto fits = [&](Eigen::Index f, const Positions& p, double cosine) {
    const Eigen::RowVector3d normal = area_vector(p, faces, f), around = corners(surface, f);
    return normal.dot(around) >= cosine * normal.norm() * around.norm();
  };
  int count = 0;
  // Putting one face back can let a neighbour fit: a few passes.
  for (int pass = 0; pass < 3; ++pass) {
    const int before = count;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d original = area_vector(input, faces, f);
      if (original.squaredNorm() == 0 || original.dot(area_vector(result, faces, f)) >= 0) continue;
      if (original.dot(corners(input_normals, f)) < 0) continue;  // a fold of the input: rightly turned
      Eigen::Matrix3d kept;
      for (int k = 0; k < 3; ++k) {
        kept.row(k) = result.row(faces(f, k));
        result.row(faces(f, k)) = input.row(faces(f, k));
      }
      bool ok = fits(f, result, min_cosine);
      for (int k = 0; k < 3 && ok; ++k)
        for (int g : faces_of[faces(f, k)])
          if (g != f && !fits(g, result, 0)) {
            ok = false;
            break;
          }
      if (ok) {
        ++count;
      } else {
        for (int k = 0; k < 3; ++k) result.row(faces(f, k)) = kept.row(k);
      }
    }
    if (count == before) break;
  }
  return count;
}

}  // namespace hht
