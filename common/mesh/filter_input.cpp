#include "mesh/filter_input.h"

namespace hht {

void prepare_filter_input(Positions& positions, Faces& faces, bool merge_seams, std::vector<int>& welded_of,
                          FilterInputReport& report) {
  report = FilterInputReport{};
  welded_of.clear();
  CornerTable table;
  int inconsistent = 0;
  std::string error;
  // Edges of more than two faces: neither step applies (the filter says so, or works without).
  if (!build_corner_table(faces, static_cast<int>(positions.rows()), table, inconsistent, error)) return;
  BorderWeld weld;
  if (merge_seams && weld_coincident_border_vertices(positions, faces, table, weld, report.not_merged_why)) {
    positions = std::move(weld.positions);
    faces = std::move(weld.faces);
    welded_of = std::move(weld.welded_of);
    report.merged = weld.merged;
    report.dropped_faces = weld.dropped_faces;
    if (!build_corner_table(faces, static_cast<int>(positions.rows()), table, inconsistent, error)) return;
  }
  report.orientation = orient_as_most_faces(faces, table, inconsistent);
}

}  // namespace hht
