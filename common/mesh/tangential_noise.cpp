#include "mesh/tangential_noise.h"

#include <algorithm>

namespace hht {

double tangential_noise_share(const Positions& v, const Positions& unit_normals, const VertexAdjacency& adjacency,
                              double sigma) {
  if (!(sigma > 0)) return 1;
  double measured = 0, expected = 0;
  for (int i = 0; i < adjacency.vertices(); ++i) {
    // A boundary vertex sits off its one-sided centroid by the surface's own extent.
    const int valence = adjacency.valence(i);
    if (valence == 0 || adjacency.boundary[i]) continue;
    Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
    for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) centroid += v.row(*j);
    const Eigen::RowVector3d offset = v.row(i) - centroid / valence;
    const Eigen::RowVector3d normal = unit_normals.row(i);
    measured += (offset - offset.dot(normal) * normal).squaredNorm();
    expected += 2 * sigma * sigma * (1 + 1.0 / valence);
  }
  if (!(expected > 0)) return 1;
  return std::min(1.0, measured / expected);
}

}  // namespace hht
