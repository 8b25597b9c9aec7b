#include "reconstruction/normal_vertex_update.h"

#include "util/parallel_for.h"

#include <vector>

namespace hht {

Positions fit_vertices_to_normals(const Positions& positions, const Faces& faces, const Positions& face_normals,
                                  int iterations, const std::vector<unsigned char>& fixed) {
  const int n = static_cast<int>(positions.rows());
  const int m = static_cast<int>(faces.rows());
  // Each vertex's faces that have a target, in ascending order (a face listed once per corner at
  // the vertex): summing their pulls in that order gives, to the bit, what a sweep over the faces
  // gives, and lets the vertices be updated in parallel.
  std::vector<int> first(n + 1, 0);
  for (int f = 0; f < m; ++f)
    if (face_normals.row(f).squaredNorm() > 0)
      for (int k = 0; k < 3; ++k) ++first[faces(f, k) + 1];
  for (int i = 0; i < n; ++i) first[i + 1] += first[i];
  std::vector<int> incident(first[n]), next(first.begin(), first.end() - 1);
  for (int f = 0; f < m; ++f)
    if (face_normals.row(f).squaredNorm() > 0)
      for (int k = 0; k < 3; ++k) incident[next[faces(f, k)]++] = f;

  Positions v = positions, moved(n, 3), centroids(m, 3);
  for (int it = 0; it < iterations; ++it) {
    parallel_for(0, m, [&](int begin, int end) {
      for (int f = begin; f < end; ++f)
        centroids.row(f) = (v.row(faces(f, 0)) + v.row(faces(f, 1)) + v.row(faces(f, 2))) / 3.0;
    });
    parallel_for(0, n, [&](int begin, int end) {
      for (int i = begin; i < end; ++i) {
        Eigen::RowVector3d step = Eigen::RowVector3d::Zero();
        for (int j = first[i]; j < first[i + 1]; ++j) {
          const Eigen::RowVector3d normal = face_normals.row(incident[j]);
          step += normal * normal.dot(centroids.row(incident[j]) - v.row(i));
        }
        const bool moves = first[i + 1] > first[i] && !(static_cast<size_t>(i) < fixed.size() && fixed[static_cast<size_t>(i)]);
        moved.row(i) = moves ? Eigen::RowVector3d(v.row(i) + step / (first[i + 1] - first[i])) : Eigen::RowVector3d(v.row(i));
      }
    });
    v.swap(moved);
  }
  return v;
}

}  // namespace hht
