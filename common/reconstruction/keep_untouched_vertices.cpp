#include "reconstruction/keep_untouched_vertices.h"

#include "mesh/flat_hinge_spikes.h"
#include "mesh/vertex_adjacency.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/normal_vertex_update.h"

#include <vector>

namespace hht {

int keep_untouched_vertices(const Positions& input, const Faces& faces, Positions& result) {
  const int n = static_cast<int>(input.rows());
  const FlatHingeSpikes spikes = flat_hinge_spikes(input, faces, vertex_adjacency(faces, n));
  if (!spikes.impulsive()) return 0;
  std::vector<unsigned char> kept(static_cast<size_t>(n), 0);
  const Positions targets = unit_face_normals(result, faces);
  int count = 0;
  for (int v = 0; v < n; ++v)
    if (spikes.role[static_cast<size_t>(v)] == kOnFlatHinge) {
      kept[static_cast<size_t>(v)] = 1;
      result.row(v) = input.row(v);
      ++count;
    }
  result = fit_vertices_to_normals(result, faces, targets, kUntouchedFitIterations, kept);
  return count;
}

}  // namespace hht
