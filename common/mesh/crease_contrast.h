// How much a surface is made of flat pieces meeting at creases: the 98th percentile of the
// angles between the normals of faces sharing an edge, over their median. A CAD part, once its
// noise is smoothed away, has nearly flat faces and a few sharp creases (9.5 to 22 on the
// corpus's fandisk, cube, anchor, turbine and blade at 10-30% noise); an organic surface bends
// everywhere about as much (5 to 9 on homer, cow, femur, bunny00, camel, man), and so does a
// CAD part without sharp creases (mech-holes-shark, 5). docs/quality.md has the table.
#pragma once

#include "mesh/dihedral_angles.h"

namespace hht {

// The median counts as at least 0.57 degrees (a clean CAD part is mostly exactly flat); 0 when
// the mesh has no interior edge or every dihedral angle is 0 (a plane).
double crease_contrast(const std::vector<DihedralAngle>& angles);
double crease_contrast(const Positions& positions, const Faces& faces);  // of dihedral_angles()

}  // namespace hht
