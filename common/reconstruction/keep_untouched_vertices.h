// Under impulsive noise, the vertices the noise left alone kept where the input has them.
//
// Why: impulsive noise moves a share of the vertices and leaves the others exactly where they
// were, so on a CAD mesh every hinge of four untouched vertices on a flat face (or a cylinder's
// ruling) is still exactly flat (mesh/flat_hinge_spikes.h), and a vertex on such a hinge is known
// to be noise-free. A denoiser run over the whole mesh moves them all the same (it cannot tell
// which vertices were hit) and blunts what they hold. Putting them back and fitting the other
// vertices to the denoised face normals with them held (normal_vertex_update.h) keeps both: the
// spikes smoothed away, the untouched surface exact (docs/quality.md, item 25). Ours, not the
// paper's.
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

// Vertex update iterations after the put-back.
constexpr int kUntouchedFitIterations = 10;

// When `input` reads impulsive noise (FlatHingeSpikes::impulsive), puts the vertices of its exactly
// flat hinges back into `result` (the input denoised, same faces), fits the others to result's
// face normals and returns how many were kept; otherwise leaves `result` and returns 0.
int keep_untouched_vertices(const Positions& input, const Faces& faces, Positions& result);

}  // namespace hht
