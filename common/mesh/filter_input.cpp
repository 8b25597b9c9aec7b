#include "mesh/filter_input.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace hht {

namespace {

// For each of the first `n` rows, the row whose result it takes: itself or one of its copies (the
// rows from n on, `copy_of`), one inside a surface before one on a border (a fin's copy of its foot
// lies on a border), then the one with the most face area around it. `table` is the
// corner table before the split, whose borders the split keeps; `faces` are after it.
std::vector<int> result_rows(const Positions& positions, const Faces& faces, const CornerTable& table,
                             const std::vector<int>& copy_of, int n) {
  const int rows = static_cast<int>(positions.rows());
  std::vector<char> on_border(rows, 0);
  for (int c = 0; c < table.corners(); ++c)
    if (table.opposite[c] < 0)
      on_border[faces(corner_triangle(c), corner_next(c) % 3)] = on_border[faces(corner_triangle(c), corner_prev(c) % 3)] = 1;
  Eigen::VectorXd around = Eigen::VectorXd::Zero(rows);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0)), b = positions.row(faces(f, 1)), c = positions.row(faces(f, 2));
    const double area = (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) around[faces(f, k)] += area;
  }
  const auto better = [&](int a, int b) { return on_border[a] != on_border[b] ? !on_border[a] : around[a] > around[b]; };
  std::vector<int> result(n);
  std::iota(result.begin(), result.end(), 0);
  for (size_t k = 0; k < copy_of.size(); ++k) {
    const int copy = n + static_cast<int>(k);
    if (better(copy, result[copy_of[k]])) result[copy_of[k]] = copy;
  }
  return result;
}

// Drops every face with the same three vertices as an earlier one, in either orientation (an
// export's repeats): it adds no surface to filter, and its edges would hold more than two faces,
// which the pairing can leave tangled (a face given twice beside one given three times kept an
// edge of three faces after the split). Returns how many were dropped.
int drop_repeated_faces(Faces& faces) {
  const Eigen::Index nf = faces.rows();
  std::vector<std::pair<std::array<int, 3>, Eigen::Index>> keyed(static_cast<size_t>(nf));
  for (Eigen::Index f = 0; f < nf; ++f) {
    std::array<int, 3> key{faces(f, 0), faces(f, 1), faces(f, 2)};
    std::sort(key.begin(), key.end());
    keyed[static_cast<size_t>(f)] = {key, f};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<char> repeat(static_cast<size_t>(nf), 0);
  int dropped = 0;
  for (size_t k = 1; k < keyed.size(); ++k)
    if (keyed[k].first == keyed[k - 1].first) {
      repeat[static_cast<size_t>(keyed[k].second)] = 1;
      ++dropped;
    }
  if (dropped == 0) return 0;
  Faces kept(nf - dropped, 3);
  Eigen::Index row = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!repeat[static_cast<size_t>(f)]) kept.row(row++) = faces.row(f);
  faces = std::move(kept);
  return dropped;
}

}  // namespace

void prepare_filter_input(Positions& positions, Faces& faces, bool mend, InputMap& map, FilterInputReport& report) {
  report = FilterInputReport{};
  map = InputMap{};
  CornerTable table;
  int inconsistent = 0, cut = 0;
  std::string error;
  const auto build = [&] {
    return build_corner_table_cutting(faces, positions, table, inconsistent, cut, error);
  };
  // Repeated faces make edges of more than two faces, so they are looked for only where there are
  // such edges: before the merge and again after it, which can make repeats of a soup's faces.
  const auto drop_repeats = [&] {
    if (cut == 0) return true;
    const int dropped = drop_repeated_faces(faces);
    report.repeated_faces += dropped;
    return dropped == 0 || build();
  };
  if (!build()) return;  // faces out of range or repeating a vertex: the filter says so
  // Edges of more than two faces: without `mend` no step applies (the filter says so, or works
  // without); with it, the faces the table left unpaired there come apart in the split.
  if (cut > 0 && !mend) return;
  if (mend && !drop_repeats()) return;
  BorderWeld weld;
  if (mend && weld_coincident_border_vertices(positions, faces, table, weld, report.not_merged_why)) {
    positions = std::move(weld.positions);
    faces = std::move(weld.faces);
    map.row_of = std::move(weld.welded_of);
    report.merged = weld.merged;
    report.dropped_faces = weld.dropped_faces;
    if (!build() || !drop_repeats()) return;
  }
  // Seams the merge refused on a mesh with such edges: the parts filtered apart would open at the
  // seams; the filter refuses the edges as it did before they were split.
  if (cut > 0 && !report.not_merged_why.empty()) return;
  report.cut_edges = cut;
  report.orientation = orient_as_most_faces(faces, table, inconsistent);
  if (!mend || !report.orientation.done) return;
  const int n = static_cast<int>(positions.rows());
  if (report.orientation.flipped > 0 && !build()) return;
  // The fans are walked across paired edges only, so the split also gives the faces left unpaired
  // at an edge of more than two faces vertices of their own. A manifold has nothing to split.
  VertexSplit split;
  report.split = split_nonmanifold_vertices(faces, table, n, split);
  if (report.split == 0) return;
  positions.conservativeResize(n + report.split, 3);
  for (int k = 0; k < report.split; ++k) positions.row(n + k) = positions.row(split.copy_of[k]);
  map.result_of = result_rows(positions, faces, table, split.copy_of, n);
  map.copy_of = std::move(split.copy_of);
}

}  // namespace hht
