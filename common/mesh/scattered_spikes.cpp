#include "mesh/scattered_spikes.h"

#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>

namespace hht {

void update_ring_height(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                        const IndexLists& around, int v, RingHeights& ring) {
  Eigen::RowVector3d c = positions.row(v);
  if (adjacency.valence(v) > 0) {
    c.setZero();
    for (const int* j = adjacency.begin(v); j != adjacency.end(v); ++j) c += positions.row(*j);
    c /= adjacency.valence(v);
  }
  ring.centroid.row(v) = c;
  // The fan's area vectors with v at c, face by face and corner by corner in face order (a face
  // listed twice holds v at two corners).
  Eigen::RowVector3d normal = Eigen::RowVector3d::Zero();
  for (int e = around.begin(v); e < around.end(v); ++e) {
    const int f = around.items[static_cast<size_t>(e)];
    if (e > around.begin(v) && around.items[static_cast<size_t>(e - 1)] == f) continue;
    for (int k = 0; k < 3; ++k)
      if (faces(f, k) == v)
        normal += (positions.row(faces(f, (k + 1) % 3)) - c).cross(positions.row(faces(f, (k + 2) % 3)) - c);
  }
  const double length = normal.norm();
  if (!(length > 0) || adjacency.valence(v) == 0) {
    ring.normal.row(v).setZero();
    ring.height[v] = 0;
    return;
  }
  ring.normal.row(v) = normal / length;
  ring.height[v] = (positions.row(v) - c).dot(ring.normal.row(v));
}

RingHeights ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                         const IndexLists& around) {
  const int n = adjacency.vertices();
  RingHeights out;
  out.centroid.resize(n, 3);
  out.normal.resize(n, 3);
  out.height.resize(n);
  parallel_for(0, n, [&](int first, int last) {
    for (int v = first; v < last; ++v) update_ring_height(positions, faces, adjacency, around, v, out);
  });
  return out;
}

RingHeights ring_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  return ring_heights(positions, faces, adjacency, vertex_faces(faces, adjacency.vertices()));
}

double two_ring_height_quantile(const Eigen::VectorXd& height, const VertexAdjacency& adjacency, int v, double q,
                                TwoRingScratch& scratch) {
  std::vector<int>& ring = scratch.ring;
  ring.clear();
  for (const int* j = adjacency.begin(v); j != adjacency.end(v); ++j) {
    ring.push_back(*j);
    for (const int* k = adjacency.begin(*j); k != adjacency.end(*j); ++k)
      if (*k != v) ring.push_back(*k);
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  std::vector<double>& values = scratch.values;
  values.clear();
  for (int j : ring) values.push_back(std::abs(height[j]));
  if (values.empty()) return 0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

double mean_ring_edge(const Positions& positions, const VertexAdjacency& adjacency, int v) {
  double sum = 0;
  for (const int* j = adjacency.begin(v); j != adjacency.end(v); ++j) sum += (positions.row(*j) - positions.row(v)).norm();
  return adjacency.valence(v) > 0 ? sum / adjacency.valence(v) : 0;
}

bool ScatteredSpikes::impulsive() const { return spikes >= kMinScatteredSpikes && share() >= kScatteredSpikeShare; }

ScatteredSpikes scattered_spikes(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency) {
  const int n = adjacency.vertices();
  const Eigen::VectorXd h = ring_heights(positions, faces, adjacency).height;
  std::vector<unsigned char> interior(static_cast<size_t>(n), 0), spike(static_cast<size_t>(n), 0);
  parallel_for(0, n, [&](int first, int last) {
    TwoRingScratch scratch;
    for (int v = first; v < last; ++v) {
      if (adjacency.valence(v) < 3 || adjacency.boundary[static_cast<size_t>(v)]) continue;
      interior[static_cast<size_t>(v)] = 1;
      const double a = std::abs(h[v]);
      bool over_neighbours = a > kSpikeStandOff * mean_ring_edge(positions, adjacency, v);
      for (const int* j = adjacency.begin(v); j != adjacency.end(v) && over_neighbours; ++j)
        over_neighbours = a > kScatteredSpikeOverNeighbours * std::abs(h[*j]);
      if (!over_neighbours) continue;
      // A scale of 0: exactly flat surroundings, flat_hinge_spikes.h's to read (a cube's corners stand so too).
      const double scale = two_ring_height_quantile(h, adjacency, v, kScatteredSpikeQuantile, scratch);
      spike[static_cast<size_t>(v)] = scale > 0 && a > kScatteredSpikeScale * scale;
    }
  });
  ScatteredSpikes out;
  out.interior = static_cast<int>(std::count(interior.begin(), interior.end(), 1));
  out.spikes = static_cast<int>(std::count(spike.begin(), spike.end(), 1));
  return out;
}

}  // namespace hht
