#include "mesh/filter_input.h"

namespace hht {

void prepare_filter_input(Positions& positions, Faces& faces, bool mend, InputMap& map, FilterInputReport& report) {
  report = FilterInputReport{};
  map = InputMap{};
  CornerTable table;
  int inconsistent = 0;
  std::string error;
  // Edges of more than two faces: no step applies (the filter says so, or works without).
  if (!build_corner_table(faces, static_cast<int>(positions.rows()), table, inconsistent, error)) return;
  BorderWeld weld;
  if (mend && weld_coincident_border_vertices(positions, faces, table, weld, report.not_merged_why)) {
    positions = std::move(weld.positions);
    faces = std::move(weld.faces);
    map.row_of = std::move(weld.welded_of);
    report.merged = weld.merged;
    report.dropped_faces = weld.dropped_faces;
    if (!build_corner_table(faces, static_cast<int>(positions.rows()), table, inconsistent, error)) return;
  }
  report.orientation = orient_as_most_faces(faces, table, inconsistent);
  if (!mend || !report.orientation.done) return;
  const int n = static_cast<int>(positions.rows());
  if (report.orientation.flipped > 0 && !build_corner_table(faces, n, table, inconsistent, error)) return;
  if (count_nonmanifold_vertices(table, n) == 0) return;
  VertexSplit split;
  report.split = split_nonmanifold_vertices(faces, table, n, split);
  positions.conservativeResize(n + report.split, 3);
  for (int k = 0; k < report.split; ++k) positions.row(n + k) = positions.row(split.copy_of[k]);
  map.copy_of = std::move(split.copy_of);
}

}  // namespace hht
