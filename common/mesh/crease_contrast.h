// How much a surface is made of flat pieces meeting at creases: the 98th percentile of the
// angles between the normals of faces sharing an edge, over their median. A CAD part, once its
// noise is smoothed away, has nearly flat faces and a few sharp creases (9.5 to 22 on the
// corpus's fandisk, cube, anchor, turbine and blade at 10-30% noise); an organic surface bends
// everywhere about as much (5 to 9 on homer, cow, femur, bunny00, camel, man), and so does a
// CAD part without sharp creases (mech-holes-shark, 5). docs/quality.md has the table.
//
// A percentile misses the creases of a finely meshed part: a crease is a line, so its share of
// the edges falls as the mesh is refined, and below 2% the 98th percentile no longer reaches it
// (fandisk with every triangle cut in 16 reads 5.0-8.6 at 2-30% noise). The crease lines
// measure the creases as lines instead (ours, docs/quality.md item 28).
#pragma once

#include "mesh/dihedral_angles.h"

namespace hht {

// An edge is on a crease line when its angle is over this times the median (floored as below).
constexpr double kCreaseLineContrast = 12.0;
// Chains of such edges shorter than this times sqrt(E) are not lines (noise left over, a sharp
// spot of an organic surface).
constexpr double kShortestCreaseLine = 0.05;

// Both readings of a mesh's dihedral angles, from one median; 0 and 0 without interior edges.
struct CreaseReadings {
  // The crease contrast. The median counts as at least 0.57 degrees (a clean CAD part is mostly
  // exactly flat); 0 also when every dihedral angle is 0 (a plane).
  double contrast = 0;
  // The length of the crease lines in units of the mesh's breadth: the edges on crease lines,
  // joined into chains where they share a vertex, counted over the chains of at least
  // kShortestCreaseLine sqrt(E) edges, divided by sqrt(E) (E the edges with an angle). Lines keep
  // their length in these units when the mesh is refined: the meshed cube reads 3.8 however finely
  // it is cut, fandisk about 5 (docs/quality.md item 28).
  double lines = 0;
};

CreaseReadings read_creases(const std::vector<DihedralAngle>& angles);
double crease_contrast(const Positions& positions, const Faces& faces);  // of dihedral_angles()

}  // namespace hht
