#include "mesh/vertex_split.h"

namespace hht {

int split_nonmanifold_vertices(Faces& faces, const CornerTable& table, int vertex_count, VertexSplit& split) {
  split = VertexSplit{};
  std::vector<char> seen(table.corners(), 0), has_fan(vertex_count, 0);
  std::vector<int> fan;
  for (int c = 0; c < table.corners(); ++c) {
    if (seen[c]) continue;
    // The corners of c's fan: swing forward (next(opposite(next(x)))), and back from c where the
    // fan is open at a boundary (count_nonmanifold_vertices walks the same way).
    fan.clear();
    for (int x = c; x >= 0 && !seen[x];) {
      seen[x] = 1;
      fan.push_back(x);
      const int o = table.opposite[corner_next(x)];
      x = o < 0 ? -1 : corner_next(o);
    }
    for (int x = c;;) {
      const int o = table.opposite[corner_prev(x)];
      if (o < 0) break;
      x = corner_prev(o);
      if (seen[x]) break;
      seen[x] = 1;
      fan.push_back(x);
    }
    const int v = table.vertex[c];
    if (!has_fan[v]) {
      has_fan[v] = 1;
      continue;
    }
    const int copy = vertex_count + static_cast<int>(split.copy_of.size());
    split.copy_of.push_back(v);
    for (int x : fan) faces(corner_triangle(x), x % 3) = copy;
  }
  return static_cast<int>(split.copy_of.size());
}

}  // namespace hht
