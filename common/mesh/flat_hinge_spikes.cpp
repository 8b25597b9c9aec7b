#include "mesh/flat_hinge_spikes.h"

#include "mesh/hinge_heights.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {

bool FlatHingeSpikes::impulsive() const { return spikes >= kMinSpikes && share() >= kSpikeShare; }

FlatHingeSpikes flat_hinge_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  const size_t n = static_cast<size_t>(adjacency.vertices());
  std::vector<unsigned char> touches_flat(n, 0);
  std::vector<int> hinges(n, 0), bent(n, 0);
  long within = 0, next = 0;  // hinges within their allowance, and bent by one to two of it
  for_each_hinge(positions, faces, adjacency, [&](const Hinge& h) {
    const Eigen::Vector3d a = positions.row(h.a), b = positions.row(h.b);
    const double edge = (b - a).norm();
    const double height = std::abs(h.height);
    const double allowed = kHingeFlatness * edge + kCoordinateRounding * a.cwiseAbs().maxCoeff();
    const bool flat = height <= allowed;
    within += flat;
    next += !flat && height <= 2 * allowed;
    const int corners[4] = {h.a, h.b, h.c, h.d};
    for (int k = 0; k < 4; ++k) {
      const size_t i = static_cast<size_t>(corners[k]);
      ++hinges[i];
      bent[i] += height >= kSpikeBend * edge;
      if (!flat || touches_flat[i]) continue;
      // Only if the other three corners span a plane: three on a line hold every position of this one.
      const Eigen::Vector3d p = positions.row(corners[(k + 1) % 4]), q = positions.row(corners[(k + 2) % 4]),
                            r = positions.row(corners[(k + 3) % 4]);
      const double longest = std::max({(q - p).squaredNorm(), (r - p).squaredNorm(), (r - q).squaredNorm()});
      touches_flat[i] = (q - p).cross(r - p).norm() >= kSpanningCorners * longest;
    }
  });
  // Hinges within the allowance by chance, about as many as bend by one to two of it, are no flat part.
  if (static_cast<double>(next) > kChanceFlatRatio * static_cast<double>(within))
    std::fill(touches_flat.begin(), touches_flat.end(), 0);
  FlatHingeSpikes out;
  out.role.assign(n, 0);
  for (size_t i = 0; i < n; ++i) out.role[i] = touches_flat[i] ? kOnFlatHinge : 0;
  for (int v = 0; v < adjacency.vertices(); ++v) {
    if (adjacency.valence(v) < 3 || adjacency.boundary[v]) continue;
    bool surrounded = true;
    for (const int* u = adjacency.begin(v); u != adjacency.end(v) && surrounded; ++u) surrounded = touches_flat[*u];
    if (!surrounded) continue;
    const size_t i = static_cast<size_t>(v);
    ++out.surrounded;
    const bool spike = !touches_flat[i] && 2 * bent[i] >= hinges[i];
    if (spike) out.role[i] = kSpike;
    out.spikes += spike;
  }
  return out;
}

}  // namespace hht
