#include "filters/guided_normal_denoise.h"

#include "mesh/mesh_checks.h"
#include "reconstruction/flip_guard.h"
#include "reconstruction/normal_vertex_update.h"
#include "mesh/sharp_features.h"

namespace hht {

bool guided_normal_denoise(const Positions& positions, const Faces& faces, const GuidedNormalDenoiseOptions& options,
                           Positions& result, std::string& error, const std::function<void(double)>& progress,
                           GuidedNormalDenoiseReport* report) {
  if (report) *report = GuidedNormalDenoiseReport{};
  if (!check_triangle_mesh(positions, faces, error)) return false;
  if (options.rounds < 0 || options.normal_passes < 0 || options.vertex_iterations < 0 || !(options.sigma > 0)) {
    error = "rounds, passes and iterations must be at least 0 and sigma positive";
    return false;
  }
  result = positions;
  const bool own_normals = options.guidance == NormalGuidance::OwnNormal;
  for (int round = 0; round < options.rounds; ++round) {
    if (options.fit_each_pass && options.normal_passes > 0) {
      int pass = 0;
      const auto fit = [&](const Positions& p, const Positions& normals) {
        Positions fitted = fit_vertices_to_normals(p, faces, normals, options.vertex_iterations);
        if (progress) progress((round + ++pass / static_cast<double>(options.normal_passes)) / options.rounds);
        return fitted;
      };
      Positions next;
      if (!filter_face_normals_refitting(result, faces, options.normal_passes, options.sigma, own_normals, fit, next,
                                         error, options.face_sigma))
        return false;
      result.swap(next);
      continue;
    }
    Positions normals;
    const bool filtered =
        own_normals ? bilateral_face_normals(result, faces, options.normal_passes, options.sigma, normals, error,
                                             options.face_sigma)
                    : guided_face_normals(result, faces, options.normal_passes, options.sigma, normals, error,
                                          options.face_sigma);
    if (!filtered) return false;
    if (progress) progress((round + 0.8) / options.rounds);
    result = fit_vertices_to_normals(result, faces, normals, options.vertex_iterations);
    if (progress) progress((round + 1.0) / options.rounds);
  }
  if (!result.allFinite()) {
    error = "the vertex update produced non-finite positions";
    return false;
  }
  if (options.stand_up_turned_faces) {
    const int stood_up = unturn_few_turned_faces(positions, faces, 1.0, result);
    if (report) report->stood_up_faces = stood_up;
  }
  return true;
}

}  // namespace hht
