#include "mesh/vertex_adjacency.h"

#include "util/parallel_for.h"

#include <algorithm>

namespace hht {

VertexAdjacency vertex_adjacency(const Faces& faces, int vertex_count) {
  // Every face adds its two other corners to each of its vertices: a neighbour j appears in the
  // raw list of i once per face on edge ij, so an edge seen once is a boundary edge.
  std::vector<int> raw_offsets(vertex_count + 1, 0);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) raw_offsets[faces(f, k) + 1] += 2;
  for (int i = 0; i < vertex_count; ++i) raw_offsets[i + 1] += raw_offsets[i];
  std::vector<int> raw(raw_offsets.back());
  std::vector<int> fill(raw_offsets.begin(), raw_offsets.end() - 1);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int v = faces(f, k);
      raw[fill[v]++] = faces(f, (k + 1) % 3);
      raw[fill[v]++] = faces(f, (k + 2) % 3);
    }

  VertexAdjacency out;
  out.boundary.assign(vertex_count, 0);
  std::vector<int> unique_count(vertex_count + 1, 0);
  parallel_for(0, vertex_count, [&](int first, int last) {
    for (int i = first; i < last; ++i) {
      int* b = raw.data() + raw_offsets[i];
      int* e = raw.data() + raw_offsets[i + 1];
      std::sort(b, e);
      int kept = 0;
      for (int* p = b; p != e;) {
        int* q = p;
        while (q != e && *q == *p) ++q;
        if (q - p == 1) out.boundary[i] = 1;
        b[kept++] = *p;
        p = q;
      }
      unique_count[i + 1] = kept;
    }
  });
  out.offsets.assign(vertex_count + 1, 0);
  for (int i = 0; i < vertex_count; ++i) out.offsets[i + 1] = out.offsets[i] + unique_count[i + 1];
  out.neighbours.resize(out.offsets.back());
  for (int i = 0; i < vertex_count; ++i)
    std::copy(raw.begin() + raw_offsets[i], raw.begin() + raw_offsets[i] + out.valence(i),
              out.neighbours.begin() + out.offsets[i]);
  return out;
}

}  // namespace hht
