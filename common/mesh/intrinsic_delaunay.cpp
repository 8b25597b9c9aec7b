#include "mesh/intrinsic_delaunay.h"

#include "mesh/corner_table.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hht {

namespace {

// Area from the side lengths (Heron's formula in Kahan's stable order); 0 for an impossible triangle.
double triangle_area(double a, double b, double c) {
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  const double q = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return q > 0 ? 0.25 * std::sqrt(q) : 0.0;
}

// The intrinsic triangulation: a corner table whose corner c faces an edge of length length[c].
struct Triangulation {
  CornerTable table;
  std::vector<double> length;

  // Cotangent of corner c's angle, bounded like corner_cotangents() on a face of no area.
  double cotangent(int c) const {
    const double a = length[c], b = length[corner_next(c)], d = length[corner_prev(c)];
    const double area = triangle_area(a, b, d);
    return (b * b + d * d - a * a) / std::max({4 * area, 2e-8 * b * d, 1e-300});
  }

  bool is_delaunay(int c) const {
    const int o = table.opposite[c];
    return o < 0 || cotangent(c) + cotangent(o) >= -1e-12;
  }

  // Replaces the edge facing c (and its opposite corner o) by the other diagonal of their two
  // triangles, laid out flat. Refuses where the layout is not a strictly convex quad, or c and o lie
  // in one triangle (folded around a vertex of one edge, which the flip would leave with none).
  bool flip(int c) {
    std::vector<int>& v = table.vertex;
    std::vector<int>& opp = table.opposite;
    const int o = opp[c];
    const int n1 = corner_next(c), p1 = corner_prev(c), n2 = corner_next(o), p2 = corner_prev(o);
    if (corner_triangle(c) == corner_triangle(o) || v[n2] != v[p1] || v[p2] != v[n1]) return false;
    // Corner c's vertex above the edge A = v[n1] -> B = v[p1], o's below it.
    const double l = length[c];
    if (!(l > 0)) return false;
    const double ca = length[p1], cb = length[n1], oa = length[n2], ob = length[p2];
    const double x1 = (l * l + ca * ca - cb * cb) / (2 * l), y1 = std::sqrt(std::max(0.0, ca * ca - x1 * x1));
    const double x2 = (l * l + oa * oa - ob * ob) / (2 * l), y2 = -std::sqrt(std::max(0.0, oa * oa - x2 * x2));
    if (!(y1 - y2 > 0)) return false;
    const double crossing = x1 + (x2 - x1) * y1 / (y1 - y2);
    if (!(crossing > 0 && crossing < l)) return false;
    const double diagonal = std::hypot(x1 - x2, y1 - y2);

    // The sides (B, c's vertex) and (A, o's vertex) move from n1 and n2 to o and c; a side glued to
    // the other one (a folded triangulation) moves with it.
    const auto moved = [&](int x) { return x == n1 ? o : x == n2 ? c : x; };
    const int across_c = moved(opp[n2]), across_o = moved(opp[n1]);
    v[p1] = v[o];
    v[p2] = v[c];
    opp[n1] = n2;
    opp[n2] = n1;
    opp[c] = across_c;
    if (across_c >= 0) opp[across_c] = c;
    opp[o] = across_o;
    if (across_o >= 0) opp[across_o] = o;
    length[c] = oa;
    length[o] = cb;
    length[n1] = length[n2] = diagonal;
    return true;
  }
};

}  // namespace

CotangentLaplacian intrinsic_delaunay_laplacian(const Positions& positions, const Faces& faces,
                                                IntrinsicDelaunayReport* report) {
  IntrinsicDelaunayReport local;
  IntrinsicDelaunayReport& r = report != nullptr ? *report : local;
  r = IntrinsicDelaunayReport{};
  const int n = static_cast<int>(positions.rows());

  Triangulation t;
  int inconsistent = 0;
  std::string error;
  if (!build_corner_table(faces, n, t.table, inconsistent, error)) return extrinsic_cotangent_laplacian(positions, faces);
  if (inconsistent > 0) {  // C and M do not depend on the faces' orientation; the flips need one
    Faces oriented = faces;
    if (!orient_faces_coherently(oriented, t.table, error) ||
        !build_corner_table(oriented, n, t.table, inconsistent, error) || inconsistent > 0)
      return extrinsic_cotangent_laplacian(positions, faces);
  }

  // A mesh with borders is flipped on its tufted cover (Sharp and Crane 2020): its faces twice, the
  // second sheet reversed and glued to the first along the borders, so that a border edge has a
  // triangle on each side too and an obtuse angle facing it is flipped away; C and M are half the cover's.
  const int faces_count = t.table.corners() / 3;
  const bool cover = std::any_of(t.table.opposite.begin(), t.table.opposite.end(), [](int o) { return o < 0; });
  if (cover) {
    const auto twin = [&](int c) { return 3 * (faces_count + c / 3) + (c % 3 == 0 ? 0 : 3 - c % 3); };
    CornerTable tufted;
    tufted.vertex.resize(6 * faces_count);
    tufted.opposite.resize(6 * faces_count);
    for (int c = 0; c < 3 * faces_count; ++c) {
      const int o = t.table.opposite[c];
      tufted.vertex[c] = tufted.vertex[twin(c)] = t.table.vertex[c];
      tufted.opposite[c] = o >= 0 ? o : twin(c);
      tufted.opposite[twin(c)] = o >= 0 ? twin(o) : c;
    }
    t.table = std::move(tufted);
  }

  const int corners = t.table.corners();
  t.length.resize(corners);
  double sum = 0;
  for (int c = 0; c < corners; ++c) {
    t.length[c] = (positions.row(t.table.vertex[corner_next(c)]) - positions.row(t.table.vertex[corner_prev(c)])).norm();
    sum += t.length[c];
  }
  const double mean = corners > 0 ? sum / corners : 0.0;
  if (!(mean > 0) || !std::isfinite(mean)) return extrinsic_cotangent_laplacian(positions, faces);
  r.intrinsic = true;
  r.tufted_cover = cover;

  double delta = 0;
  for (int c = 0; c < corners; ++c)
    delta = std::max(delta, kMollifyMargin * mean - (t.length[corner_next(c)] + t.length[corner_prev(c)] - t.length[c]));
  if (delta > 0)
    for (double& l : t.length) l += delta;
  r.mollified = delta / mean;

  std::vector<int> stack;
  stack.reserve(corners / 2);
  for (int c = 0; c < corners; ++c)
    if (t.table.opposite[c] > c) stack.push_back(c);
  // Flipping ends in exact arithmetic; the bound only stops a loop of rounding.
  const long long max_flips = 20LL * corners + 100;
  while (!stack.empty() && r.flips < max_flips) {
    const int c = stack.back();
    stack.pop_back();
    const int o = t.table.opposite[c];
    if (t.is_delaunay(c) || !t.flip(c)) continue;
    ++r.flips;
    // The quad's four sides may no longer be Delaunay.
    for (int x : {c, corner_prev(c), o, corner_prev(o)})
      if (t.table.opposite[x] >= 0) stack.push_back(x);
  }

  // The flips keep every edge glued to one other, coherently, with one length on both sides
  // (checked: a broken table would give wrong weights silently; the mesh's own triangles are then used).
  for (int c = 0; c < corners; ++c) {
    const int o = t.table.opposite[c];
    if (o < 0 || o >= corners || t.table.opposite[o] != c ||
        t.table.vertex[corner_next(c)] != t.table.vertex[corner_prev(o)] || t.length[c] != t.length[o]) {
      r = IntrinsicDelaunayReport{};
      return extrinsic_cotangent_laplacian(positions, faces);
    }
  }

  CotangentLaplacian out;
  out.pairs.resize(corners, 2);
  out.weights.resize(corners);
  out.areas = Eigen::VectorXd::Zero(n);
  for (int f = 0; f < corners / 3; ++f) {
    double cot[3], squared[3];
    for (int k = 0; k < 3; ++k) {
      const int c = 3 * f + k;
      cot[k] = t.cotangent(c);
      squared[k] = t.length[c] * t.length[c];
      out.pairs(c, 0) = t.table.vertex[corner_next(c)];
      out.pairs(c, 1) = t.table.vertex[corner_prev(c)];
      out.weights[c] = (cover ? 0.25 : 0.5) * cot[k];
    }
    const double area = triangle_area(t.length[3 * f], t.length[3 * f + 1], t.length[3 * f + 2]);
    if (!(area > 0)) continue;
    for (int k = 0; k < 3; ++k) out.areas[t.table.vertex[3 * f + k]] += mixed_voronoi_share(squared, cot, area, k);
  }
  if (cover) out.areas *= 0.5;
  return out;
}

CotangentLaplacian cotangent_laplacian(const Positions& positions, const Faces& faces, LaplacianTriangles triangles,
                                       IntrinsicDelaunayReport* report) {
  if (report != nullptr) *report = IntrinsicDelaunayReport{};
  return triangles == LaplacianTriangles::IntrinsicDelaunay ? intrinsic_delaunay_laplacian(positions, faces, report)
                                                            : extrinsic_cotangent_laplacian(positions, faces);
}

}  // namespace hht
