#include "mesh/vertex_split.h"

namespace hht {

int split_nonmanifold_vertices(Faces& faces, const CornerTable& table, int vertex_count, VertexSplit& split) {
  split = VertexSplit{};
  std::vector<char> seen(table.corners(), 0), has_fan(vertex_count, 0);
  std::vector<int> fan;
  for (int c = 0; c < table.corners(); ++c) {
    if (seen[c]) continue;
    fan.clear();
    walk_fan(table, c, seen, fan);
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
