#include "filters/l0_denoise.h"

#include "mesh/corner_table.h"
#include "mesh/mesh_checks.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hht {

namespace {

using Sparse = Eigen::SparseMatrix<double>;

// An interior edge (ends i, j) with its two triangles' apexes k and l.
struct Hinge {
  std::array<int, 4> v;  // i, j, k, l
};

// R_e(p) = p_i + p_j - p_k - p_l.
constexpr std::array<double, 4> kRegulariser = {1, 1, -1, -1};

// The interior edges as hinges, and the count and summed length of all edges (the reference
// code's means run over OpenMesh's edges, boundary ones included). Fails on non-manifold edges.
struct Edges {
  std::vector<Hinge> hinges;
  int count = 0;
  double length = 0;
  int inconsistent = 0;  // neighbouring faces of opposite orientations
};

bool mesh_edges(const Positions& positions, const Faces& faces, Edges& edges, std::string& error) {
  CornerTable table;
  edges = Edges{};
  if (!build_corner_table(faces, static_cast<int>(positions.rows()), table, edges.inconsistent, error)) return false;
  for (int c = 0; c < table.corners(); ++c) {
    const int o = table.opposite[c];
    if (o >= 0 && o < c) continue;  // each edge once
    const int i = table.vertex[corner_next(c)], j = table.vertex[corner_prev(c)];
    ++edges.count;
    edges.length += (positions.row(i) - positions.row(j)).norm();
    if (o >= 0) edges.hinges.push_back({{i, j, table.vertex[c], table.vertex[o]}});
  }
  return true;
}

// D_e's coefficients on (i, j, k, l) at the positions p. Each apex weighs by the area of the
// other triangle and is taken relative to its foot on the edge's line; the coefficients sum to
// 0, so D_e ignores translations. A hinge with a degenerate edge or two degenerate triangles has
// no offset to measure: all zero.
std::array<double, 4> edge_operator(const Positions& p, const Hinge& h) {
  const Eigen::RowVector3d pi = p.row(h.v[0]), pj = p.row(h.v[1]), pk = p.row(h.v[2]), pl = p.row(h.v[3]);
  const Eigen::RowVector3d e = pj - pi;
  const double e2 = e.squaredNorm();
  const double area_k = 0.5 * e.cross(pk - pi).norm(), area_l = 0.5 * e.cross(pl - pi).norm();
  const double total = area_k + area_l;
  if (!(e2 > 0) || !(total > 0)) return {0, 0, 0, 0};
  const double wk = area_l / total, wl = area_k / total;          // apex weights
  const double tk = (pk - pi).dot(e) / e2, tl = (pl - pi).dot(e) / e2;  // feet along the edge
  return {-(wk * (1 - tk) + wl * (1 - tl)), -(wk * tk + wl * tl), wk, wl};
}

// Signed as OpenMesh's calc_dihedral_angle (the reference code's): positive where the other
// apex lies behind a face's plane (a convex edge for outward faces). Below kFlat radians an edge
// counts as flat, so that rounding on a plane cannot give the mean a sign.
constexpr double kFlat = 1e-9;

double hinge_angle(const Positions& p, const Hinge& h, bool is_signed) {
  const Eigen::RowVector3d pi = p.row(h.v[0]), pj = p.row(h.v[1]), pk = p.row(h.v[2]), pl = p.row(h.v[3]);
  // (i, j, k) is the first face as given, (j, i, l) the second oriented to agree with it.
  const Eigen::RowVector3d nk = (pj - pi).cross(pk - pi), nl = (pi - pj).cross(pl - pj);
  if (!(nk.norm() > 0) || !(nl.norm() > 0)) return 0;  // OpenMesh's 0 for a degenerate face
  const double angle = std::atan2(nk.cross(nl).norm(), nk.dot(nl));
  if (angle < kFlat) return 0;
  return is_signed && nk.dot(pl - pi) > 0 ? -angle : angle;
}

}  // namespace

bool l0_default_weights(const Positions& positions, const Faces& faces, DihedralMean mean, L0Weights& weights,
                        std::string& error) {
  if (!check_triangle_mesh(positions, faces, error)) return false;
  Edges edges;
  if (!mesh_edges(positions, faces, edges, error)) return false;
  const bool is_signed = mean == DihedralMean::Signed;
  if (is_signed && edges.inconsistent > 0) {
    // The sign needs neighbouring faces on the same side of the surface.
    Faces oriented = faces;
    CornerTable table;
    int inconsistent = 0;
    if (!build_corner_table(oriented, static_cast<int>(positions.rows()), table, inconsistent, error) ||
        !orient_faces_coherently(oriented, table, error) || !mesh_edges(positions, oriented, edges, error))
      return false;
  }
  double dihedral = 0;
  for (const Hinge& h : edges.hinges) dihedral += hinge_angle(positions, h, is_signed);
  weights.mean_edge_length = edges.length / edges.count;
  weights.mean_dihedral = dihedral / edges.count;
  weights.alpha = kAlphaPerDihedral * weights.mean_dihedral;
  weights.lambda = kLambdaPerDihedral * weights.mean_edge_length * weights.mean_edge_length * weights.mean_dihedral;
  return true;
}

bool l0_denoise(const Positions& positions, const Faces& faces, const L0DenoiseOptions& options, Positions& result,
                std::string& error, const std::function<void(double)>& progress) {
  if (!check_triangle_mesh(positions, faces, error)) return false;
  const auto bad = [](const std::optional<double>& w) { return w && !(*w >= 0 && std::isfinite(*w)); };
  if (!(options.beta0 > 0) || !(options.beta_max >= options.beta0) || !std::isfinite(options.beta_max) ||
      !(options.kappa > 1) || !(options.alpha_decay >= 0 && options.alpha_decay <= 1) || bad(options.alpha) ||
      bad(options.lambda)) {
    error = "beta0 must be positive, beta_max at least beta0, kappa over 1, the alpha decay in [0, 1], alpha and "
            "lambda at least 0";
    return false;
  }
  double alpha = options.alpha.value_or(0), lambda = options.lambda.value_or(0);
  if (!options.alpha || !options.lambda) {
    L0Weights w;
    if (!l0_default_weights(positions, faces, options.dihedral_mean, w, error)) return false;
    if (w.mean_dihedral < 0) {
      error = "the mean signed dihedral angle is negative (" + std::to_string(w.mean_dihedral) +
              " rad: faces oriented inwards, or a mostly concave mesh), and with it the default alpha and lambda; "
              "give them, or take the unsigned mean";
      return false;
    }
    if (!options.alpha) alpha = w.alpha;
    if (!options.lambda) lambda = w.lambda;
  }
  Edges edges;
  if (!mesh_edges(positions, faces, edges, error)) return false;
  const std::vector<Hinge>& hinges = edges.hinges;

  // The system I + alpha R^T R + beta D^T D couples the four vertices of each hinge: its pattern
  // is fixed, so CHOLMOD analyses it once and each iteration only refactors. `slot` maps each
  // hinge's ordered vertex pairs onto the stored lower triangle (-1: the upper one).
  const Eigen::Index n = positions.rows();
  Sparse system(n, n);
  {
    std::vector<Eigen::Triplet<double>> pattern;
    pattern.reserve(n + 10 * hinges.size());
    for (Eigen::Index i = 0; i < n; ++i) pattern.emplace_back(i, i, 0.0);
    for (const Hinge& h : hinges)
      for (int a : h.v)
        for (int b : h.v)
          if (a >= b) pattern.emplace_back(a, b, 0.0);
    system.setFromTriplets(pattern.begin(), pattern.end());
  }
  const auto slot_of = [&](int row, int col) {
    const int* first = system.innerIndexPtr() + system.outerIndexPtr()[col];
    const int* last = system.innerIndexPtr() + system.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(first, last, row) - system.innerIndexPtr());
  };
  std::vector<std::array<int, 16>> slots(hinges.size());
  for (size_t e = 0; e < hinges.size(); ++e)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int row = hinges[e].v[a], col = hinges[e].v[b];
        slots[e][4 * a + b] = row >= col ? slot_of(row, col) : -1;
      }
  std::vector<int> diagonal(n);
  for (Eigen::Index i = 0; i < n; ++i) diagonal[i] = slot_of(static_cast<int>(i), static_cast<int>(i));

  Eigen::CholmodDecomposition<Sparse, Eigen::Lower> solver;
  solver.analyzePattern(system);
  if (solver.info() != Eigen::Success) {
    error = "CHOLMOD could not analyse the system";
    return false;
  }

  const Eigen::MatrixX3d target = positions;
  Eigen::MatrixX3d rhs(n, 3);
  Positions p = positions;
  int total = 0;
  for (double b = options.beta0; b < options.beta_max; b *= options.kappa) ++total;
  double beta = options.beta0;
  for (int iteration = 0; iteration < total; ++iteration, beta *= options.kappa, alpha *= options.alpha_decay) {
    double* value = system.valuePtr();
    std::fill(value, value + system.nonZeros(), 0.0);
    for (Eigen::Index i = 0; i < n; ++i) value[diagonal[i]] = 1;
    rhs = target;
    for (size_t e = 0; e < hinges.size(); ++e) {
      const Hinge& h = hinges[e];
      const std::array<double, 4> c = edge_operator(p, h);
      Eigen::RowVector3d d = Eigen::RowVector3d::Zero();
      for (int a = 0; a < 4; ++a) d += c[a] * p.row(h.v[a]);
      // delta: the edge's operator kept whole, or dropped to 0 (the L0 term's closed form).
      const bool kept = d.squaredNorm() >= lambda / beta;
      for (int a = 0; a < 4; ++a) {
        if (kept) rhs.row(h.v[a]) += beta * c[a] * d;
        for (int b = 0; b < 4; ++b)
          if (slots[e][4 * a + b] >= 0)
            value[slots[e][4 * a + b]] += alpha * kRegulariser[a] * kRegulariser[b] + beta * c[a] * c[b];
      }
    }
    solver.factorize(system);
    if (solver.info() != Eigen::Success) {
      error = "the Cholesky factorisation failed at iteration " + std::to_string(iteration + 1);
      return false;
    }
    p = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !p.allFinite()) {
      error = "the linear solve failed at iteration " + std::to_string(iteration + 1);
      return false;
    }
    if (progress) progress((iteration + 1.0) / total);
  }
  if (!check_result_positions(positions, p, error)) return false;
  result.swap(p);
  return true;
}

}  // namespace hht
