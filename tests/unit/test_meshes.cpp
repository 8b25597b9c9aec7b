#include "test_meshes.h"

#include "mesh/corner_table.h"

#include <vcg/complex/algorithms/create/platonic.h>
#include <wrap/io_trimesh/import_off.h>

#include <map>
#include <random>
#include <set>
#include <stdexcept>

namespace hht::test {

namespace {
ArrayMesh from_vcg(const TriMesh& m) {
  ArrayMesh a;
  mesh_to_arrays(m, a.positions, a.faces);
  return a;
}
}  // namespace

ArrayMesh load_data_mesh(const std::string& name) {
  TriMesh m;
  const std::string path = std::string(HHT_DATA_DIR) + "/" + name + ".off";
  if (vcg::tri::io::ImporterOFF<TriMesh>::Open(m, path.c_str()) != 0)
    throw std::runtime_error("cannot read " + path + " (run scripts/setup.sh)");
  return from_vcg(m);
}

ArrayMesh grid(int nx, int ny) {
  ArrayMesh m;
  m.positions.resize(nx * ny, 3);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.positions.row(j * nx + i) << i, j, 0;
  m.faces.resize(2 * (nx - 1) * (ny - 1), 3);
  int f = 0;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      m.faces.row(f++) << a, b, d;
      m.faces.row(f++) << a, d, c;
    }
  return m;
}

ArrayMesh midpoint_subdivision(const ArrayMesh& m) {
  std::map<std::pair<int, int>, int> midpoint;
  std::vector<Eigen::RowVector3d> added;
  auto middle = [&](int a, int b) {
    const auto [it, inserted] = midpoint.try_emplace({std::min(a, b), std::max(a, b)}, m.vertices() + static_cast<int>(added.size()));
    if (inserted) added.push_back(0.5 * (m.positions.row(a) + m.positions.row(b)));
    return it->second;
  };
  ArrayMesh out;
  out.faces.resize(4 * m.faces.rows(), 3);
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f) {
    const int a = m.faces(f, 0), b = m.faces(f, 1), c = m.faces(f, 2);
    const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    out.faces.row(4 * f) << a, ab, ca;
    out.faces.row(4 * f + 1) << ab, b, bc;
    out.faces.row(4 * f + 2) << ca, bc, c;
    out.faces.row(4 * f + 3) << ab, bc, ca;
  }
  out.positions.resize(m.vertices() + static_cast<Eigen::Index>(added.size()), 3);
  out.positions.topRows(m.vertices()) = m.positions;
  for (size_t i = 0; i < added.size(); ++i) out.positions.row(m.vertices() + static_cast<Eigen::Index>(i)) = added[i];
  return out;
}

ArrayMesh sphere(int subdivisions, double radius) {
  TriMesh m;
  vcg::tri::Sphere(m, subdivisions);
  ArrayMesh a = from_vcg(m);
  a.positions *= radius;
  return a;
}

ArrayMesh torus(double major, double minor, int major_steps, int minor_steps) {
  TriMesh m;
  vcg::tri::Torus(m, major, minor, major_steps, minor_steps);
  return from_vcg(m);
}

ArrayMesh remove_faces(const ArrayMesh& m, int every) {
  // Drop a face and its edge neighbours every `every` faces: separate holes of a few faces.
  CornerTable t;
  int inconsistent = 0;
  std::string error;
  build_corner_table(m.faces, m.vertices(), t, inconsistent, error);
  std::vector<char> drop(m.faces.rows(), 0), touched(m.vertices(), 0);
  for (Eigen::Index f = 0; f < m.faces.rows(); f += every) {
    bool free = true;  // keep holes apart so no vertex joins two of them
    for (int c = 3 * f; c < 3 * f + 3; ++c)
      for (int k : {c, t.opposite[c]})
        for (int j = 3 * (k / 3); j < 3 * (k / 3) + 3; ++j) free = free && !touched[t.vertex[j]];
    if (!free) continue;
    drop[f] = 1;
    for (int c = 3 * f; c < 3 * f + 3; ++c) {
      drop[t.opposite[c] / 3] = 1;
      for (int k : {c, t.opposite[c]})
        for (int j = 3 * (k / 3); j < 3 * (k / 3) + 3; ++j) touched[t.vertex[j]] = 1;
    }
  }
  ArrayMesh out;
  out.positions = m.positions;
  out.faces.resize(m.faces.rows(), 3);
  Eigen::Index n = 0;
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    if (!drop[f]) out.faces.row(n++) = m.faces.row(f);
  out.faces.conservativeResize(n, 3);
  return out;
}

ArrayMesh disjoint_union(const ArrayMesh& a, const ArrayMesh& b) {
  ArrayMesh u;
  u.positions.resize(a.positions.rows() + b.positions.rows(), 3);
  u.positions << a.positions, b.positions;
  u.faces.resize(a.faces.rows() + b.faces.rows(), 3);
  u.faces << a.faces, (b.faces.array() + a.vertices()).matrix();
  return u;
}

ArrayMesh touching_spheres(int subdivisions) {
  const ArrayMesh a = sphere(subdivisions);
  const int n = a.vertices();
  ArrayMesh both = disjoint_union(a, a);
  // The second sphere mirrored through vertex 0 of the first (its faces turned back outwards), its
  // own vertex 0 replaced by the first's, and its last vertex moved into the freed place.
  const Eigen::RowVector3d shift = a.positions.row(0) * 2;
  for (int i = n; i < 2 * n; ++i) both.positions.row(i) = -both.positions.row(i) + shift;
  for (Eigen::Index f = a.faces.rows(); f < both.faces.rows(); ++f) {
    std::swap(both.faces(f, 1), both.faces(f, 2));
    for (int k = 0; k < 3; ++k) {
      if (both.faces(f, k) == n) both.faces(f, k) = 0;
      else if (both.faces(f, k) == 2 * n - 1) both.faces(f, k) = n;
    }
  }
  both.positions.row(n) = both.positions.row(2 * n - 1);
  both.positions.conservativeResize(2 * n - 1, 3);
  return both;
}

ArrayMesh finned_sphere(int subdivisions, int fin_edges) {
  const ArrayMesh ball = sphere(subdivisions);
  const int n = ball.vertices();
  std::vector<std::set<int>> neighbours(n);
  for (Eigen::Index f = 0; f < ball.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) neighbours[ball.faces(f, k)].insert(ball.faces(f, (k + 1) % 3));
  // The path climbs one direction, so it never comes back to a vertex.
  const Eigen::RowVector3d climb = Eigen::RowVector3d(1, 0.3, 0.1).normalized();
  std::vector<int> path{0};
  while (static_cast<int>(path.size()) <= fin_edges) {
    int best = -1;
    for (int j : neighbours[path.back()])
      if (ball.positions.row(j).dot(climb) > ball.positions.row(path.back()).dot(climb) &&
          (best < 0 || ball.positions.row(j).dot(climb) > ball.positions.row(best).dot(climb)))
        best = j;
    if (best < 0) break;
    path.push_back(best);
  }
  const int steps = static_cast<int>(path.size()) - 1;
  const double height = (ball.positions.row(path[1]) - ball.positions.row(path[0])).norm();
  ArrayMesh out;
  out.positions.resize(n + steps + 1, 3);
  out.positions.topRows(n) = ball.positions;
  for (int i = 0; i <= steps; ++i)
    out.positions.row(n + i) = ball.positions.row(path[i]) * (1 + height / ball.positions.row(path[i]).norm());
  out.faces.resize(ball.faces.rows() + 2 * steps, 3);
  out.faces.topRows(ball.faces.rows()) = ball.faces;
  for (int i = 0; i < steps; ++i) {
    const Eigen::Index f = ball.faces.rows() + 2 * i;
    out.faces.row(f) << path[i], path[i + 1], n + i + 1;
    out.faces.row(f + 1) << path[i], n + i + 1, n + i;
  }
  return out;
}

ArrayMesh flip_random_edges(const ArrayMesh& m, int flips, unsigned seed) {
  ArrayMesh out = m;
  CornerTable t;
  int inconsistent = 0;
  std::string error;
  build_corner_table(out.faces, out.vertices(), t, inconsistent, error);
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < out.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = out.faces(f, k), b = out.faces(f, (k + 1) % 3);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  std::vector<char> used(out.faces.rows(), 0);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, t.corners() - 1);
  for (int tries = 0, done = 0; done < flips && tries < 100 * flips; ++tries) {
    const int c = pick(rng), o = t.opposite[c];
    if (o < 0 || used[c / 3] || used[o / 3]) continue;
    const int x = t.vertex[c], a = t.vertex[corner_next(c)], b = t.vertex[corner_prev(c)], y = t.vertex[o];
    if (x == y || edges.count({std::min(x, y), std::max(x, y)})) continue;
    out.faces.row(c / 3) << x, a, y;  // (x,a,b) + (y,b,a) -> (x,a,y) + (y,b,x)
    out.faces.row(o / 3) << y, b, x;
    edges.erase({std::min(a, b), std::max(a, b)});
    edges.insert({std::min(x, y), std::max(x, y)});
    used[c / 3] = used[o / 3] = 1;
    ++done;
  }
  return out;
}

}  // namespace hht::test
