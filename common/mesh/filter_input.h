// The surface a filter works on, made whole from what MeshLab holds: border vertices at the same
// position merged (border_weld.h: a triangle soup, a surface cut at seams), then faces oriented
// against their neighbours turned (coherent_orientation.h). One corner table serves both steps
// unless the merge changes the faces (0.28 s for both at 3.3M faces; docs/quality.md item 42).
#pragma once

#include "mesh/border_weld.h"
#include "mesh/coherent_orientation.h"

#include <string>
#include <vector>

namespace hht {

struct FilterInputReport {
  int merged = 0;               // vertices merged into another (0: `welded_of` left empty)
  int dropped_faces = 0;        // faces the merge left with no area
  std::string not_merged_why;   // border vertices on each other, left apart: why
  OrientationRepair orientation;  // done false with an empty why_not: edges of more than two faces, not checked
};

// Merges (when `merge_seams`) and orients `positions` and `faces` in place; `welded_of` gets each
// input vertex's row when vertices were merged, and is emptied otherwise.
void prepare_filter_input(Positions& positions, Faces& faces, bool merge_seams, std::vector<int>& welded_of,
                          FilterInputReport& report);

}  // namespace hht
