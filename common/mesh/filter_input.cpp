#include "mesh/filter_input.h"

#include <numeric>

namespace hht {

void prepare_filter_input(Positions& positions, Faces& faces, bool mend, InputMap& map, FilterInputReport& report) {
  report = FilterInputReport{};
  map = InputMap{};
  CornerTable table;
  int inconsistent = 0, cut = 0;
  std::string error;
  const auto build = [&] {
    return build_corner_table_cutting(faces, positions, table, inconsistent, cut, error);
  };
  if (!build()) return;  // faces out of range or repeating a vertex: the filter says so
  // Edges of more than two faces: without `mend` no step applies (the filter says so, or works
  // without); with it, the faces the table left unpaired there come apart in the split.
  if (cut > 0 && !mend) return;
  BorderWeld weld;
  if (mend && weld_coincident_border_vertices(positions, faces, table, weld, report.not_merged_why)) {
    positions = std::move(weld.positions);
    faces = std::move(weld.faces);
    map.row_of = std::move(weld.welded_of);
    report.merged = weld.merged;
    report.dropped_faces = weld.dropped_faces;
    if (!build()) return;
  }
  // Seams on a mesh with such edges: the merge refuses them (it does not join faces into edges of
  // more than two), and the parts filtered apart would open at the seams; the filter refuses the
  // edges as it did before they were split.
  if (cut > 0 && !report.not_merged_why.empty()) return;
  report.cut_edges = cut;
  report.orientation = orient_as_most_faces(faces, table, inconsistent);
  if (!mend || !report.orientation.done) return;
  const int n = static_cast<int>(positions.rows());
  if (report.orientation.flipped > 0 && !build()) return;
  if (cut == 0 && count_nonmanifold_vertices(table, n) == 0) return;
  // The fans are walked across paired edges only, so the split also gives the faces left unpaired
  // at an edge of more than two faces vertices of their own.
  VertexSplit split;
  report.split = split_nonmanifold_vertices(faces, table, n, split);
  positions.conservativeResize(n + report.split, 3);
  for (int k = 0; k < report.split; ++k) positions.row(n + k) = positions.row(split.copy_of[k]);
  // Each vertex takes the result of the copy inside a surface (a fin's or a repeated face's copy
  // lies on a border) with the most face area around it.
  const int rows = n + report.split;
  std::vector<char> on_border(rows, 0);
  if (build_corner_table(faces, rows, table, inconsistent, error))
    for (int c = 0; c < table.corners(); ++c)
      if (table.opposite[c] < 0) on_border[table.vertex[corner_next(c)]] = on_border[table.vertex[corner_prev(c)]] = 1;
  Eigen::VectorXd around = Eigen::VectorXd::Zero(rows);
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const Eigen::RowVector3d a = positions.row(faces(f, 0)), b = positions.row(faces(f, 1)), c = positions.row(faces(f, 2));
    const double area = (b - a).cross(c - a).norm();
    for (int k = 0; k < 3; ++k) around[faces(f, k)] += area;
  }
  const auto better = [&](int a, int b) {
    return on_border[a] != on_border[b] ? !on_border[a] : around[a] > around[b];
  };
  map.result_of.resize(n);
  std::iota(map.result_of.begin(), map.result_of.end(), 0);
  for (int k = 0; k < report.split; ++k) {
    int& taken = map.result_of[split.copy_of[k]];
    if (better(n + k, taken)) taken = n + k;
  }
  map.copy_of = std::move(split.copy_of);
}

}  // namespace hht
