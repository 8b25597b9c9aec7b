#include "cycle/feature_lines.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/sharp_features.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace hht {
namespace {

std::vector<FeatureType> detect(const Positions& p, const Faces& f, const SharpFeatureOptions& o = {}) {
  std::vector<FeatureType> type;
  std::string error;
  EXPECT_TRUE(detect_sharp_features(p, f, o, type, error)) << error;
  return type;
}

int count_features(const std::vector<FeatureType>& type) {
  return static_cast<int>(std::count_if(type.begin(), type.end(), [](FeatureType t) { return t != FeatureType::None; }));
}

std::set<std::pair<int, int>> mesh_edges(const Faces& f) {
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int a = f(i, k), b = f(i, (k + 1) % 3);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return edges;
}

// The structure every linking must have, whatever the mesh: ordered paths along mesh edges,
// ends at corners or free ends, consistent line_of_vertex and valences; and detection types
// that agree with it (typed corners are the corners, edge vertices lie on lines).
void expect_well_formed(const Faces& faces, const std::vector<FeatureType>& type, const FeatureLines& fl) {
  const auto edges = mesh_edges(faces);
  auto adjacent = [&](int a, int b) { return edges.count({std::min(a, b), std::max(a, b)}) > 0; };
  const std::set<int> corners(fl.corners.begin(), fl.corners.end());
  ASSERT_EQ(fl.lines.size(), fl.closed.size());
  ASSERT_EQ(fl.corners.size(), fl.corner_valence.size());
  ASSERT_EQ(fl.line_of_vertex.size(), type.size());
  std::vector<int> valence(type.size(), 0), seen(type.size(), 0);
  for (size_t l = 0; l < fl.lines.size(); ++l) {
    const std::vector<int>& line = fl.lines[l];
    ASSERT_GE(line.size(), 2u) << "line " << l;
    for (size_t i = 0; i + 1 < line.size(); ++i)
      EXPECT_TRUE(adjacent(line[i], line[i + 1])) << "line " << l << " step " << i << " is no mesh edge";
    if (fl.closed[l]) {
      EXPECT_TRUE(adjacent(line.back(), line.front())) << "closed line " << l;
      EXPECT_GE(line.size(), 3u);
    } else {
      ++valence[line.front()];
      ++valence[line.back()];
    }
    for (size_t i = 0; i < line.size(); ++i) {
      const int v = line[i];
      EXPECT_NE(type[v], FeatureType::None) << "vertex " << v << " of line " << l << " is no feature";
      const bool end = !fl.closed[l] && (i == 0 || i + 1 == line.size());
      if (corners.count(v)) {
        EXPECT_TRUE(end) << "corner " << v << " inside line " << l;
        EXPECT_EQ(fl.line_of_vertex[v], -1);
      } else {
        EXPECT_EQ(fl.line_of_vertex[v], static_cast<int>(l));
        EXPECT_EQ(++seen[v], 1) << "vertex " << v << " on two lines";
      }
    }
  }
  for (size_t c = 0; c < fl.corners.size(); ++c) {
    EXPECT_EQ(fl.corner_valence[c], valence[fl.corners[c]]) << "corner " << fl.corners[c];
    EXPECT_EQ(type[fl.corners[c]], FeatureType::Corner) << "corner " << fl.corners[c];
  }
  for (size_t v = 0; v < type.size(); ++v) {
    if (type[v] == FeatureType::Corner) {
      EXPECT_TRUE(corners.count(static_cast<int>(v))) << "typed corner " << v;
    }
    if (type[v] == FeatureType::Edge) {
      EXPECT_GE(fl.line_of_vertex[v], 0) << "edge vertex " << v << " on no line";
    }
  }
}

// A flat grid, quads split along one diagonal: vertex (i, j) = i * n + j at (j, i, 0) is adjacent
// to (i +- 1, j), (i, j +- 1), (i + 1, j + 1) and (i - 1, j - 1).
struct Grid {
  static constexpr int n = 12;
  test::ArrayMesh mesh;
  std::vector<FeatureType> type = std::vector<FeatureType>(n * n, FeatureType::None);
  Grid() : mesh(test::grid(n, n)) {}
  static int at(int i, int j) { return i * n + j; }
  void mark(int i, int j, FeatureType t = FeatureType::Edge) { type[at(i, j)] = t; }
  FeatureLines link(int min_line_length = 3) const { return link_feature_lines(mesh.positions, mesh.faces, type, min_line_length); }
};

// ---------------------------------------------------------------------------------------------
// Cube: 12 lines between 8 corners of valence 3, each line on one cube edge.

void expect_cube_features(const Positions& clean, const Positions& p, const Faces& f) {
  const std::vector<FeatureType> type = detect(p, f);
  const FeatureLines fl = link_feature_lines(p, f, type);
  expect_well_formed(f, type, fl);
  const double l = mean_edge_length(clean, f);
  const double tol = 1.0 * l;  // measured: the detected vertices are the cube-edge vertices exactly

  ASSERT_EQ(fl.corners.size(), 8u);
  std::set<int> octants;
  for (size_t c = 0; c < fl.corners.size(); ++c) {
    const Eigen::RowVector3d q = p.row(fl.corners[c]);
    EXPECT_LT((q.cwiseAbs().array() - 1.0).abs().maxCoeff(), tol) << "corner at " << q;
    octants.insert((q.x() > 0) + 2 * (q.y() > 0) + 4 * (q.z() > 0));
    EXPECT_EQ(fl.corner_valence[c], 3);
  }
  EXPECT_EQ(octants.size(), 8u) << "two corners found at one cube corner";

  ASSERT_EQ(fl.lines.size(), 12u);
  std::set<std::vector<int>> cube_edges;  // per line: the fixed axes and their signs
  for (size_t i = 0; i < fl.lines.size(); ++i) {
    const std::vector<int>& line = fl.lines[i];
    EXPECT_FALSE(fl.closed[i]);
    std::vector<int> fixed;  // axis * 2 + (side > 0) for each axis on which all vertices sit at +-1
    for (int k = 0; k < 3; ++k) {
      const double side = p(line[line.size() / 2], k) > 0 ? 1.0 : -1.0;
      bool all = true;
      for (int v : line) all = all && std::abs(p(v, k) - side) < tol;
      if (all) fixed.push_back(2 * k + (side > 0));
    }
    EXPECT_EQ(fixed.size(), line.size() > 2 ? 2u : 3u) << "line " << i << " leaves its cube edge";
    cube_edges.insert(fixed);
  }
  EXPECT_EQ(cube_edges.size(), 12u) << "two lines on one cube edge";

  // No feature inside a face: more than 2 edge lengths from every cube edge, on the clean cube.
  int inside = 0;
  for (Eigen::Index v = 0; v < clean.rows(); ++v) {
    Eigen::Vector3d a = clean.row(v).cwiseAbs().transpose();
    std::sort(a.data(), a.data() + 3);
    if (type[v] != FeatureType::None && 1.0 - a[1] > 2 * l) ++inside;
  }
  EXPECT_EQ(inside, 0);
}

TEST(SharpFeatures, CubeNoiseFreeHasTwelveEdgesAndEightCorners) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  expect_cube_features(m.positions, m.positions, m.faces);
  // every vertex on a cube edge is found: 8 corners + 12 edges of 15 inner vertices
  EXPECT_EQ(count_features(detect(m.positions, m.faces)), 188);
}

TEST(SharpFeatures, CubeWithTenPercentNoise) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    SCOPED_TRACE(seed);
    const Positions p = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Random, seed);
    expect_cube_features(m.positions, p, m.faces);
  }
}

TEST(SharpFeatures, CubeWithInconsistentOrientationGivesTheSameFeatures) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  Faces flipped = m.faces;
  for (Eigen::Index f = 0; f < flipped.rows(); f += 2) std::swap(flipped(f, 1), flipped(f, 2));
  EXPECT_EQ(detect(m.positions, flipped), detect(m.positions, m.faces));
}

// ---------------------------------------------------------------------------------------------
// Fandisk. Its true creases are known from the clean mesh: the edges whose two faces meet at
// some angle or more, and its true corners the vertices where three or more such edges meet.
// Creases of 30 degrees (the default threshold) must be found; detections must lie near
// creases of 20 degrees (which includes Fandisk's one weak crease of ~22 degrees), and corners
// near the 35 vertices where 20-degree creases meet. The detector is judged against these, not
// against counts of its own output: those once pinned two valence-4 corners that are
// artefacts (where long thin triangles span a narrow flat strip between creases, the filter
// blends the neighbouring planes into the strip and a short line cuts across it); today they
// are the two detected corners near no true corner.

struct TrueFeatures {
  std::vector<char> crease;   // per vertex: on a crease edge
  std::vector<char> corner;   // per vertex: three or more crease edges meet
  std::vector<int> corners;
};

TrueFeatures true_features(const test::ArrayMesh& m, double degrees) {
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (int f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.faces(f, k), b = m.faces(f, (k + 1) % 3);
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  auto normal = [&](int f) {
    const Eigen::RowVector3d a = m.positions.row(m.faces(f, 0));
    return Eigen::RowVector3d((m.positions.row(m.faces(f, 1)) - a).cross(m.positions.row(m.faces(f, 2)) - a).normalized());
  };
  TrueFeatures t{std::vector<char>(m.vertices(), 0), std::vector<char>(m.vertices(), 0), {}};
  std::vector<int> crease_edges(m.vertices(), 0);
  for (const auto& [edge, two] : faces_of_edge)
    if (two.size() == 2 && normal(two[0]).dot(normal(two[1])) < std::cos(degrees * M_PI / 180)) {
      t.crease[edge.first] = t.crease[edge.second] = 1;
      ++crease_edges[edge.first];
      ++crease_edges[edge.second];
    }
  for (int v = 0; v < m.vertices(); ++v)
    if (crease_edges[v] >= 3) {
      t.corner[v] = 1;
      t.corners.push_back(v);
    }
  return t;
}

// Detected corners near true corners, and true corners found: each within two edge lengths.
void expect_corners_near_the_true_ones(const test::ArrayMesh& m, const FeatureLines& fl, int spurious_allowed,
                                       int missed_allowed) {
  const TrueFeatures truth = true_features(m, 20.0);
  const double l = mean_edge_length(m.positions, m.faces);
  auto near_any = [&](int v, const std::vector<int>& set) {
    for (int w : set)
      if ((m.positions.row(v) - m.positions.row(w)).norm() < 2 * l) return true;
    return false;
  };
  int spurious = 0, missed = 0;
  for (int c : fl.corners) spurious += !near_any(c, truth.corners);
  for (int c : truth.corners) missed += !near_any(c, fl.corners);
  EXPECT_LE(spurious, spurious_allowed) << fl.corners.size() << " corners detected";
  EXPECT_LE(missed, missed_allowed) << truth.corners.size() << " true corners";
}

// Detected feature vertices within one ring of a true crease vertex, and true crease vertices
// with a detected one within one ring.
void expect_features_near_the_true_creases(const test::ArrayMesh& m, const std::vector<FeatureType>& type,
                                           double found_share, double kept_share) {
  const TrueFeatures strong = true_features(m, 30.0), weak = true_features(m, 20.0);
  std::vector<std::vector<int>> ring(m.vertices());
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) ring[m.faces(f, k)].push_back(m.faces(f, (k + 1) % 3));
  auto near = [&](auto&& is, int v) {
    if (is(v)) return true;
    for (int w : ring[v])
      if (is(w)) return true;
    return false;
  };
  auto detected = [&](int v) { return type[v] != FeatureType::None; };
  auto weak_crease = [&](int v) { return weak.crease[v] != 0; };
  int creases = 0, found = 0, kept = 0;
  for (int v = 0; v < m.vertices(); ++v) {
    if (strong.crease[v]) {
      ++creases;
      found += near(detected, v);
    }
    if (detected(v)) kept += near(weak_crease, v);
  }
  EXPECT_GE(found, found_share * creases) << found << " of " << creases << " true crease vertices found";
  EXPECT_GE(kept, kept_share * count_features(type)) << kept << " of " << count_features(type) << " detected near a crease";
}

TEST(SharpFeatures, FandiskNoiseFreeLinesAreOrderedPaths) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  const std::vector<FeatureType> type = detect(m.positions, m.faces);
  const FeatureLines fl = link_feature_lines(m.positions, m.faces, type);
  expect_well_formed(m.faces, type, fl);
  // measured: 2 spurious corners (the artefacts), none missed; 702 of 712 crease vertices
  // found, every detection within one ring of a crease
  expect_corners_near_the_true_ones(m, fl, 2, 0);
  expect_features_near_the_true_creases(m, type, 0.98, 0.99);

  // Lines follow creases: the faces of nearly every line edge meet at 10 degrees or more.
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (int f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.faces(f, k), b = m.faces(f, (k + 1) % 3);
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  auto normal = [&](int f) {
    const Eigen::RowVector3d a = m.positions.row(m.faces(f, 0));
    return Eigen::RowVector3d((m.positions.row(m.faces(f, 1)) - a).cross(m.positions.row(m.faces(f, 2)) - a).normalized());
  };
  int edges = 0, flat = 0;
  for (const auto& line : fl.lines)
    for (size_t i = 0; i + 1 < line.size(); ++i, ++edges) {
      const auto& two = faces_of_edge.at({std::min(line[i], line[i + 1]), std::max(line[i], line[i + 1])});
      flat += normal(two[0]).dot(normal(two[1])) > std::cos(10 * M_PI / 180);
    }
  EXPECT_LE(flat, 0.025 * edges) << flat << " of " << edges;  // measured 15 of 750
}

TEST(SharpFeatures, FandiskWithFivePercentNoise) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const Positions p = add_gaussian_noise(m.positions, m.faces, 5.0, NoiseDirection::Random, seed);
    const std::vector<FeatureType> type = detect(p, m.faces);
    const FeatureLines fl = link_feature_lines(p, m.faces, type);
    expect_well_formed(m.faces, type, fl);
    expect_corners_near_the_true_ones(m, fl, 2, 0);  // measured as noise-free
    expect_features_near_the_true_creases(m, type, 0.98, 0.99);  // measured 701-704 of 712, all
  }
}

// The hard case, 30% noise (raw face normals off by ~28 degrees on average), against the true
// creases and corners of the clean mesh.
TEST(SharpFeatures, FandiskWithThirtyPercentNoiseFindsTheTrueCreases) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const Positions p = add_gaussian_noise(m.positions, m.faces, 30.0, NoiseDirection::Random, seed);
    const std::vector<FeatureType> type = detect(p, m.faces);
    const FeatureLines fl = link_feature_lines(p, m.faces, type);
    expect_well_formed(m.faces, type, fl);
    // measured: 1-2 spurious and 0-3 missed corners, 692-701 of 712 crease vertices found,
    // every detection within one ring of a crease
    expect_corners_near_the_true_ones(m, fl, 2, 3);
    expect_features_near_the_true_creases(m, type, 0.96, 0.99);
  }
}

// The header's one-vertex-wide chains: a face whose three vertices are all features lies at a
// junction of lines (a corner among them), never inside a band along a crease. Without the
// thinning, anchor_dense has 4 such faces clean and 7-9 at 10%, the meshed cube 2 at 30%.
TEST(SharpFeatures, CreasesAreChainsOneVertexWide) {
  struct Case {
    const char* mesh;
    double level;
  };
  for (const Case& c : {Case{"anchor_dense", 0}, Case{"anchor_dense", 10}, Case{"cube-meshed", 30}}) {
    const test::ArrayMesh m = test::load_data_mesh(c.mesh);
    for (unsigned seed : {1u, 2u}) {
      SCOPED_TRACE(std::string(c.mesh) + " " + std::to_string(c.level) + "% seed " + std::to_string(seed));
      const Positions p = c.level > 0 ? add_gaussian_noise(m.positions, m.faces, c.level, NoiseDirection::Random, seed)
                                      : m.positions;
      const std::vector<FeatureType> type = detect(p, m.faces);
      int bands = 0;
      for (Eigen::Index f = 0; f < m.faces.rows(); ++f) {
        int features = 0, corners = 0;
        for (int k = 0; k < 3; ++k) {
          features += type[m.faces(f, k)] != FeatureType::None;
          corners += type[m.faces(f, k)] == FeatureType::Corner;
        }
        bands += features == 3 && corners == 0;
      }
      EXPECT_EQ(bands, 0);
    }
  }
}

TEST(SharpFeatures, ScaleAndTranslationDoNotChangeTheResult) {
  const test::ArrayMesh m = test::load_data_mesh("fandisk");
  Positions moved = (m.positions * 7.5).rowwise() + Eigen::RowVector3d(3, -2, 10);
  EXPECT_EQ(detect(moved, m.faces), detect(m.positions, m.faces));
}

// What the angle thresholds: the angle between the *filtered* normals of an edge's faces. The
// filter blunts moderate creases: on this grid a noise-free fold of 40 degrees comes out at
// 28.8 and is missed by the default 30, one of 45 at 36.9, 60 at 58.1, 90 at 90. Without
// filtering the threshold is exact.
TEST(SharpFeatures, FoldAngleAgainstTheThreshold) {
  auto fold_found = [](double degrees, int filter_iterations) {
    Grid g;
    for (int i = 0; i < Grid::n; ++i)
      for (int j = 0; j < Grid::n; ++j) g.mesh.positions(Grid::at(i, j), 2) = std::tan(degrees * M_PI / 360) * std::abs(i - 5);
    SharpFeatureOptions o;
    o.filter_iterations = filter_iterations;
    const std::vector<FeatureType> type = detect(g.mesh.positions, g.mesh.faces, o);
    int on_fold = 0, elsewhere = 0;  // inner vertices; the mesh boundary is always a feature
    for (int i = 1; i + 1 < Grid::n; ++i)
      for (int j = 1; j + 1 < Grid::n; ++j) (i == 5 ? on_fold : elsewhere) += type[Grid::at(i, j)] != FeatureType::None;
    EXPECT_EQ(elsewhere, 0) << degrees << " degrees";
    for (int k = 0; k < Grid::n; ++k)  // thinning never removes boundary vertices, ears included
      for (int v : {Grid::at(0, k), Grid::at(Grid::n - 1, k), Grid::at(k, 0), Grid::at(k, Grid::n - 1)})
        EXPECT_NE(type[v], FeatureType::None) << "boundary vertex " << v;
    return on_fold == Grid::n - 2 ? 1 : on_fold == 0 ? 0 : -1;
  };
  EXPECT_EQ(fold_found(25, 0), 0);
  EXPECT_EQ(fold_found(35, 0), 1);
  EXPECT_EQ(fold_found(40, 4), 0);
  EXPECT_EQ(fold_found(45, 4), 1);
  EXPECT_EQ(fold_found(90, 4), 1);
}

// Neighbour support, on raw normals (no filter: exact angles). A 90 degree fold along row 5
// with a 27 degree crease (weak: between 0.8 and 1 times the threshold) above it: continuing
// the fold the weak crease is taken, branching off at a right angle it is not.
TEST(SharpFeatures, SupportContinuesACreaseButDoesNotBranch) {
  SharpFeatureOptions raw;
  raw.filter_iterations = 0;
  const double weak = std::tan(27.0 * M_PI / 360);
  {  // the fold turns weak halfway along row 5
    Grid g;
    for (int i = 0; i < Grid::n; ++i)
      for (int j = 0; j < Grid::n; ++j)
        g.mesh.positions(Grid::at(i, j), 2) = (j < 6 ? 1.0 : weak) * std::abs(i - 5);
    const std::vector<FeatureType> type = detect(g.mesh.positions, g.mesh.faces, raw);
    for (int j = 1; j + 1 < Grid::n; ++j) EXPECT_NE(type[Grid::at(5, j)], FeatureType::None) << j;
    raw.support_ratio = 1;  // no support: the weak half is lost
    const std::vector<FeatureType> unsupported = detect(g.mesh.positions, g.mesh.faces, raw);
    EXPECT_EQ(unsupported[Grid::at(5, 9)], FeatureType::None);
    raw.support_ratio = SharpFeatureOptions{}.support_ratio;
  }
  {  // a weak crease along column 6 branches off the fold
    Grid g;
    const double b = std::sqrt(2 * (1 - std::cos(27.0 * M_PI / 180)) / (1 + std::cos(27.0 * M_PI / 180)));
    for (int i = 0; i < Grid::n; ++i)
      for (int j = 0; j < Grid::n; ++j)
        g.mesh.positions(Grid::at(i, j), 2) = std::abs(i - 5) + (i > 5 ? b * std::abs(j - 6) : 0.0);
    const std::vector<FeatureType> type = detect(g.mesh.positions, g.mesh.faces, raw);
    for (int j = 1; j + 1 < Grid::n; ++j) EXPECT_NE(type[Grid::at(5, j)], FeatureType::None) << j;
    for (int i = 6; i + 1 < Grid::n; ++i) EXPECT_EQ(type[Grid::at(i, 6)], FeatureType::None) << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Smooth surfaces: measured no feature vertex at all over 40 seeds (the filtered normals of
// neighbouring faces differ by at most ~5 degrees on the sphere, ~28 on the coarse torus,
// whose rings are 11 degrees apart). Allowed: 0.5% of the vertices.

TEST(SharpFeatures, SmoothSphereAndTorusWithTenPercentNoiseHaveNoFeatures) {
  for (const test::ArrayMesh& m : {test::sphere(4), test::torus(3, 1, 64, 32)}) {
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
      SCOPED_TRACE(seed);
      const Positions p = add_gaussian_noise(m.positions, m.faces, 10.0, NoiseDirection::Random, seed);
      const std::vector<FeatureType> type = detect(p, m.faces);
      EXPECT_LE(count_features(type), 0.005 * m.vertices()) << m.vertices() << " vertices";
      EXPECT_TRUE(link_feature_lines(p, m.faces, type).corners.empty());
    }
  }
}

// Scattered detections on a torus with 20% noise (twice the noise the test above uses) are
// mostly groups of a few vertices: measured 110 feature vertices over five seeds with the
// default min_feature_vertices = 5, against 362 when no group is dropped.
TEST(SharpFeatures, SmallGroupsAreDropped) {
  const test::ArrayMesh m = test::torus(3, 1, 64, 32);
  SharpFeatureOptions keep_all;
  keep_all.min_feature_vertices = 1;
  int kept = 0, all = 0;
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    const Positions p = add_gaussian_noise(m.positions, m.faces, 20.0, NoiseDirection::Random, seed);
    kept += count_features(detect(p, m.faces));
    all += count_features(detect(p, m.faces, keep_all));
  }
  EXPECT_GT(all, 0);
  EXPECT_LT(kept, all / 2);
}

TEST(SharpFeatures, MeshBoundaryLoopsBecomeClosedLines) {
  const test::ArrayMesh m = test::remove_faces(test::sphere(4), 300);
  CornerTable table;
  int inconsistent = 0;
  std::string error;
  ASSERT_TRUE(build_corner_table(m.faces, m.vertices(), table, inconsistent, error)) << error;
  const auto loops = boundary_loops(table);
  ASSERT_GE(loops.size(), 5u);
  const std::vector<FeatureType> type = detect(m.positions, m.faces);
  const FeatureLines fl = link_feature_lines(m.positions, m.faces, type);
  expect_well_formed(m.faces, type, fl);
  ASSERT_EQ(fl.lines.size(), loops.size());
  std::set<std::set<int>> lines, holes;
  for (size_t l = 0; l < fl.lines.size(); ++l) {
    EXPECT_TRUE(fl.closed[l]);
    lines.insert(std::set<int>(fl.lines[l].begin(), fl.lines[l].end()));
  }
  for (const auto& loop : loops) holes.insert(std::set<int>(loop.begin(), loop.end()));
  EXPECT_EQ(lines, holes);
}

TEST(SharpFeatures, BadInputFailsWithAMessage) {
  const test::ArrayMesh m = test::load_data_mesh("cube-meshed");
  std::vector<FeatureType> type;
  std::string error;
  EXPECT_FALSE(detect_sharp_features(m.positions, Faces(0, 3), {}, type, error));
  EXPECT_NE(error.find("no faces"), std::string::npos) << error;

  Positions nan = m.positions;
  nan(5, 1) = std::numeric_limits<double>::quiet_NaN();
  error.clear();
  EXPECT_FALSE(detect_sharp_features(nan, m.faces, {}, type, error));
  EXPECT_NE(error.find("NaN"), std::string::npos) << error;

  Faces out_of_range = m.faces;
  out_of_range(3, 2) = m.vertices();
  error.clear();
  EXPECT_FALSE(detect_sharp_features(m.positions, out_of_range, {}, type, error));
  EXPECT_FALSE(error.empty());

  Faces fin = m.faces;  // a third face on the edge of face 0
  fin.conservativeResize(fin.rows() + 1, 3);
  Positions with_tip(m.vertices() + 1, 3);
  with_tip << m.positions, Eigen::RowVector3d(3, 3, 3);
  fin.row(fin.rows() - 1) << m.faces(0, 0), m.faces(0, 1), m.vertices();
  error.clear();
  EXPECT_FALSE(detect_sharp_features(with_tip, fin, {}, type, error));
  EXPECT_NE(error.find("non-manifold"), std::string::npos) << error;

  SharpFeatureOptions flat;
  flat.angle_degrees = 0;
  error.clear();
  EXPECT_FALSE(detect_sharp_features(m.positions, m.faces, flat, type, error));
  EXPECT_FALSE(error.empty());
}

// ---------------------------------------------------------------------------------------------
// Linking on its own, from hand-made types on the grid.

TEST(SharpFeatureLines, StraightRowIsOneOrderedLineWithFreeEnds) {
  Grid g;
  for (int j = 1; j < 11; ++j) g.mark(5, j);
  const FeatureLines fl = g.link();
  ASSERT_EQ(fl.lines.size(), 1u);
  EXPECT_FALSE(fl.closed[0]);
  EXPECT_TRUE(fl.corners.empty());
  std::vector<int> expected;
  for (int j = 1; j < 11; ++j) expected.push_back(Grid::at(5, j));
  if (fl.lines[0].front() != expected.front()) std::reverse(expected.begin(), expected.end());
  EXPECT_EQ(fl.lines[0], expected);
}

TEST(SharpFeatureLines, CrossingMakesACornerOfValenceFour) {
  Grid g;
  for (int k = 1; k < 11; ++k) {
    g.mark(5, k);
    g.mark(k, 7);
  }
  const FeatureLines fl = g.link();
  expect_well_formed(g.mesh.faces, [&] {
    std::vector<FeatureType> t = g.type;
    t[Grid::at(5, 7)] = FeatureType::Corner;
    return t;
  }(), fl);
  ASSERT_EQ(fl.corners, std::vector<int>{Grid::at(5, 7)});
  EXPECT_EQ(fl.corner_valence[0], 4);
  EXPECT_EQ(fl.lines.size(), 4u);
}

TEST(SharpFeatureLines, BumpsBesideALineBecomeSpursAndAreDropped) {
  Grid g;
  for (int j = 1; j < 11; ++j) g.mark(5, j);
  g.mark(6, 3);  // shares a face with (5, 2) and (5, 3)
  g.mark(4, 7);  // shares a face with (5, 7) and (5, 8)
  g.mark(6, 9);  // shares a face with (5, 8) and (5, 9)
  const FeatureLines fl = g.link();
  ASSERT_EQ(fl.lines.size(), 1u);
  EXPECT_TRUE(fl.corners.empty());
  EXPECT_EQ(fl.lines[0].size(), 10u);  // straight along the row: no detour, no short cut
  for (int v : {Grid::at(6, 3), Grid::at(4, 7), Grid::at(6, 9)}) EXPECT_EQ(fl.line_of_vertex[v], -1);

  // Keeping every line shows the spurs: one at (5, 3), two at (5, 8), which carries both
  // bumps' faces.
  const FeatureLines all = g.link(1);
  EXPECT_EQ(all.lines.size(), 6u);
  EXPECT_EQ(all.corners, (std::vector<int>{Grid::at(5, 3), Grid::at(5, 8)}));
  EXPECT_EQ(all.corner_valence, (std::vector<int>{3, 4}));
}

TEST(SharpFeatureLines, TypedCornerSplitsALineAndLoopsAreClosed) {
  Grid g;
  for (int j = 1; j < 11; ++j) g.mark(2, j);
  g.mark(2, 5, FeatureType::Corner);
  for (int k = 6; k < 10; ++k) {  // a square ring, rows 6 and 9, columns 6 and 9: its turns at
                                  // (6, 9) and (9, 6) face a diagonal edge, which is not taken
    g.mark(6, k);
    g.mark(9, k);
    g.mark(k, 6);
    g.mark(k, 9);
  }
  const FeatureLines fl = g.link();
  ASSERT_EQ(fl.lines.size(), 3u);
  ASSERT_EQ(fl.corners, std::vector<int>{Grid::at(2, 5)});
  EXPECT_EQ(fl.corner_valence[0], 2);
  EXPECT_EQ(std::count(fl.closed.begin(), fl.closed.end(), 1), 1);
  for (size_t l = 0; l < fl.lines.size(); ++l) {
    if (fl.closed[l]) {
      EXPECT_EQ(fl.lines[l].size(), 12u);
    }
  }
  expect_well_formed(g.mesh.faces, g.type, fl);
  // Asking for 13 vertices drops the ring too (the row's halves have free ends); the typed
  // corner stays, on no line.
  const FeatureLines none = g.link(13);
  EXPECT_TRUE(none.lines.empty());
  EXPECT_EQ(none.corner_valence, std::vector<int>{0});
}

TEST(SharpFeatureLines, CreaseMeetsTheMeshBoundaryWithoutShortCuttingIt) {
  Grid g;
  for (int k = 0; k < Grid::n; ++k) {  // the grid's boundary loop
    g.mark(0, k);
    g.mark(Grid::n - 1, k);
    g.mark(k, 0);
    g.mark(k, Grid::n - 1);
  }
  for (int i = 1; i < 5; ++i) g.mark(i, 5);  // a crease ending on the boundary row 0
  // (1, 5) pulled close to the boundary: the boundary edge (0, 4)-(0, 5) becomes the longest
  // of their face, which a crease must still not cut.
  g.mesh.positions.row(Grid::at(1, 5)) << 4.5, 0.3, 0;
  const FeatureLines fl = g.link();
  ASSERT_EQ(fl.corners.size(), 1u);
  EXPECT_TRUE(fl.corners[0] == Grid::at(0, 4) || fl.corners[0] == Grid::at(0, 5));
  EXPECT_EQ(fl.corner_valence[0], 3);
  ASSERT_EQ(fl.lines.size(), 2u);  // the boundary, from the corner round to it, and the crease
  std::set<std::pair<int, int>> followed;
  for (const auto& line : fl.lines)
    for (size_t i = 0; i + 1 < line.size(); ++i) followed.insert({std::min(line[i], line[i + 1]), std::max(line[i], line[i + 1])});
  for (int k = 0; k + 1 < Grid::n; ++k)
    for (auto [a, b] : {std::pair{Grid::at(0, k), Grid::at(0, k + 1)}, std::pair{Grid::at(k, 0), Grid::at(k + 1, 0)},
                        std::pair{Grid::at(Grid::n - 1, k), Grid::at(Grid::n - 1, k + 1)},
                        std::pair{Grid::at(k, Grid::n - 1), Grid::at(k + 1, Grid::n - 1)}})
      EXPECT_TRUE(followed.count({a, b})) << a << "-" << b << " not followed";
}

TEST(SharpFeatureLines, MismatchedInputGivesNothing) {
  Grid g;
  g.type.pop_back();
  EXPECT_TRUE(g.link().lines.empty());
}

}  // namespace
}  // namespace hht
