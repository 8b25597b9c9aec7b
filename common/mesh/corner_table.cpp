#include "mesh/corner_table.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hht {

namespace {

// Corners grouped by the smaller endpoint of the edge they face: a counting sort, so the
// table is built in linear time (a comparison sort of 10M corners takes seconds).
void group_corners_by_edge(const CornerTable& t, int vertex_count, std::vector<int>& start,
                           std::vector<int>& corners) {
  start.assign(vertex_count + 1, 0);
  for (int c = 0; c < t.corners(); ++c)
    ++start[std::min(t.vertex[corner_next(c)], t.vertex[corner_prev(c)]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> fill(start.begin(), start.end() - 1);
  corners.resize(t.corners());
  for (int c = 0; c < t.corners(); ++c)
    corners[fill[std::min(t.vertex[corner_next(c)], t.vertex[corner_prev(c)])]++] = c;
}

// The corners c[0..k) facing one edge of more than two faces paired two by two, the best pair
// first: two faces of one part of the surface without such edges (`part`: a surface with a fin on
// it stays closed, the fin comes off), then faces whose orientations agree across the edge (a
// coherent sheet's sides do), then the pair nearest to lying flat across the edge (their third
// vertices most opposite seen along it), then the faces that come first. A face without a partner
// is left unpaired. Returns the pairs whose orientations disagree.
int pair_sheets(const Positions& p, const std::vector<int>& part, const std::vector<int>& vertex, const int* c, int k,
                std::vector<int>& opposite) {
  const int a = vertex[corner_next(c[0])], b = vertex[corner_prev(c[0])];
  const Eigen::RowVector3d axis = (p.row(b) - p.row(a)).normalized();
  std::vector<Eigen::RowVector3d> side(k);
  for (int i = 0; i < k; ++i) {
    const Eigen::RowVector3d u = p.row(vertex[c[i]]) - p.row(a);
    side[i] = u - u.dot(axis) * axis;
    const double length = side[i].norm();
    side[i] = length > 0 && std::isfinite(length) ? Eigen::RowVector3d(side[i] / length) : Eigen::RowVector3d::Zero();
  }
  const auto disagree = [&](int i, int j) { return vertex[corner_next(c[i])] != vertex[corner_prev(c[j])]; };
  std::vector<char> paired(k, 0);
  int disagreeing = 0;
  // Each round scans every pair: on an edge of very many faces (a broken export's fan of pages)
  // only the best pair is joined, or none, so that the work stays bounded.
  const int rounds = k <= 64 ? k / 2 : k <= 4096 ? 1 : 0;
  for (int round = 0; round < rounds; ++round) {
    int bi = -1, bj = -1;
    double best = 0;
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j) {
        if (paired[i] || paired[j]) continue;
        const double score = side[i].dot(side[j]) + (disagree(i, j) ? 2 : 0) +
                             (part[corner_triangle(c[i])] != part[corner_triangle(c[j])] ? 4 : 0);
        // A tie (a face given twice) goes to the faces that come first, the same at each of their edges.
        const int last = std::max(c[i], c[j]);
        if (bi < 0 || score < best || (score == best && last < std::max(c[bi], c[bj]))) {
          best = score;
          bi = i;
          bj = j;
        }
      }
    paired[bi] = paired[bj] = 1;
    opposite[c[bi]] = c[bj];
    opposite[c[bj]] = c[bi];
    disagreeing += disagree(bi, bj);
  }
  return disagreeing;
}

// `positions` null: an edge of more than two faces fails the build; else its faces are paired by
// pair_sheets and the edge counted in `cut_edges`.
bool build_table(const Faces& faces, int vertex_count, const Positions* positions, CornerTable& table,
                 int& inconsistent_edges, int* cut_edges, std::vector<char>* on_cut_edge, std::string& error) {
  const int nf = static_cast<int>(faces.rows());
  table.vertex.resize(3 * static_cast<size_t>(nf));
  table.opposite.assign(3 * static_cast<size_t>(nf), -1);
  int repeated = 0;
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v = faces(f, k);
      if (v < 0 || v >= vertex_count) {
        error = "face " + std::to_string(f) + " references vertex " + std::to_string(v) +
                ", which does not exist";
        return false;
      }
      table.vertex[3 * f + k] = v;
    }
    if (faces(f, 0) == faces(f, 1) || faces(f, 1) == faces(f, 2) || faces(f, 0) == faces(f, 2))
      ++repeated;
  }
  if (repeated > 0) {
    error = std::to_string(repeated) +
            " faces use the same vertex twice (topologically degenerate); remove them first "
            "(Cleaning and Repairing > Remove Duplicate Faces / Remove Zero Area Faces)";
    return false;
  }

  std::vector<int> start, corners;
  group_corners_by_edge(table, vertex_count, start, corners);
  if (on_cut_edge) on_cut_edge->assign(vertex_count, 0);
  inconsistent_edges = 0;
  int nonmanifold_edges = 0;
  std::vector<std::pair<int, int>> crowded;  // edges of more than two faces: their corners' range
  for (int v = 0; v < vertex_count; ++v) {
    // Within one bucket, corners facing the same edge share the larger endpoint too.
    std::sort(corners.begin() + start[v], corners.begin() + start[v + 1], [&](int a, int b) {
      return std::max(table.vertex[corner_next(a)], table.vertex[corner_prev(a)]) <
             std::max(table.vertex[corner_next(b)], table.vertex[corner_prev(b)]);
    });
    for (int i = start[v]; i < start[v + 1];) {
      const int c = corners[i];
      const int far = std::max(table.vertex[corner_next(c)], table.vertex[corner_prev(c)]);
      int j = i + 1;
      while (j < start[v + 1] && std::max(table.vertex[corner_next(corners[j])],
                                          table.vertex[corner_prev(corners[j])]) == far)
        ++j;
      if (j - i == 2) {
        const int d = corners[i + 1];
        table.opposite[c] = d;
        table.opposite[d] = c;
        if (table.vertex[corner_next(c)] != table.vertex[corner_prev(d)]) ++inconsistent_edges;
      } else if (j - i > 2) {
        ++nonmanifold_edges;
        crowded.emplace_back(i, j - i);
        if (on_cut_edge) (*on_cut_edge)[v] = (*on_cut_edge)[far] = 1;
      }
      i = j;
    }
  }
  if (positions && !crowded.empty()) {
    std::vector<int> part;
    face_components(table, part);
    for (const auto& [first, count] : crowded)
      inconsistent_edges += pair_sheets(*positions, part, table.vertex, &corners[first], count, table.opposite);
  }
  if (cut_edges) *cut_edges = nonmanifold_edges;
  if (nonmanifold_edges > 0 && !cut_edges) {
    error = std::to_string(nonmanifold_edges) +
            " non-manifold edges (shared by more than two faces); repair them first "
            "(Cleaning and Repairing > Repair non Manifold Edges)";
    return false;
  }
  return true;
}

}  // namespace

bool build_corner_table(const Faces& faces, int vertex_count, CornerTable& table, int& inconsistent_edges,
                        std::string& error) {
  return build_table(faces, vertex_count, nullptr, table, inconsistent_edges, nullptr, nullptr, error);
}

bool build_corner_table_cutting(const Faces& faces, const Positions& positions, CornerTable& table,
                                int& inconsistent_edges, int& cut_edges, std::string& error,
                                std::vector<char>* on_cut_edge) {
  return build_table(faces, static_cast<int>(positions.rows()), &positions, table, inconsistent_edges, &cut_edges,
                     on_cut_edge, error);
}

bool orient_faces_coherently(Faces& faces, const CornerTable& table, std::string& error) {
  const int nf = static_cast<int>(faces.rows());
  std::vector<signed char> flip(nf, -1);  // -1: not reached yet
  std::vector<int> stack;
  for (int seed = 0; seed < nf; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        const int d = table.opposite[c];
        if (d < 0) continue;
        const bool agree = table.vertex[corner_next(c)] == table.vertex[corner_prev(d)];
        const signed char wanted = static_cast<signed char>(flip[f] ^ (agree ? 0 : 1));
        const int g = corner_triangle(d);
        if (flip[g] < 0) {
          flip[g] = wanted;
          stack.push_back(g);
        } else if (flip[g] != wanted) {
          error = "the mesh is not orientable (a Moebius-like strip): no coherent orientation exists";
          return false;
        }
      }
    }
  }
  for (int f = 0; f < nf; ++f)
    if (flip[f] == 1) std::swap(faces(f, 1), faces(f, 2));
  return true;
}

void walk_fan(const CornerTable& table, int c, std::vector<char>& seen, std::vector<int>& fan) {
  // Within one fan, the next corner at the same vertex is next(opposite(next(c))).
  for (int x = c; x >= 0 && !seen[x];) {
    seen[x] = 1;
    fan.push_back(x);
    const int o = table.opposite[corner_next(x)];
    x = o < 0 ? -1 : corner_next(o);
  }
  for (int x = c;;) {
    const int o = table.opposite[corner_prev(x)];
    if (o < 0) break;
    x = corner_prev(o);
    if (seen[x]) break;
    seen[x] = 1;
    fan.push_back(x);
  }
}

int count_nonmanifold_vertices(const CornerTable& table, int vertex_count, std::vector<char>* flags) {
  std::vector<int> incident(vertex_count, 0), fans(vertex_count, 0), outgoing_boundary(vertex_count, 0);
  std::vector<char> seen(table.corners(), 0);
  for (int c = 0; c < table.corners(); ++c) {
    ++incident[table.vertex[c]];
    if (table.opposite[c] < 0) ++outgoing_boundary[table.vertex[corner_next(c)]];
  }
  std::vector<int> fan;
  for (int c = 0; c < table.corners(); ++c) {
    if (seen[c]) continue;
    ++fans[table.vertex[c]];
    walk_fan(table, c, seen, fan);
  }
  if (flags != nullptr) flags->assign(vertex_count, 0);
  int bad = 0;
  for (int v = 0; v < vertex_count; ++v)
    if (fans[v] > 1 || outgoing_boundary[v] > 1) {
      ++bad;
      if (flags != nullptr) (*flags)[v] = 1;
    }
  return bad;
}

std::vector<std::vector<int>> boundary_loops(const CornerTable& table) {
  // A boundary corner c faces the boundary edge vertex[next(c)] -> vertex[prev(c)].
  std::vector<int> outgoing;  // vertex -> a boundary corner leaving it
  int max_vertex = -1;
  for (int v : table.vertex) max_vertex = std::max(max_vertex, v);
  outgoing.assign(max_vertex + 1, -1);
  for (int c = 0; c < table.corners(); ++c)
    if (table.opposite[c] < 0) outgoing[table.vertex[corner_next(c)]] = c;
  std::vector<std::vector<int>> loops;
  std::vector<char> used(table.corners(), 0);
  for (int c = 0; c < table.corners(); ++c) {
    if (table.opposite[c] >= 0 || used[c]) continue;
    std::vector<int> loop;
    for (int x = c; x >= 0 && !used[x]; x = outgoing[table.vertex[corner_prev(x)]]) {
      used[x] = 1;
      loop.push_back(table.vertex[corner_next(x)]);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

int face_components(const CornerTable& table, std::vector<int>& component_of_face) {
  const int nf = table.corners() / 3;
  component_of_face.assign(nf, -1);
  int count = 0;
  std::vector<int> stack;
  for (int seed = 0; seed < nf; ++seed) {
    if (component_of_face[seed] >= 0) continue;
    component_of_face[seed] = count;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        const int d = table.opposite[c];
        if (d >= 0 && component_of_face[corner_triangle(d)] < 0) {
          component_of_face[corner_triangle(d)] = count;
          stack.push_back(corner_triangle(d));
        }
      }
    }
    ++count;
  }
  return count;
}

}  // namespace hht
