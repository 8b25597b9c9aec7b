#include "evaluation/gaussian_noise.h"
#include "mesh/scattered_spikes.h"
#include "mesh/vertex_adjacency.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace hht {
namespace {

ScatteredSpikes spikes_of(const Positions& p, const Faces& f) {
  return scattered_spikes(p, f, vertex_adjacency(f, static_cast<int>(p.rows())));
}

// A vertex lifted off a flat grid stands off its ring; its neighbours hold a sixth of the lift each.
TEST(ScatteredSpikes, RingHeightOfALiftedVertex) {
  test::ArrayMesh g = test::grid(7, 7);
  const int v = 3 * 7 + 3;
  g.positions(v, 2) = 0.6;
  const VertexAdjacency adjacency = vertex_adjacency(g.faces, g.vertices());
  const RingHeights ring = ring_heights(g.positions, g.faces, adjacency);
  EXPECT_NEAR(std::abs(ring.height[v]), 0.6, 1e-12);  // the ring normal ignores the vertex itself
  EXPECT_NEAR(std::abs(ring.normal(v, 2)), 1.0, 1e-12);
  for (const int* j = adjacency.begin(v); j != adjacency.end(v); ++j)
    EXPECT_NEAR(std::abs(ring.height[*j]), 0.1, 0.02) << *j;
}

// Moving a few vertices changes the ring heights of those vertices and their neighbours only:
// recomputing just these gives exactly a full recount (the spike removal's rounds rely on it).
TEST(ScatteredSpikes, RingHeightsUpdatedAroundMovesEqualAFullRecount) {
  const test::ArrayMesh m = test::load_data_mesh("cow");
  const VertexAdjacency adjacency = vertex_adjacency(m.faces, m.vertices());
  const IndexLists around = vertex_faces(m.faces, m.vertices());
  RingHeights ring = ring_heights(m.positions, m.faces, adjacency, around);
  Positions moved = m.positions;
  std::vector<int> touched;
  for (int v = 0; v < m.vertices(); v += 97) {
    moved.row(v) += Eigen::RowVector3d(0.01, -0.02, 0.015);
    touched.push_back(v);
    touched.insert(touched.end(), adjacency.begin(v), adjacency.end(v));
  }
  for (int v : touched) update_ring_height(moved, m.faces, adjacency, around, v, ring);
  const RingHeights full = ring_heights(moved, m.faces, adjacency);
  EXPECT_EQ(ring.height, full.height);
  EXPECT_EQ(ring.normal, full.normal);
  EXPECT_EQ(ring.centroid, full.centroid);
}

// Clean meshes, organic and CAD, have a few tips at most, not a share (a cube's corners stand off
// exactly flat faces: flat_hinge_spikes.h reads those).
TEST(ScatteredSpikes, CleanMeshesAreNotImpulsive) {
  for (const char* name : {"cow", "femur", "bull", "camel", "elephant", "armadillo", "fandisk", "cube-meshed", "turbine",
                           "blade", "rotor", "spool", "anchor_dense"}) {
    const test::ArrayMesh m = test::load_data_mesh(name);
    const ScatteredSpikes s = spikes_of(m.positions, m.faces);
    EXPECT_GT(s.interior, m.vertices() / 2) << name;
    EXPECT_LE(s.share(), 0.5 * kScatteredSpikeShare) << name << ": " << s.spikes << " of " << s.interior;
    EXPECT_FALSE(s.impulsive()) << name;
  }
}

// Gaussian noise moves every vertex, in any direction model: no share of spikes over their rings.
TEST(ScatteredSpikes, GaussianNoiseIsNotImpulsive) {
  for (const char* name : {"cow", "camel", "elephant", "bull"})
    for (NoiseDirection direction : {NoiseDirection::Isotropic, NoiseDirection::Normal, NoiseDirection::Random})
      for (double percent : {2.0, 10.0, 30.0}) {
        const test::ArrayMesh m = test::load_data_mesh(name);
        const ScatteredSpikes s = spikes_of(add_gaussian_noise(m.positions, m.faces, percent, direction, 7), m.faces);
        EXPECT_FALSE(s.impulsive()) << name << " " << percent << " direction " << static_cast<int>(direction) << ": "
                                    << s.spikes << " of " << s.interior;
      }
}

// A share of the vertices moved along the normals, the others left alone: impulsive, on organic
// meshes and on CAD meshes alike. (A twentieth moved is not read on every mesh: elephant 8 spikes.)
TEST(ScatteredSpikes, ImpulsiveNoiseStandsOut) {
  for (const char* name : {"cow", "femur", "camel", "elephant", "fandisk", "turbine"})
    for (double share : {0.1, 0.3}) {
      const test::ArrayMesh m = test::load_data_mesh(name);
      const Positions noisy = add_gaussian_noise(m.positions, m.faces, 50, NoiseDirection::Normal, 3, share);
      const ScatteredSpikes s = spikes_of(noisy, m.faces);
      EXPECT_TRUE(s.impulsive()) << name << " " << share << ": " << s.spikes << " of " << s.interior;
      EXPECT_LT(s.share(), share) << name << " " << share;
    }
}

}  // namespace
}  // namespace hht
