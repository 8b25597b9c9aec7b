#include "filters/sd_normal_denoise.h"

#include "mesh/corner_table.h"
#include "mesh/face_geometry.h"
#include "mesh/face_rings.h"
#include "mesh/mesh_checks.h"
#include "reconstruction/closeness_vertex_update.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

namespace hht {

namespace {

struct Connectivity {
  Faces faces;                                 // coherently oriented copy of the input
  std::vector<unsigned char> flipped;          // 1: the copy's face winds against the input's
  std::vector<std::array<int, 2>> edge_faces;  // the edges shared by two faces
  std::vector<std::array<int, 3>> face_edges;  // per face, its edges' indices there (-1 on the boundary)
  IndexLists vertex_edges;                     // per vertex, its edges shared by two faces
  IndexLists vertex_faces;
  IndexLists rings;  // per face, the faces sharing a vertex with it (itself included, sorted)
};

bool same_winding(const Faces& a, const Faces& b, Eigen::Index f) {
  for (int r = 0; r < 3; ++r)
    if (a(f, 0) == b(f, r) && a(f, 1) == b(f, (r + 1) % 3) && a(f, 2) == b(f, (r + 2) % 3)) return true;
  return false;
}

bool build_connectivity(const Positions& positions, const Faces& faces, Connectivity& c, std::string& error) {
  if (!check_triangle_mesh(positions, faces, error)) return false;
  const int n = static_cast<int>(positions.rows());
  c.faces = faces;
  CornerTable table;
  int inconsistent = 0;
  if (!build_corner_table(c.faces, n, table, inconsistent, error)) return false;
  if (inconsistent > 0) {  // neighbouring normals must be comparable
    if (!orient_faces_coherently(c.faces, table, error)) return false;
    if (!build_corner_table(c.faces, n, table, inconsistent, error)) return false;
  }
  const int m = static_cast<int>(faces.rows());
  c.flipped.assign(m, 0);
  for (int f = 0; f < m; ++f) c.flipped[f] = !same_winding(c.faces, faces, f);
  c.face_edges.assign(m, {-1, -1, -1});
  std::vector<std::array<int, 2>> edge_vertices;
  for (int k = 0; k < table.corners(); ++k) {
    const int o = table.opposite[k];
    if (o < 0 || o < k) continue;
    const int e = static_cast<int>(c.edge_faces.size());
    c.edge_faces.push_back({k / 3, o / 3});
    edge_vertices.push_back({table.vertex[corner_next(k)], table.vertex[corner_prev(k)]});
    c.face_edges[k / 3][k % 3] = e;
    c.face_edges[o / 3][o % 3] = e;
  }
  if (c.edge_faces.empty()) {
    error = "no two faces share an edge: the SD filter needs neighbouring faces";
    return false;
  }
  c.vertex_edges.start.assign(n + 1, 0);
  for (const auto& ev : edge_vertices)
    for (int v : ev) ++c.vertex_edges.start[v + 1];
  std::partial_sum(c.vertex_edges.start.begin(), c.vertex_edges.start.end(), c.vertex_edges.start.begin());
  std::vector<int> fill(c.vertex_edges.start.begin(), c.vertex_edges.start.end() - 1);
  c.vertex_edges.items.resize(c.vertex_edges.start.back());
  for (size_t e = 0; e < edge_vertices.size(); ++e)
    for (int v : edge_vertices[e]) c.vertex_edges.items[fill[v]++] = static_cast<int>(e);
  c.vertex_faces = vertex_faces(c.faces, n);
  c.rings = face_rings(c.faces, n);
  return true;
}

bool check_options(const SdNormalDenoiseOptions& o, std::string& error) {
  if (!(o.lambda > 0 && o.eta > 0 && o.mu > 0 && o.nu > 0 && o.closeness_weight > 0 && o.stop_angle_degrees >= 0) ||
      o.outer_iterations < 0 || o.filter_iterations < 1 || o.vertex_iterations < 0) {
    error = "lambda, eta, mu, nu and the closeness weight must be positive, the stop angle at least 0, "
            "the filter iterations at least 1 and the outer and vertex iterations at least 0";
    return false;
  }
  return true;
}

// The faces' geometry with their areas over the mean (the authors' area weights).
bool face_geometry_with_unit_mean_area(const Positions& p, const Faces& faces, FaceGeometry& g, std::string& error) {
  g = face_geometry(p, faces);
  const double mean = g.areas.mean();
  if (!(mean > 0)) {
    error = "all faces are degenerate (zero area)";
    return false;
  }
  g.areas /= mean;
  return true;
}

Eigen::RowVector3d unit_or_zero(const Eigen::RowVector3d& v) {
  const double len = v.norm();
  return len > 0 ? Eigen::RowVector3d(v / len) : Eigen::RowVector3d::Zero();
}

// The static guidance, as the authors' denoiser builds it (after guided normal filtering): each
// face takes the area-weighted mean normal of the most consistent patch among those centred on
// the faces of its ring. A patch (a face's ring) scores its largest normal difference times its
// largest edge saliency |n_a - n_b| over their sum, on its edges at the centre face's vertices:
// a patch on one side of a crease beats one straddling it.
Positions patch_guidance(const Connectivity& c, const FaceGeometry& g) {
  const int m = static_cast<int>(c.faces.rows());
  const int n = static_cast<int>(c.vertex_edges.start.size()) - 1;
  std::vector<double> saliency(c.edge_faces.size());
  for (size_t e = 0; e < saliency.size(); ++e)
    saliency[e] = (g.normals.row(c.edge_faces[e][0]) - g.normals.row(c.edge_faces[e][1])).norm();
  std::vector<double> vertex_largest(n, 0.0), vertex_sum(n, 0.0);
  for (int v = 0; v < n; ++v)
    for (int i = c.vertex_edges.begin(v); i < c.vertex_edges.end(v); ++i) {
      vertex_largest[v] = std::max(vertex_largest[v], saliency[c.vertex_edges.items[i]]);
      vertex_sum[v] += saliency[c.vertex_edges.items[i]];
    }
  std::vector<double> score(m);
  Positions mean(m, 3), guide(m, 3);
  parallel_for(0, m, [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      const int* ring = c.rings.items.data() + c.rings.begin(j);
      const int size = c.rings.end(j) - c.rings.begin(j);
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      double spread = 0;
      for (int a = 0; a < size; ++a) {
        sum += g.areas[ring[a]] * g.normals.row(ring[a]);
        for (int b = a + 1; b < size; ++b)
          spread = std::max(spread, (g.normals.row(ring[a]) - g.normals.row(ring[b])).squaredNorm());
      }
      double largest = 0, total = 0;
      for (int k = 0; k < 3; ++k) {
        const int v = c.faces(j, k);
        largest = std::max(largest, vertex_largest[v]);
        total += vertex_sum[v];
        // the face's own edges are met at both their ends: counted once
        if (c.face_edges[j][k] >= 0) total -= saliency[c.face_edges[j][k]];
      }
      score[j] = std::sqrt(spread) * largest / (1e-9 + total);
      mean.row(j) = unit_or_zero(sum);
    }
  });
  for (int f = 0; f < m; ++f) {
    int best = c.rings.items[c.rings.begin(f)];
    for (int i = c.rings.begin(f); i < c.rings.end(f); ++i)
      if (score[c.rings.items[i]] < score[best]) best = c.rings.items[i];
    guide.row(f) = mean.row(best);
  }
  return guide;
}

// Each face's neighbours: the faces whose centroids lie within `radius` of its own, reached by a
// breadth-first search through faces sharing a vertex that stays inside that ball.
std::vector<std::vector<int>> ball_neighbours(const Connectivity& c, const Positions& centroids, double radius) {
  const int m = static_cast<int>(c.faces.rows());
  const int n = static_cast<int>(c.vertex_faces.start.size()) - 1;
  std::vector<std::vector<int>> near(m);
  parallel_for(0, m, [&](int first, int last) {
    std::vector<int> face_seen(m, -1), vertex_seen(n, -1), queue;
    for (int i = first; i < last; ++i) {
      face_seen[i] = i;
      queue.assign(1, i);
      for (size_t q = 0; q < queue.size(); ++q)
        for (int k = 0; k < 3; ++k) {
          const int v = c.faces(queue[q], k);
          if (vertex_seen[v] == i) continue;
          vertex_seen[v] = i;
          for (int a = c.vertex_faces.begin(v); a < c.vertex_faces.end(v); ++a) {
            const int f = c.vertex_faces.items[a];
            if (face_seen[f] == i) continue;
            face_seen[f] = i;
            if ((centroids.row(f) - centroids.row(i)).norm() < radius) {
              queue.push_back(f);
              near[i].push_back(f);
            }
          }
        }
      std::sort(near[i].begin(), near[i].end());
    }
  }, 256);
  return near;
}

// The pairs of faces that are each other's neighbours, and per face its pairs.
struct Pairs {
  std::vector<std::array<int, 2>> faces;
  std::vector<double> distance;
  IndexLists of_face;  // items: pair indices
};

Pairs neighbour_pairs(const Connectivity& c, const Positions& centroids, double radius) {
  const std::vector<std::vector<int>> near = ball_neighbours(c, centroids, radius);
  const int m = static_cast<int>(near.size());
  Pairs p;
  for (int i = 0; i < m; ++i)
    for (int j : near[i])
      if (j > i && std::binary_search(near[j].begin(), near[j].end(), i)) {
        p.faces.push_back({i, j});
        p.distance.push_back((centroids.row(i) - centroids.row(j)).norm());
      }
  p.of_face.start.assign(m + 1, 0);
  for (const auto& ij : p.faces) {
    ++p.of_face.start[ij[0] + 1];
    ++p.of_face.start[ij[1] + 1];
  }
  std::partial_sum(p.of_face.start.begin(), p.of_face.start.end(), p.of_face.start.begin());
  std::vector<int> fill(p.of_face.start.begin(), p.of_face.start.end() - 1);
  p.of_face.items.resize(p.of_face.start.back());
  for (size_t k = 0; k < p.faces.size(); ++k)
    for (int f : p.faces[k]) p.of_face.items[fill[f]++] = static_cast<int>(k);
  return p;
}

bool filter_normals(const Connectivity& c, const Positions& positions, const SdNormalDenoiseOptions& o,
                    Positions& normals, std::string& error) {
  FaceGeometry g;
  if (!face_geometry_with_unit_mean_area(positions, c.faces, g, error)) return false;
  double spacing = 0;
  for (const auto& ef : c.edge_faces) spacing += (g.centroids.row(ef[0]) - g.centroids.row(ef[1])).norm();
  spacing /= static_cast<double>(c.edge_faces.size());
  const double eta = o.eta * spacing;
  const Pairs pairs = neighbour_pairs(c, g.centroids, 3 * eta);
  if (pairs.faces.empty() || !(eta > 0)) {
    error = "no face has a neighbour within the filter's radius (all centroids in one point?)";
    return false;
  }
  const Positions guide = patch_guidance(c, g);

  // The static part of each pair's weight, and lambda rescaled so that the penalty and the
  // fidelity weigh alike whatever the neighbourhood's size (as the authors do).
  const size_t np = pairs.faces.size();
  std::vector<double> fixed_weight(np);
  double spatial_sum = 0;
  for (size_t k = 0; k < np; ++k) {
    const int i = pairs.faces[k][0], j = pairs.faces[k][1];
    const double d = pairs.distance[k];
    const double spatial = (g.areas[i] + g.areas[j]) * std::exp(-d * d / (2 * eta * eta));
    spatial_sum += spatial;
    fixed_weight[k] = spatial * std::exp(-(guide.row(i) - guide.row(j)).squaredNorm() / (2 * o.mu * o.mu));
  }
  const double lambda = o.lambda * g.areas.sum() / spatial_sum;

  const int m = static_cast<int>(c.faces.rows());
  const Positions fidelity = (g.areas * (2 * o.nu * o.nu / lambda)).asDiagonal() * g.normals;
  const double eps = 2 * std::sin(0.5 * o.stop_angle_degrees * M_PI / 180);
  const double stop = g.areas.sum() * eps * eps;
  Positions current = g.normals, next(m, 3);
  std::vector<double> weight(np);
  for (int it = 0; it < o.filter_iterations; ++it) {
    parallel_for(0, static_cast<int>(np), [&](int first, int last) {
      for (int k = first; k < last; ++k)
        weight[k] = fixed_weight[k] * std::exp(-(current.row(pairs.faces[k][0]) - current.row(pairs.faces[k][1])).squaredNorm() /
                                               (2 * o.nu * o.nu));
    });
    parallel_for(0, m, [&](int first, int last) {
      for (int i = first; i < last; ++i) {
        Eigen::RowVector3d sum = fidelity.row(i);
        for (int a = pairs.of_face.begin(i); a < pairs.of_face.end(i); ++a) {
          const int k = pairs.of_face.items[a];
          const int j = pairs.faces[k][0] == i ? pairs.faces[k][1] : pairs.faces[k][0];
          sum += weight[k] * current.row(j);
        }
        next.row(i) = unit_or_zero(sum);
      }
    });
    const double change = g.areas.dot((next - current).rowwise().squaredNorm());
    current.swap(next);
    if (change <= stop) break;
  }
  normals = current;
  return true;
}

}  // namespace

bool sd_filter_face_normals(const Positions& positions, const Faces& faces, const SdNormalDenoiseOptions& options,
                            Positions& normals, std::string& error) {
  Connectivity c;
  if (!check_options(options, error) || !build_connectivity(positions, faces, c, error)) return false;
  Positions filtered;
  if (!filter_normals(c, positions, options, filtered, error)) return false;
  for (Eigen::Index f = 0; f < filtered.rows(); ++f)
    if (c.flipped[f]) filtered.row(f) *= -1;  // back to the input's winding
  normals.swap(filtered);
  return true;
}

bool sd_normal_denoise(const Positions& positions, const Faces& faces, const SdNormalDenoiseOptions& options,
                       Positions& result, std::string& error, const std::function<void(double)>& progress) {
  Connectivity c;
  if (!check_options(options, error) || !build_connectivity(positions, faces, c, error)) return false;
  Positions current = positions, normals;
  for (int outer = 0; outer < options.outer_iterations; ++outer) {
    if (!filter_normals(c, current, options, normals, error)) return false;
    if (!fit_vertices_to_normals_with_closeness(current, c.faces, normals, options.closeness_weight,
                                                options.vertex_iterations, current, error))
      return false;
    if (progress) progress((outer + 1.0) / options.outer_iterations);
  }
  if (!current.allFinite()) {
    error = "the vertex update produced non-finite positions";
    return false;
  }
  result.swap(current);
  return true;
}

}  // namespace hht
