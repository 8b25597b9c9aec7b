#include "mesh/flat_hinge_spikes.h"

#include "mesh/hinge_heights.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hht {

bool FlatHingeSpikes::impulsive() const { return spikes >= kMinSpikes && share() >= kSpikeShare; }

namespace {

// How far a hinge may bend and still count as flat: kHingeFlatness of its edge plus the rounding of
// coordinates of its magnitude.
double flatness_allowed(const Positions& positions, const Hinge& h, double& edge) {
  const Eigen::Vector3d a = positions.row(h.a), b = positions.row(h.b);
  edge = (b - a).norm();
  return kHingeFlatness * edge + kCoordinateRounding * a.cwiseAbs().maxCoeff();
}

// Whether the hinges within their allowance stand out from those bent by one to two allowances
// (see kChanceFlatRatio).
bool flat_hinges_stand_out(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  long within = 0, next = 0;
  for_each_hinge(positions, faces, adjacency, [&](const Hinge& h) {
    double edge = 0;
    const double allowed = flatness_allowed(positions, h, edge), height = std::abs(h.height);
    within += height <= allowed;
    next += height > allowed && height <= 2 * allowed;
  });
  return within > 0 && static_cast<double>(next) <= kChanceFlatRatio * static_cast<double>(within);
}

}  // namespace

FlatHingeSpikes flat_hinge_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  const size_t n = static_cast<size_t>(adjacency.vertices());
  std::vector<unsigned char> touches_flat(n, 0);
  std::vector<int> hinges(n, 0), bent(n, 0);
  const bool judged = flat_hinges_stand_out(positions, faces, adjacency);
  for_each_hinge(positions, faces, adjacency, [&](const Hinge& h) {
    double edge = 0;
    const double allowed = flatness_allowed(positions, h, edge), height = std::abs(h.height);
    const bool flat = judged && height <= allowed;
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
