#include "cycle/hamiltonian_cycle.h"

#include <algorithm>
#include <random>

namespace hht {

namespace {

// Growth state of the region over the closed mesh (real vertices plus one dummy per hole).
struct Region {
  const CornerTable& table;
  const std::vector<char>& dummy;  // per vertex
  std::vector<char> visited;       // per vertex: on the ring
  std::vector<char> in_region;     // per triangle
  std::vector<int> corner_start, corners_at;  // vertex -> its corners (CSR)

  Region(const CornerTable& t, const std::vector<char>& d, int vertex_count)
      : table(t), dummy(d), visited(vertex_count, 0), in_region(t.corners() / 3, 0) {
    corner_start.assign(vertex_count + 1, 0);
    for (int v : t.vertex) ++corner_start[v + 1];
    for (int v = 0; v < vertex_count; ++v) corner_start[v + 1] += corner_start[v];
    std::vector<int> fill(corner_start.begin(), corner_start.end() - 1);
    corners_at.resize(t.corners());
    for (int c = 0; c < t.corners(); ++c) corners_at[fill[t.vertex[c]]++] = c;
  }

  int v(int c) const { return table.vertex[c]; }
  int o(int c) const { return table.opposite[c]; }
  bool has_dummy(int tri) const {
    return dummy[v(3 * tri)] || dummy[v(3 * tri + 1)] || dummy[v(3 * tri + 2)];
  }
  bool ring_edge(int c) const {  // the edge facing c separates the region from the rest
    return in_region[corner_triangle(c)] != in_region[corner_triangle(o(c))];
  }
  int region_faces_at(int vertex, int& last) const {
    int count = 0;
    for (int i = corner_start[vertex]; i < corner_start[vertex + 1]; ++i)
      if (in_region[corner_triangle(corners_at[i])]) {
        ++count;
        last = corners_at[i];
      }
    return count;
  }

  // The LR Ring Expander from seed corner s. A triangle is taken when its tip is new; its
  // gate edge must not touch a dummy, so each dummy enters through one boundary edge only
  // and dropping it later leaves that edge on the cycle.
  bool expand(int s) {
    visited[v(corner_next(s))] = visited[v(corner_prev(s))] = 1;
    long long budget = 4LL * table.corners() + 16;
    int c = s;
    do {
      if (!visited[v(c)] && !dummy[v(corner_next(c))] && !dummy[v(corner_prev(c))]) {
        visited[v(c)] = 1;
        in_region[corner_triangle(c)] = 1;
      } else if (!in_region[corner_triangle(c)]) {
        c = o(c);
      }
      c = o(corner_next(c));
    } while (c != o(s) && --budget > 0);
    return budget > 0;
  }

  // Attaches isolated vertex u by a local move: for a triangle (u,x,y) whose neighbour T2
  // across xy lies outside the region but has a ring edge facing w (x or y), w being an
  // ear tip (in exactly one region triangle, whose third edge is interior): drop the ear,
  // take T2 through its ring edge (w is its new tip), then take (u,x,y) through xy.
  bool attach(int u) {
    for (int i = corner_start[u]; i < corner_start[u + 1]; ++i) {
      const int cu = corners_at[i];
      const int t1 = corner_triangle(cu), t2 = corner_triangle(o(cu));
      if (has_dummy(t1) || has_dummy(t2)) continue;
      if (in_region[t2]) {  // xy is already a ring edge: take (u,x,y) directly
        take(t1);
        visited[u] = 1;
        return true;
      }
      for (int k : {corner_next(o(cu)), corner_prev(o(cu))}) {
        if (!ring_edge(k)) continue;
        const int w = v(k);
        int ear_corner = -1;
        if (region_faces_at(w, ear_corner) != 1) continue;
        const int ear = corner_triangle(ear_corner);
        if (has_dummy(ear) || !in_region[corner_triangle(o(ear_corner))] ||
            corner_triangle(o(k)) == ear)
          continue;
        in_region[ear] = 0;
        take(t2);
        take(t1);
        visited[u] = 1;
        return true;
      }
    }
    return false;
  }

  void take(int tri) { in_region[tri] = 1; }

  void reset(const std::vector<int>& faces) {
    for (int f : faces) {
      in_region[f] = 0;
      for (int k = 0; k < 3; ++k) visited[v(3 * f + k)] = 0;
    }
  }
};

bool close_holes(Faces& faces, int vertex_count, const CornerTable& table, int& holes,
                 std::vector<char>& dummy) {
  const auto loops = boundary_loops(table);
  holes = static_cast<int>(loops.size());
  dummy.assign(vertex_count + holes, 0);
  if (holes == 0) return true;
  size_t added = 0;
  for (const auto& loop : loops) added += loop.size();
  const Eigen::Index first = faces.rows();
  faces.conservativeResize(first + static_cast<Eigen::Index>(added), 3);
  Eigen::Index f = first;
  for (int h = 0; h < holes; ++h) {
    const int d = vertex_count + h;
    dummy[d] = 1;
    const auto& loop = loops[h];
    for (size_t j = 0; j < loop.size(); ++j) {
      // boundary edge loop[j] -> loop[j+1]; the fan triangle runs it the other way
      faces(f, 0) = loop[(j + 1) % loop.size()];
      faces(f, 1) = loop[j];
      faces(f, 2) = d;
      ++f;
    }
  }
  return true;
}

}  // namespace

bool hamiltonian_cycle(const Faces& input_faces, int vertex_count, const CycleOptions& options,
                       HamiltonianCycle& cycle, std::string& error) {
  cycle = HamiltonianCycle{};
  if (input_faces.rows() == 0) {
    error = "the mesh has no faces (a point cloud?): a Hamiltonian cycle needs a triangle mesh";
    return false;
  }
  Faces faces = input_faces;
  CornerTable table;
  if (!build_corner_table(faces, vertex_count, table, cycle.inconsistent_edges, error))
    return false;
  if (cycle.inconsistent_edges > 0) {
    int still = 0;
    if (!orient_faces_coherently(faces, table, error) ||
        !build_corner_table(faces, vertex_count, table, still, error))
      return false;
  }
  const int bad_vertices = count_nonmanifold_vertices(table, vertex_count);
  if (bad_vertices > 0) {
    error = std::to_string(bad_vertices) +
            " non-manifold vertices (several fans of faces, or boundaries, meeting at one vertex); "
            "repair them first (Cleaning and Repairing > Repair non Manifold Vertices by splitting)";
    return false;
  }

  std::vector<char> dummy;
  close_holes(faces, vertex_count, table, cycle.holes, dummy);
  const int total_vertices = vertex_count + cycle.holes;
  int unused = 0;
  if (cycle.holes > 0 && !build_corner_table(faces, total_vertices, table, unused, error))
    return false;

  std::vector<int> component_of_face;
  cycle.components = face_components(table, component_of_face);
  std::vector<std::vector<int>> component_faces(cycle.components);
  for (int f = 0; f < static_cast<int>(component_of_face.size()); ++f)
    component_faces[component_of_face[f]].push_back(f);

  Region region(table, dummy, total_vertices);
  std::mt19937 rng(static_cast<unsigned>(options.seed));
  cycle.position.assign(vertex_count, -1);
  std::vector<char> referenced(vertex_count, 0);
  for (int c = 0; c < static_cast<int>(input_faces.size()); ++c) referenced[input_faces.data()[c]] = 1;

  std::vector<int> successor(total_vertices, -1);
  for (const auto& comp : component_faces) {
    std::vector<int> seeds;  // real (dummy-free) faces only
    for (int f : comp)
      if (!region.has_dummy(f)) seeds.push_back(f);
    if (seeds.empty()) continue;

    std::vector<int> comp_vertices;
    for (int f : comp)
      for (int k = 0; k < 3; ++k)
        if (!dummy[table.vertex[3 * f + k]]) comp_vertices.push_back(table.vertex[3 * f + k]);
    std::sort(comp_vertices.begin(), comp_vertices.end());
    comp_vertices.erase(std::unique(comp_vertices.begin(), comp_vertices.end()), comp_vertices.end());

    auto grow = [&](int seed_face, int& isolated, int& repaired) {
      region.reset(comp);
      if (!region.expand(3 * seed_face)) return false;
      repaired = 0;
      for (int pass = 0; pass < 3 && options.repair; ++pass) {
        int gained = 0;
        for (int u : comp_vertices)
          if (!region.visited[u] && region.attach(u)) ++gained;
        repaired += gained;
        if (gained == 0) break;
      }
      isolated = static_cast<int>(
          std::count_if(comp_vertices.begin(), comp_vertices.end(), [&](int u) { return !region.visited[u]; }));
      return true;
    };

    int best_face = options.seed == 0 ? seeds.front()
                                      : seeds[std::uniform_int_distribution<size_t>(0, seeds.size() - 1)(rng)];
    int best_isolated = -1;
    for (int t = 0; t < std::max(1, options.tries); ++t) {
      const int face = t == 0 ? best_face
                              : seeds[std::uniform_int_distribution<size_t>(0, seeds.size() - 1)(rng)];
      int isolated = 0, repaired = 0;
      if (!grow(face, isolated, repaired)) {
        error = "internal error: the ring expander did not close its ring";
        return false;
      }
      if (best_isolated < 0 || isolated < best_isolated) {
        best_isolated = isolated;
        best_face = face;
      }
    }
    int isolated = 0, repaired = 0;
    grow(best_face, isolated, repaired);
    cycle.isolated += isolated;
    cycle.repaired += repaired;

    // The ring: region triangles' edges that face a non-region triangle, in region orientation.
    int ring_vertices = 0;
    for (int f : comp) {
      if (!region.in_region[f]) continue;
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        if (region.in_region[corner_triangle(table.opposite[c])]) continue;
        const int from = table.vertex[corner_next(c)];
        if (successor[from] >= 0) {
          error = "internal error: the ring passes twice through a vertex";
          return false;
        }
        successor[from] = table.vertex[corner_prev(c)];
        ++ring_vertices;
      }
    }
    const int start = table.vertex[3 * best_face + 1];
    cycle.segment_begin.push_back(static_cast<int>(cycle.order.size()));
    int steps = 0;
    for (int x = start; steps < ring_vertices; x = successor[x], ++steps) {
      if (x < 0) break;
      if (!dummy[x]) cycle.order.push_back(x);
      if (successor[x] == start) { ++steps; break; }
    }
    if (steps != ring_vertices) {
      error = "internal error: the ring is not a single simple cycle";
      return false;
    }
  }
  cycle.segment_begin.push_back(static_cast<int>(cycle.order.size()));
  for (int i = 0; i < static_cast<int>(cycle.order.size()); ++i) cycle.position[cycle.order[i]] = i;
  for (int v = 0; v < vertex_count; ++v) cycle.unreferenced += referenced[v] ? 0 : 1;
  return true;
}

}  // namespace hht
