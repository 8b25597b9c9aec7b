// Feature-preserving denoising by guided mesh normal filtering alone (Zhang, Deng, Zhang,
// Bouaziz, Liu, "Guided mesh normal filtering", Pacific Graphics 2015): face normals are
// filtered by a joint bilateral filter whose range kernel compares guidance normals taken from
// the most consistent patch around each face (sharp_features.h, guided_face_normals), then the
// vertices are fitted to the filtered normals (Sun et al. 2007, normal_vertex_update.h); the
// two steps are repeated `rounds` times, each round filtering the normals of the last result.
// With `fit_each_pass` the vertices are fitted after every normal pass instead of once after all
// of them, as the authors' code does (its defaults: 20 such steps of 10 vertex iterations): each
// pass then filters normals that the surface can take.
// No HHT: the strongest of the field's denoisers that this project has, the baseline the HHT
// denoiser is measured against, and the refinement stage of that denoiser. With
// NormalGuidance::OwnNormal it is bilateral normal filtering (Zheng et al. 2011), the other
// classic of the field (its authors' defaults: 20 passes, 10 vertex iterations, one round).
#pragma once

#include <functional>
#include <vector>

#include "mesh/mesh_arrays.h"

#include <string>

namespace hht {

// What the range kernel compares: the guidance normals of the most consistent patch (Zhang et
// al. 2015), or each face's own filtered normal (bilateral normal filtering, Zheng et al. 2011).
enum class NormalGuidance { ConsistentPatch, OwnNormal };

struct GuidedNormalDenoiseOptions {
  int rounds = 1;              // normal filtering + vertex update, repeated
  int normal_passes = 8;       // guided normal filtering passes per round
  double sigma = 0.35;         // range width on unit guidance normals (~20 degrees)
  int vertex_iterations = 20;  // vertex update iterations per round, or per pass with fit_each_pass
  bool fit_each_pass = false;  // vertices fitted after every normal pass (see above)
  std::vector<double> face_sigma;  // each face's own range width instead of `sigma` (empty: none)
  NormalGuidance guidance = NormalGuidance::ConsistentPatch;
  // Ours, not the published methods': the faces the vertex update turned over against the input
  // (and not folded there) stood back up at the end (flip_guard.h, unturn_few_turned_faces with
  // every such face taken). On a clean irregular mesh the filter turns its wrinkles and slivers
  // over (man: 471 faces; docs/quality.md item 40); the filter's dialog has it on.
  bool stand_up_turned_faces = false;
};

struct GuidedNormalDenoiseReport {
  int stood_up_faces = 0;  // with stand_up_turned_faces: the faces stood back up
};

// Fails like guided_face_normals on broken input (no faces, non-manifold, non-finite).
// progress(fraction done) after each round's normal filtering and vertex update.
bool guided_normal_denoise(const Positions& positions, const Faces& faces, const GuidedNormalDenoiseOptions& options,
                           Positions& result, std::string& error, const std::function<void(double)>& progress = {},
                           GuidedNormalDenoiseReport* report = nullptr);

}  // namespace hht
