#include "mesh/sharp_features.h"

#include "mesh/corner_table.h"
#include "mesh/face_geometry.h"
#include "cycle/feature_lines.h"
#include "mesh/face_rings.h"
#include "mesh/mesh_checks.h"
#include "util/parallel_for.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace hht {

namespace {

// Builds lists from (list, item) pairs by a counting sort: linear time.
template <class Pairs>
IndexLists make_lists(int count, const Pairs& for_each_pair) {
  IndexLists l;
  l.start.assign(count + 1, 0);
  for_each_pair([&](int list, int) { ++l.start[list + 1]; });
  std::partial_sum(l.start.begin(), l.start.end(), l.start.begin());
  std::vector<int> fill(l.start.begin(), l.start.end() - 1);
  l.items.resize(l.start.back());
  for_each_pair([&](int list, int item) { l.items[fill[list]++] = item; });
  return l;
}

struct Topology {
  Faces faces;                           // coherently oriented copy of the input
  std::vector<std::array<int, 2>> edge_vertices;
  std::vector<std::array<int, 2>> edge_faces;  // second face -1 on the mesh boundary
  std::vector<int> corner_edge;          // per corner (3 f + k): the edge opposite it
  IndexLists vertex_faces, vertex_edges;
  IndexLists face_faces;                      // faces sharing a vertex with the face, itself included
};

bool build_topology(const Faces& faces, int vertex_count, Topology& topo, std::string& error) {
  topo.faces = faces;
  CornerTable table;
  int inconsistent = 0;
  if (!build_corner_table(topo.faces, vertex_count, table, inconsistent, error)) return false;
  if (inconsistent > 0) {
    // Dihedral angles need neighbouring normals on the same side of the surface.
    if (!orient_faces_coherently(topo.faces, table, error)) return false;
    if (!build_corner_table(topo.faces, vertex_count, table, inconsistent, error)) return false;
  }
  topo.corner_edge.assign(table.corners(), -1);
  for (int c = 0; c < table.corners(); ++c) {
    const int o = table.opposite[c];
    if (o >= 0 && o < c) continue;
    topo.corner_edge[c] = static_cast<int>(topo.edge_vertices.size());
    if (o >= 0) topo.corner_edge[o] = topo.corner_edge[c];
    topo.edge_vertices.push_back({table.vertex[corner_next(c)], table.vertex[corner_prev(c)]});
    topo.edge_faces.push_back({c / 3, o >= 0 ? o / 3 : -1});
  }
  const int ne = static_cast<int>(topo.edge_vertices.size());
  topo.vertex_faces = vertex_faces(topo.faces, vertex_count);
  topo.vertex_edges = make_lists(vertex_count, [&](auto&& add) {
    for (int e = 0; e < ne; ++e)
      for (int v : topo.edge_vertices[e]) add(v, e);
  });
  topo.face_faces = face_rings(topo.faces, vertex_count);
  return true;
}

// Guidance of each face (Zhang, Deng, Zhang, Bouaziz, Liu 2015): the mean normal of the most
// consistent patch (patch = a face and the faces sharing a vertex with it) that contains it.
// Consistency is the patch's largest normal deviation times the share of its largest edge
// saliency |n_a - n_b|: a patch lying on one side of a crease wins over one straddling it.
Positions guidance(const Topology& topo, const FaceGeometry& g, const Positions& n) {
  const int nf = static_cast<int>(topo.faces.rows());
  const int ne = static_cast<int>(topo.edge_faces.size());
  std::vector<double> saliency(ne), consistency(nf);
  Positions mean(nf, 3), guide(nf, 3);
  for (int e = 0; e < ne; ++e) {
    const auto& ef = topo.edge_faces[e];
    saliency[e] = ef[1] >= 0 ? (n.row(ef[0]) - n.row(ef[1])).norm() : 0.0;
  }
  // The patch's edges are those at the face's three vertices: per vertex, the largest and the
  // sum of its edges' saliencies; the face's own edges, met at both their ends, are taken once.
  const int nv = static_cast<int>(topo.vertex_edges.start.size()) - 1;
  std::vector<double> vertex_largest(nv, 0.0), vertex_sum(nv, 0.0);
  parallel_for(0, nv, [&](int first, int last) {
    for (int v = first; v < last; ++v)
      for (int i = topo.vertex_edges.begin(v); i < topo.vertex_edges.end(v); ++i) {
        vertex_largest[v] = std::max(vertex_largest[v], saliency[topo.vertex_edges.items[i]]);
        vertex_sum[v] += saliency[topo.vertex_edges.items[i]];
      }
  });
  parallel_for(0, nf, [&](int first, int last) {
    for (int j = first; j < last; ++j) {
      Eigen::RowVector3d m = Eigen::RowVector3d::Zero();
      for (int i = topo.face_faces.begin(j); i < topo.face_faces.end(j); ++i) {
        const int k = topo.face_faces.items[i];
        m += g.areas[k] * n.row(k);
      }
      const double len = m.norm();
      if (len > 0) m /= len;
      double deviation = 0;
      for (int i = topo.face_faces.begin(j); i < topo.face_faces.end(j); ++i)
        deviation = std::max(deviation, (n.row(topo.face_faces.items[i]) - m).squaredNorm());
      double largest = 0, sum = 0;
      for (int k = 0; k < 3; ++k) {
        const int v = topo.faces(j, k);
        largest = std::max(largest, vertex_largest[v]);
        sum += vertex_sum[v] - saliency[topo.corner_edge[3 * j + k]];
      }
      mean.row(j) = m;
      consistency[j] = std::sqrt(deviation) * largest / (1e-9 + sum);
    }
  });
  parallel_for(0, nf, [&](int first, int last) {
    for (int f = first; f < last; ++f) {
      int best = f;
      for (int i = topo.face_faces.begin(f); i < topo.face_faces.end(f); ++i) {
        const int j = topo.face_faces.items[i];
        if (consistency[j] < consistency[best]) best = j;
      }
      guide.row(f) = mean.row(best);
    }
  });
  return guide;
}

// Guided normal filtering: each pass, a joint bilateral filter over the faces sharing a vertex
// with each face, weighted by area, centroid distance and the difference of the guidance
// normals, so faces on the two sides of a crease barely mix.
// With own_normals the range kernel compares the filtered normals themselves over the faces
// around, the face left out: bilateral normal filtering (Zheng et al. 2011, local scheme).
Positions filter_normals(const Topology& topo, const FaceGeometry& g, int iterations, double sigma_r,
                         const std::vector<double>& face_sigma_r = {}, bool own_normals = false) {
  const int nf = static_cast<int>(topo.faces.rows());
  double spacing = 0;
  int interior = 0;
  for (const auto& ef : topo.edge_faces)
    if (ef[1] >= 0) {
      spacing += (g.centroids.row(ef[0]) - g.centroids.row(ef[1])).norm();
      ++interior;
    }
  const double sigma_s = interior > 0 ? spacing / interior : 1.0;
  const double inv_s = 1.0 / (2 * sigma_s * sigma_s), inv_r = 1.0 / (2 * sigma_r * sigma_r);
  // A face's own range width, where given (each face weighs its neighbours with its own kernel).
  std::vector<double> face_inv_r;
  for (double w : face_sigma_r) face_inv_r.push_back(1.0 / (2 * w * w));
  // The weights are held in float: areas in units of a power of two near their mean, so that
  // coordinates of 1e30 (areas of 1e60) or 1e-20 neither overflow nor vanish, and, a power of
  // two scaling exactly, the filtered normals of an ordinary mesh are unchanged to the bit.
  const double mean_area = nf > 0 ? g.areas.sum() / nf : 0.0;
  const double area_unit = mean_area > 0 && std::isfinite(mean_area) ? std::ldexp(1.0, -std::ilogb(mean_area)) : 1.0;
  // area times spatial kernel, per (face, neighbour) pair: fixed over the iterations
  std::vector<float> spatial(topo.face_faces.items.size());
  parallel_for(0, nf, [&](int first, int last) {
    for (int f = first; f < last; ++f)
      for (int i = topo.face_faces.begin(f); i < topo.face_faces.end(f); ++i) {
        const int j = topo.face_faces.items[i];
        spatial[i] = static_cast<float>(
            area_unit * g.areas[j] * std::exp(-(g.centroids.row(f) - g.centroids.row(j)).squaredNorm() * inv_s));
      }
  });

  Positions n = g.normals, next(nf, 3);
  for (int it = 0; it < iterations; ++it) {
    const Positions patch_guide = own_normals ? Positions() : guidance(topo, g, n);
    const Positions& guide = own_normals ? n : patch_guide;
    parallel_for(0, nf, [&](int first, int last) {
      for (int f = first; f < last; ++f) {
        const double inv_rf = face_inv_r.empty() ? inv_r : face_inv_r[f];
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        for (int i = topo.face_faces.begin(f); i < topo.face_faces.end(f); ++i) {
          const int j = topo.face_faces.items[i];
          if (own_normals && j == f) continue;
          const float range = static_cast<float>((guide.row(f) - guide.row(j)).squaredNorm() * inv_rf);
          sum += (spatial[i] * std::exp(-range)) * n.row(j);
        }
        const double len = sum.norm();
        next.row(f) = len > 0 ? Eigen::RowVector3d(sum / len) : n.row(f);
      }
    });
    n.swap(next);
  }
  return n;
}

// Normal voting tensor of each vertex (Wang et al.): T = sum_f w_f n_f n_f^T over its faces,
// w_f = A_f exp(-|c_f - v| / theta), theta its longest edge (the paper's 1/A_max factor
// cancels in the normalised eigenvalues mu1 >= mu2 >= mu3, sum 1). Returns 1 - mu1 = mu2 + mu3:
// 0 on a plane, (1 - cos a) / 2 on a balanced crease of angle a, 2/3 at a cube corner.
std::vector<double> tensor_saliency(const Positions& p, const Topology& topo, const FaceGeometry& g,
                                    const Positions& normals) {
  const int nv = static_cast<int>(p.rows());
  std::vector<double> saliency(nv, 0.0);
  for (int v = 0; v < nv; ++v) {
    double theta = 0;
    for (int i = topo.vertex_edges.begin(v); i < topo.vertex_edges.end(v); ++i) {
      const auto& ev = topo.edge_vertices[topo.vertex_edges.items[i]];
      theta = std::max(theta, (p.row(ev[0]) - p.row(ev[1])).norm());
    }
    if (theta <= 0) continue;
    Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
    for (int i = topo.vertex_faces.begin(v); i < topo.vertex_faces.end(v); ++i) {
      const int f = topo.vertex_faces.items[i];
      const double w = g.areas[f] * std::exp(-(g.centroids.row(f) - p.row(v)).norm() / theta);
      tensor += w * normals.row(f).transpose() * normals.row(f);
    }
    const double trace = tensor.trace();
    if (!(trace > 0)) continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(tensor / trace, Eigen::EigenvaluesOnly);
    saliency[v] = 1.0 - eig.eigenvalues()[2];
  }
  return saliency;
}

int other_vertex(const Topology& topo, int e, int v) {
  const auto& ev = topo.edge_vertices[e];
  return ev[0] == v ? ev[1] : ev[0];
}

// Neighbour support: a weak crease edge is accepted when it continues an accepted one at a
// shared vertex, along the same line: the path turns there by less than 60 degrees. (Also
// asking the crease directions n_0 x n_1 to agree changed nothing measurable.)
void supported_creases(const Positions& p, const Topology& topo, std::vector<char>& crease, std::vector<int>& queue) {
  while (!queue.empty()) {
    const int e = queue.back();
    queue.pop_back();
    for (int v : topo.edge_vertices[e]) {
      const Eigen::RowVector3d in = (p.row(v) - p.row(other_vertex(topo, e, v))).normalized();
      for (int i = topo.vertex_edges.begin(v); i < topo.vertex_edges.end(v); ++i) {
        const int f = topo.vertex_edges.items[i];
        if (crease[f] != 1) continue;
        const Eigen::RowVector3d out = (p.row(other_vertex(topo, f, v)) - p.row(v)).normalized();
        if (in.dot(out) < 0.5) continue;
        crease[f] = 2;
        queue.push_back(f);
      }
    }
  }
}

// Where three creases meet at a vertex whose faces all touch two of them (a coarse corner),
// the filter blends those faces: the creases stop one vertex short and close a small loop of
// crease edges around it (its one-ring's outer edges). Such a vertex is taken back as their
// junction. (A vertex merely surrounded by feature vertices, as in a strip one triangle
// wide between two creases, is not: its ring has edges across the strip.)
void fill_junctions(const Topology& topo, const std::vector<char>& crease, const std::vector<char>& on_boundary,
                    std::vector<char>& feature) {
  auto is_crease = [&](int a, int b) {
    for (int i = topo.vertex_edges.begin(a); i < topo.vertex_edges.end(a); ++i) {
      const int e = topo.vertex_edges.items[i];
      if (other_vertex(topo, e, a) == b) return crease[e] == 2;
    }
    return false;
  };
  const int nv = static_cast<int>(feature.size());
  std::vector<int> junctions;
  for (int v = 0; v < nv; ++v) {
    if (feature[v] || on_boundary[v] || topo.vertex_faces.end(v) == topo.vertex_faces.begin(v)) continue;
    bool enclosed = true;
    for (int i = topo.vertex_faces.begin(v); i < topo.vertex_faces.end(v) && enclosed; ++i) {
      const int f = topo.vertex_faces.items[i];
      const int k = topo.faces(f, 0) == v ? 0 : topo.faces(f, 1) == v ? 1 : 2;
      enclosed = is_crease(topo.faces(f, (k + 1) % 3), topo.faces(f, (k + 2) % 3));
    }
    if (enclosed) junctions.push_back(v);
  }
  for (int v : junctions) feature[v] = 1;
}

// Makes the types agree with the lines linked from them: junctions become corners, and
// vertices the linking leaves on no line (spurs, isolated corners) are dropped. A few rounds
// reach a fixed point (link_feature_lines gives back the same corners).
void agree_with_lines(const Positions& positions, const Faces& faces, std::vector<FeatureType>& type) {
  const int nv = static_cast<int>(type.size());
  for (int round = 0; round < 4; ++round) {
    const FeatureLines lines = link_feature_lines(positions, faces, type);
    std::vector<FeatureType> linked(nv, FeatureType::None);
    for (int v = 0; v < nv; ++v)
      if (lines.line_of_vertex[v] >= 0) linked[v] = FeatureType::Edge;
    for (size_t c = 0; c < lines.corners.size(); ++c)
      if (lines.corner_valence[c] > 0) linked[lines.corners[c]] = FeatureType::Corner;
    if (linked == type) return;
    type.swap(linked);
  }
}

// Topology-preserving thinning (after Rossl, Kobbelt & Seidel 2000): a feature vertex whose
// feature neighbours form a single arc of its one-ring can go without splitting or closing
// anything; removing such vertices, least salient (tensor_saliency) first, until none is
// left turns bands into one-vertex-wide chains. Line ends (one feature neighbour), junctions
// (several arcs) and mesh boundary vertices stay.
void thin(const Topology& topo, const std::vector<double>& saliency, const std::vector<char>& on_boundary,
          std::vector<char>& feature) {
  const int nv = static_cast<int>(feature.size());
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (feature[v] && !on_boundary[v]) order.push_back(v);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return saliency[a] < saliency[b]; });
  for (bool changed = true; changed;) {
    changed = false;
    for (int v : order) {
      if (!feature[v]) continue;
      int neighbours = 0, joined = 0;  // joined: faces at v whose two other vertices are features
      for (int i = topo.vertex_edges.begin(v); i < topo.vertex_edges.end(v); ++i)
        neighbours += feature[other_vertex(topo, topo.vertex_edges.items[i], v)];
      for (int i = topo.vertex_faces.begin(v); i < topo.vertex_faces.end(v); ++i) {
        const int f = topo.vertex_faces.items[i];
        int others = 0;
        for (int k = 0; k < 3; ++k) others += topo.faces(f, k) != v && feature[topo.faces(f, k)];
        joined += others == 2;
      }
      // around an interior vertex the arcs number neighbours - joined (0: the whole ring)
      if (neighbours >= 2 && neighbours - joined == 1) {
        feature[v] = 0;
        changed = true;
      }
    }
  }
}

// Drops connected groups of feature vertices smaller than `min_size` (isolated noise
// detections); groups on the mesh boundary stay.
void drop_small_groups(const Topology& topo, const std::vector<char>& on_boundary, int min_size,
                       std::vector<char>& feature) {
  const int nv = static_cast<int>(feature.size());
  std::vector<char> seen(nv, 0);
  std::vector<int> group;
  for (int s = 0; s < nv; ++s) {
    if (!feature[s] || seen[s]) continue;
    group.assign(1, s);
    seen[s] = 1;
    bool keep = false;
    for (size_t g = 0; g < group.size(); ++g) {
      const int v = group[g];
      keep = keep || on_boundary[v];
      for (int i = topo.vertex_edges.begin(v); i < topo.vertex_edges.end(v); ++i) {
        const int w = other_vertex(topo, topo.vertex_edges.items[i], v);
        if (feature[w] && !seen[w]) {
          seen[w] = 1;
          group.push_back(w);
        }
      }
    }
    if (!keep && static_cast<int>(group.size()) < min_size)
      for (int v : group) feature[v] = 0;
  }
}

}  // namespace

bool detect_sharp_features(const Positions& positions, const Faces& faces, const SharpFeatureOptions& options,
                           std::vector<FeatureType>& type, std::string& error) {
  if (!check_triangle_mesh(positions, faces, error)) return false;
  if (!(options.angle_degrees > 0 && options.angle_degrees < 180)) {
    error = "the feature angle must lie between 0 and 180 degrees";
    return false;
  }
  const int nv = static_cast<int>(positions.rows());
  Topology topo;
  if (!build_topology(faces, nv, topo, error)) return false;
  const FaceGeometry geometry = face_geometry(positions, topo.faces);
  const Positions normals =
      filter_normals(topo, geometry, std::max(0, options.filter_iterations), options.filter_sigma);
  const std::vector<double> saliency = tensor_saliency(positions, topo, geometry, normals);

  // Crease edges: strong above the angle, weak above support_ratio times it.
  const int ne = static_cast<int>(topo.edge_vertices.size());
  const double strong = std::cos(options.angle_degrees * M_PI / 180);
  const double weak = std::cos(options.support_ratio * options.angle_degrees * M_PI / 180);
  std::vector<char> crease(ne, 0);  // 2 accepted, 1 weak (waiting for support), 0 none
  std::vector<int> queue;
  for (int e = 0; e < ne; ++e) {
    const auto& ef = topo.edge_faces[e];
    const double c = ef[1] < 0 ? -1.0 : normals.row(ef[0]).dot(normals.row(ef[1]));
    crease[e] = c < strong ? 2 : c < weak ? 1 : 0;
    if (crease[e] == 2) queue.push_back(e);
  }
  supported_creases(positions, topo, crease, queue);

  std::vector<char> feature(nv, 0), on_boundary(nv, 0);
  for (int e = 0; e < ne; ++e) {
    if (crease[e] != 2) continue;
    for (int v : topo.edge_vertices[e]) feature[v] = 1;
    if (topo.edge_faces[e][1] < 0)
      for (int v : topo.edge_vertices[e]) on_boundary[v] = 1;
  }
  fill_junctions(topo, crease, on_boundary, feature);
  thin(topo, saliency, on_boundary, feature);
  drop_small_groups(topo, on_boundary, options.min_feature_vertices, feature);

  type.assign(nv, FeatureType::None);
  for (int v = 0; v < nv; ++v)
    if (feature[v]) type[v] = FeatureType::Edge;
  agree_with_lines(positions, topo.faces, type);
  return true;
}

// filter_normals on a checked mesh and per-face widths (empty, or one positive width per face).
static bool check_face_sigma(const Faces& faces, const std::vector<double>& face_sigma, std::string& error) {
  if (!face_sigma.empty() && static_cast<Eigen::Index>(face_sigma.size()) != faces.rows()) {
    error = "one range width per face expected";
    return false;
  }
  for (double w : face_sigma)
    if (!(w > 0)) {
      error = "range widths must be positive";
      return false;
    }
  return true;
}

static bool filtered_face_normals(const Positions& positions, const Faces& faces, int iterations, double sigma,
                                  const std::vector<double>& face_sigma, bool own_normals, Positions& normals,
                                  std::string& error) {
  Topology topo;
  if (!check_face_sigma(faces, face_sigma, error) ||
      !build_topology(faces, static_cast<int>(positions.rows()), topo, error))
    return false;
  normals = filter_normals(topo, face_geometry(positions, faces), iterations, sigma, face_sigma, own_normals);
  return true;
}

bool filter_face_normals_refitting(const Positions& positions, const Faces& faces, int passes, double sigma,
                                   bool own_normals,
                                   const std::function<Positions(const Positions&, const Positions&)>& fit,
                                   Positions& result, std::string& error, const std::vector<double>& face_sigma) {
  Topology topo;
  if (!check_face_sigma(faces, face_sigma, error) ||
      !build_topology(faces, static_cast<int>(positions.rows()), topo, error))
    return false;
  result = positions;
  for (int pass = 0; pass < passes; ++pass)
    result = fit(result, filter_normals(topo, face_geometry(result, faces), 1, sigma, face_sigma, own_normals));
  return true;
}

bool guided_face_normals(const Positions& positions, const Faces& faces, int iterations, double sigma,
                         Positions& normals, std::string& error, const std::vector<double>& face_sigma) {
  return filtered_face_normals(positions, faces, iterations, sigma, face_sigma, false, normals, error);
}

bool bilateral_face_normals(const Positions& positions, const Faces& faces, int iterations, double sigma,
                            Positions& normals, std::string& error, const std::vector<double>& face_sigma) {
  return filtered_face_normals(positions, faces, iterations, sigma, face_sigma, true, normals, error);
}

}  // namespace hht
