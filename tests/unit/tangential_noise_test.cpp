#include "evaluation/gaussian_noise.h"
#include "mesh/tangential_noise.h"
#include "mesh/vertex_adjacency.h"
#include "mesh/vertex_normals.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hht {
namespace {

// The share for noise of `level` mean edges added in `direction`, read with the clean mesh's
// normals (the smoothing reads them from its input, averaged over a few rings).
double share(const test::ArrayMesh& m, double level, NoiseDirection direction, double read_level = -1) {
  const double edge = mean_edge_length(m.positions, m.faces);
  const Positions noisy = level > 0 ? add_gaussian_noise(m.positions, m.faces, 100 * level, direction, 5) : m.positions;
  const Positions normals = area_weighted_vertex_normals(m.positions, m.faces).rowwise().normalized();
  return tangential_noise_share(noisy, normals, vertex_adjacency(m.faces, static_cast<int>(m.positions.rows())),
                                (read_level > 0 ? read_level : level) * edge);
}

// Isotropic noise fills the share; noise along the normals leaves it at the triangulation's
// own offsets, small on a regular mesh. Fails if the offsets are not projected on the tangent
// plane (noise along the normals then reads about half) or the expectation is off.
TEST(TangentialNoise, TellsIsotropicNoiseFromNoiseAlongTheNormals) {
  const test::ArrayMesh s = test::sphere(5);
  for (double level : {0.1, 0.3}) {
    EXPECT_GT(share(s, level, NoiseDirection::Isotropic), 0.95) << level;
    EXPECT_LT(share(s, level, NoiseDirection::Normal), 0.1) << level;
  }
}

// An irregular triangulation's own offsets count as room for tangential noise: the share never
// goes below 1 with isotropic noise, and stays high along the normals at 10% (cow's floor).
TEST(TangentialNoise, AnIrregularMeshReadsItsOwnOffsets) {
  const test::ArrayMesh cow = test::load_data_mesh("cow");
  EXPECT_EQ(share(cow, 0.1, NoiseDirection::Isotropic), 1.0);
  EXPECT_EQ(share(cow, 0.3, NoiseDirection::Isotropic), 1.0);
  EXPECT_GT(share(cow, 0.1, NoiseDirection::Normal), 0.9);
}

// A layout that varies smoothly over the surface (a graded sampling: here each coordinate of a
// flat grid shifted along itself by a sine of 8 edges' period) is not noise: its offsets from
// the one-ring centroids exceed what noise of a tenth of an edge gives them, but they change
// little from vertex to vertex, and the second differences the share reads drop them (0.02
// along the normals). Reading the offsets themselves, noise along the normals scores 1.
TEST(TangentialNoise, ASmoothlyGradedLayoutIsNotNoise) {
  test::ArrayMesh graded = test::grid(40, 40);
  const double period = 8, amplitude = 0.9;
  for (Eigen::Index i = 0; i < graded.positions.rows(); ++i)
    for (int c = 0; c < 2; ++c)
      graded.positions(i, c) += amplitude * std::sin(2 * M_PI * graded.positions(i, c) / period);
  EXPECT_LT(share(graded, 0.1, NoiseDirection::Normal), 0.2);
  EXPECT_GT(share(graded, 0.1, NoiseDirection::Isotropic), 0.9);
}

// A large mesh is read at a stride of its vertices: the mean changes little (a sphere of 10,242
// vertices read at 1,000 of them), and a stride that skipped the vertices' rings altogether (or
// counted the rest as zeros) would not.
TEST(TangentialNoise, AStridedSampleReadsAsTheWholeMesh) {
  const test::ArrayMesh s = test::sphere(5);
  const double edge = mean_edge_length(s.positions, s.faces);
  const Positions normals = area_weighted_vertex_normals(s.positions, s.faces).rowwise().normalized();
  const VertexAdjacency adjacency = vertex_adjacency(s.faces, s.vertices());
  for (NoiseDirection direction : {NoiseDirection::Isotropic, NoiseDirection::Normal}) {
    const Positions noisy = add_gaussian_noise(s.positions, s.faces, 20, direction, 5);
    const double whole = tangential_noise_share(noisy, normals, adjacency, 0.2 * edge);
    const double sampled = tangential_noise_share(noisy, normals, adjacency, 0.2 * edge, 1000);
    EXPECT_NEAR(sampled, whole, 0.05 * whole + 0.01);
  }
}

// A vertex on a hole's rim sits off its one-sided centroid by the surface's extent, not noise:
// counted, a sphere with holes and noise along the normals reads 1 at 10%.
TEST(TangentialNoise, LeavesBoundaryVerticesOut) {
  const test::ArrayMesh holes = test::remove_faces(test::sphere(5), 7);
  EXPECT_LT(share(holes, 0.1, NoiseDirection::Normal), 0.1);
  EXPECT_LT(share(holes, 0, NoiseDirection::Normal, 0.1), 0.1);
}

// The expectation counts two coordinates, those of each vertex's tangent plane, so the second
// difference is projected on it again: the neighbours' offsets lie in their own planes. On a
// coarse torus (8 vertices around the tube: the normals turn by 45 degrees from one to the next)
// noise along the normals gives them a part along the vertex's normal, which counted would raise
// the reading by half. Checked against the definition in dense matrices: D = I - W, the offsets
// O = P D V and S = P D O (P the projections on the tangent planes), share = |S|^2 over
// 2 sigma^2 |D^2|^2 (Frobenius norms).
TEST(TangentialNoise, ReadsTheSecondDifferencesOnEachTangentPlane) {
  const test::ArrayMesh torus = test::torus(1.0, 0.35, 12, 8);
  const int n = torus.vertices();
  const double sigma = 0.1 * mean_edge_length(torus.positions, torus.faces);
  const Positions noisy = add_gaussian_noise(torus.positions, torus.faces, 10, NoiseDirection::Normal, 5);
  const Positions normals = area_weighted_vertex_normals(torus.positions, torus.faces).rowwise().normalized();

  Eigen::MatrixXd adjacent = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index f = 0; f < torus.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = torus.faces(f, k), b = torus.faces(f, (k + 1) % 3);
      adjacent(a, b) = adjacent(b, a) = 1;
    }
  const Eigen::MatrixXd d = Eigen::MatrixXd::Identity(n, n) - (adjacent.rowwise().sum().cwiseInverse().asDiagonal() * adjacent);
  auto project = [&](const Eigen::MatrixXd& x) {
    return Eigen::MatrixXd(x - (x.cwiseProduct(normals).rowwise().sum().asDiagonal() * normals));
  };
  const Eigen::MatrixXd second = project(d * project(d * noisy));
  const double reference = second.squaredNorm() / (2 * sigma * sigma * (d * d).squaredNorm());
  ASSERT_LT(reference, 0.5);  // below the cap at 1

  const double read = tangential_noise_share(noisy, normals, vertex_adjacency(torus.faces, n), sigma);
  EXPECT_NEAR(read, reference, 1e-9 * reference);
}

TEST(TangentialNoise, NoSigmaOrNoInteriorVertexReadsOne) {
  const test::ArrayMesh s = test::sphere(2);
  const Positions normals = area_weighted_vertex_normals(s.positions, s.faces).rowwise().normalized();
  const VertexAdjacency adjacency = vertex_adjacency(s.faces, static_cast<int>(s.positions.rows()));
  EXPECT_EQ(tangential_noise_share(s.positions, normals, adjacency, 0), 1.0);
  Faces one(1, 3);
  one << 0, 1, 2;
  EXPECT_EQ(tangential_noise_share(s.positions, normals, vertex_adjacency(one, static_cast<int>(s.positions.rows())), 0.1),
            1.0);
}

}  // namespace
}  // namespace hht
