#include "cycle/feature_lines.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

namespace hht {

namespace {

// The mesh edges between feature vertices, as adjacency lists (a few entries each), with
// the number of faces on each edge (1 on the mesh boundary).
struct FeatureGraph {
  std::vector<std::vector<int>> next, faces;
  int degree(int v) const { return static_cast<int>(next[v].size()); }
  int find(int a, int b) const {
    const auto it = std::find(next[a].begin(), next[a].end(), b);
    return it == next[a].end() ? -1 : static_cast<int>(it - next[a].begin());
  }
  bool linked(int a, int b) const { return find(a, b) >= 0; }
  bool on_boundary(int a, int b) const { return faces[a][find(a, b)] == 1; }
  void link(int a, int b) {
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
      const int i = find(from, to);
      if (i >= 0) {
        ++faces[from][i];
      } else {
        next[from].push_back(to);
        faces[from].push_back(1);
      }
    }
  }
  void unlink(int a, int b) {
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
      const int i = find(from, to);
      next[from].erase(next[from].begin() + i);
      faces[from].erase(faces[from].begin() + i);
    }
  }
};

// Lines between nodes (corners, ends, junctions), then the loops of what is left.
FeatureLines trace(const FeatureGraph& g, const std::vector<FeatureType>& type) {
  const int nv = static_cast<int>(type.size());
  FeatureLines out;
  auto is_corner = [&](int v) { return type[v] == FeatureType::Corner || g.degree(v) >= 3; };
  auto is_node = [&](int v) { return is_corner(v) || g.degree(v) != 2; };
  std::vector<char> done(nv, 0);
  for (int a = 0; a < nv; ++a) {
    if (type[a] == FeatureType::None || !is_node(a)) continue;
    for (int w : g.next[a]) {
      if (is_node(w) ? w < a : done[w]) continue;  // that line is traced already
      std::vector<int> line{a};
      for (int prev = a, cur = w;;) {
        line.push_back(cur);
        if (is_node(cur)) break;
        done[cur] = 1;
        const int step = g.next[cur][0] == prev ? g.next[cur][1] : g.next[cur][0];
        prev = cur;
        cur = step;
      }
      out.lines.push_back(std::move(line));
      out.closed.push_back(0);
    }
  }
  for (int s = 0; s < nv; ++s) {
    if (type[s] == FeatureType::None || is_node(s) || done[s]) continue;
    std::vector<int> loop;
    for (int prev = g.next[s][1], cur = s; !done[cur];) {
      loop.push_back(cur);
      done[cur] = 1;
      const int step = g.next[cur][0] == prev ? g.next[cur][1] : g.next[cur][0];
      prev = cur;
      cur = step;
    }
    out.lines.push_back(std::move(loop));
    out.closed.push_back(1);
  }
  out.line_of_vertex.assign(nv, -1);
  std::vector<int> valence(nv, 0);
  for (size_t l = 0; l < out.lines.size(); ++l) {
    for (int v : out.lines[l])
      if (!is_corner(v)) out.line_of_vertex[v] = static_cast<int>(l);
    if (out.closed[l]) continue;
    ++valence[out.lines[l].front()];
    ++valence[out.lines[l].back()];
  }
  for (int v = 0; v < nv; ++v)
    if (type[v] != FeatureType::None && is_corner(v)) {
      out.corners.push_back(v);
      out.corner_valence.push_back(valence[v]);
    }
  return out;
}

}  // namespace

FeatureLines link_feature_lines(const Positions& positions, const Faces& faces, const std::vector<FeatureType>& type,
                                int min_line_length) {
  const int nv = static_cast<int>(positions.rows());
  if (static_cast<int>(type.size()) != nv || (faces.size() > 0 && (faces.minCoeff() < 0 || faces.maxCoeff() >= nv)))
    return {};
  auto feature = [&](int v) { return type[v] != FeatureType::None; };
  FeatureGraph g;
  g.next.resize(nv);
  g.faces.resize(nv);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      if (a != b && feature(a) && feature(b)) g.link(a, b);
    }

  // A face of three feature vertices: following all three edges would make a short cut.
  // Drop the edge opposite the vertex that should carry the path: a corner, else the centre
  // of a cluster of such faces (a junction), else the one at the largest angle (facing the
  // longest edge: a line turning there keeps its turn), else the one with most feature
  // neighbours. Mesh boundary edges always stay.
  std::vector<int> full_faces(nv, 0);
  auto full = [&](Eigen::Index f) {
    return feature(faces(f, 0)) && feature(faces(f, 1)) && feature(faces(f, 2));
  };
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    if (full(f))
      for (int k = 0; k < 3; ++k) ++full_faces[faces(f, k)];
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const std::array<int, 3> v{faces(f, 0), faces(f, 1), faces(f, 2)};
    if (!g.linked(v[0], v[1]) || !g.linked(v[1], v[2]) || !g.linked(v[2], v[0])) continue;
    auto key = [&](int k) {
      const int a = v[(k + 1) % 3], b = v[(k + 2) % 3];
      return std::make_tuple(type[v[k]] == FeatureType::Corner, full_faces[v[k]],
                             (positions.row(a) - positions.row(b)).squaredNorm(), g.degree(v[k]));
    };
    int hub = -1;
    for (int k = 0; k < 3; ++k)
      if (!g.on_boundary(v[(k + 1) % 3], v[(k + 2) % 3]) && (hub < 0 || key(k) > key(hub))) hub = k;
    if (hub >= 0) g.unlink(v[(hub + 1) % 3], v[(hub + 2) % 3]);
  }

  // Drop short lines with a free end, until none is left: each drop can merge two lines.
  for (;;) {
    FeatureLines out = trace(g, type);
    auto free_end = [&](int v) { return type[v] != FeatureType::Corner && g.degree(v) <= 1; };
    bool dropped = false;
    for (size_t l = 0; l < out.lines.size(); ++l) {
      const std::vector<int>& line = out.lines[l];
      if (static_cast<int>(line.size()) >= min_line_length) continue;
      if (!out.closed[l] && !free_end(line.front()) && !free_end(line.back())) continue;
      for (size_t i = 0; i + 1 < line.size(); ++i) g.unlink(line[i], line[i + 1]);
      if (out.closed[l] && line.size() > 2) g.unlink(line.back(), line.front());
      dropped = true;
    }
    if (!dropped) return out;
  }
}

}  // namespace hht
