#include "filters/guided_normal_denoise.h"

#include <algorithm>

#include "mesh/mesh_checks.h"
#include "reconstruction/normal_vertex_update.h"
#include "mesh/sharp_features.h"

namespace hht {

bool guided_normal_denoise(const Positions& positions, const Faces& faces, const GuidedNormalDenoiseOptions& options,
                           Positions& result, std::string& error, const std::function<void(double)>& progress) {
  if (!check_triangle_mesh(positions, faces, error)) return false;
  if (options.rounds < 0 || options.normal_passes < 0 || options.vertex_iterations < 0 || !(options.sigma > 0)) {
    error = "rounds, passes and iterations must be at least 0 and sigma positive";
    return false;
  }
  result = positions;
  // Each step filters the normals `passes` times, then fits the vertices to them.
  const int steps = options.fit_each_pass ? std::max(1, options.normal_passes) : 1;
  const int passes = options.fit_each_pass ? std::min(1, options.normal_passes) : options.normal_passes;
  for (int round = 0; round < options.rounds; ++round) {
    for (int step = 0; step < steps; ++step) {
      Positions normals;
      const bool filtered =
          options.guidance == NormalGuidance::OwnNormal
              ? bilateral_face_normals(result, faces, passes, options.sigma, normals, error, options.face_sigma)
              : guided_face_normals(result, faces, passes, options.sigma, normals, error, options.face_sigma);
      if (!filtered) return false;
      result = fit_vertices_to_normals(result, faces, normals, options.vertex_iterations);
      if (progress) progress((round + (step + 1.0) / steps) / options.rounds);
    }
  }
  if (!result.allFinite()) {
    error = "the vertex update produced non-finite positions";
    return false;
  }
  return true;
}

}  // namespace hht
