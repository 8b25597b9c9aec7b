#include "mesh/border_weld.h"

#include <algorithm>
#include <numeric>

namespace hht {

namespace {

// Vertices whose faces, coherently oriented, form more than one fan, not counting the vertices of
// edges of more than two faces (the table pairs such an edge's faces, and the faces left over come
// apart at those vertices anyway; docs/quality.md item 44); kNoOrientation when the faces have no
// coherent orientation.
constexpr int kNoOrientation = -1;
int nonmanifold_vertices(const Positions& positions, const Faces& faces) {
  const int n = static_cast<int>(positions.rows());
  CornerTable table;
  int inconsistent = 0, cut = 0;
  std::string error;
  if (!build_corner_table_cutting(faces, positions, table, inconsistent, cut, error)) return 0;
  Faces oriented = faces;
  if (!orient_faces_coherently(oriented, table, error)) return kNoOrientation;
  std::vector<char> on_cut_edge, nonmanifold;
  if (!build_corner_table_cutting(oriented, positions, table, inconsistent, cut, error, &on_cut_edge)) return 0;
  count_nonmanifold_vertices(table, n, &nonmanifold);
  int count = 0;
  for (int v = 0; v < n; ++v) count += nonmanifold[v] && !on_cut_edge[v] ? 1 : 0;
  return count;
}

}  // namespace

bool weld_coincident_border_vertices(const Positions& positions, const Faces& faces, BorderWeld& weld,
                                     std::string& why_not) {
  weld = BorderWeld{};
  why_not.clear();
  CornerTable table;
  int inconsistent = 0, cut = 0;
  std::string error;
  if (!build_corner_table_cutting(faces, positions, table, inconsistent, cut, error))
    return false;  // the filter says what is wrong
  return weld_coincident_border_vertices(positions, faces, table, weld, why_not);
}

bool weld_coincident_border_vertices(const Positions& positions, const Faces& faces, const CornerTable& table,
                                     BorderWeld& weld, std::string& why_not) {
  weld = BorderWeld{};
  why_not.clear();
  const int n = static_cast<int>(positions.rows());
  std::vector<int> border;
  {
    std::vector<unsigned char> on_border(n, 0);
    for (int c = 0; c < table.corners(); ++c)
      if (table.opposite[c] < 0) on_border[table.vertex[corner_next(c)]] = on_border[table.vertex[corner_prev(c)]] = 1;
    for (int i = 0; i < n; ++i)
      if (on_border[i]) border.push_back(i);
  }
  auto position_less = [&](int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (positions(a, k) != positions(b, k)) return positions(a, k) < positions(b, k);
    return a < b;
  };
  std::sort(border.begin(), border.end(), position_less);
  std::vector<int> representative(n);
  std::iota(representative.begin(), representative.end(), 0);
  int merged = 0;
  for (size_t i = 1; i < border.size(); ++i)
    if (positions.row(border[i]) == positions.row(border[i - 1])) {
      representative[border[i]] = representative[border[i - 1]];  // the group's smallest index
      ++merged;
    }
  if (merged == 0) return false;

  std::vector<int> welded_of(n, -1);
  int rows = 0;
  for (int i = 0; i < n; ++i)
    if (representative[i] == i) welded_of[i] = rows++;
  for (int i = 0; i < n; ++i) welded_of[i] = welded_of[representative[i]];
  Faces welded_faces(faces.rows(), 3);
  int kept = 0, dropped = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const int a = welded_of[faces(f, 0)], b = welded_of[faces(f, 1)], c = welded_of[faces(f, 2)];
    if (a == b || b == c || a == c) {
      ++dropped;
      continue;
    }
    welded_faces.row(kept++) << a, b, c;
  }
  welded_faces.conservativeResize(kept, 3);
  Positions welded_positions(rows, 3);
  for (int i = 0; i < n; ++i) welded_positions.row(welded_of[i]) = positions.row(i);
  const int after = nonmanifold_vertices(welded_positions, welded_faces);
  if (after == kNoOrientation) {
    why_not = "merged, the surface would have no coherent orientation";
    return false;
  }
  // An input without a coherent orientation counts as having none: merging may mend it.
  if (after > std::max(0, nonmanifold_vertices(positions, faces))) {
    why_not = "merging them would join parts at a single vertex";
    return false;
  }
  weld.positions = std::move(welded_positions);
  weld.faces = std::move(welded_faces);
  weld.welded_of = std::move(welded_of);
  weld.merged = merged;
  weld.dropped_faces = dropped;
  return true;
}

}  // namespace hht
