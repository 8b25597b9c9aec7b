#include "mesh/face_rings.h"

#include <algorithm>
#include <numeric>

namespace hht {

IndexLists vertex_faces(const Faces& faces, int vertex_count) {
  IndexLists l;
  l.start.assign(vertex_count + 1, 0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++l.start[faces(f, k) + 1];
  std::partial_sum(l.start.begin(), l.start.end(), l.start.begin());
  std::vector<int> fill(l.start.begin(), l.start.end() - 1);
  l.items.resize(l.start.back());
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) l.items[fill[faces(f, k)]++] = static_cast<int>(f);
  return l;
}

void face_ring(const Faces& faces, const IndexLists& around, Eigen::Index f, std::vector<int>& ring) {
  ring.clear();
  for (int k = 0; k < 3; ++k) {
    const int v = faces(f, k);
    ring.insert(ring.end(), around.items.begin() + around.begin(v), around.items.begin() + around.end(v));
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
}

IndexLists face_rings(const Faces& faces, int vertex_count) {
  const IndexLists around = vertex_faces(faces, vertex_count);
  IndexLists rings;
  rings.start.assign(faces.rows() + 1, 0);
  std::vector<int> ring;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    face_ring(faces, around, f, ring);
    rings.items.insert(rings.items.end(), ring.begin(), ring.end());
    rings.start[f + 1] = static_cast<int>(rings.items.size());
  }
  return rings;
}

}  // namespace hht
