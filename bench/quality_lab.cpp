// Scratch lab for the smoothing quality work (issue 7): noisy copies of a clean mesh, several
// candidate smoothers, E_a / RMS / flips against the clean mesh.
#include "bench_util.h"
#include "signal/emd.h"
#include "cycle/hamiltonian_cycle.h"
#include "cycle/cycle_decomposition.h"
#include "cycle/cycle_signal.h"
#include "signal/noise_estimate.h"
#include "evaluation/denoise_metrics.h"
#include "evaluation/gaussian_noise.h"
#include "mesh/mean_curvature.h"
#include "mesh/cotangent_laplacian.h"
#include "mesh/vertex_normals.h"
#include "mesh/vertex_adjacency.h"
#include "mesh/uniform_laplacian.h"
#include "reconstruction/taubin_smoothing.h"
#include "reconstruction/biharmonic_low_pass.h"
#include "filters/spectral_mesh_filter.h"
#include "filters/guided_normal_denoise.h"
#include "filters/sd_normal_denoise.h"
#include "filters/l0_denoise.h"
#include "filters/feature_preserving_denoise.h"
#include "filters/noise_adaptive_smoothing.h"
#include "reconstruction/normal_vertex_update.h"
#include "reconstruction/flip_guard.h"
#include "mesh/sharp_features.h"
#include "mesh/crease_contrast.h"
#include "mesh/hinge_heights.h"
#include "filters/spike_removal.h"
#include "reconstruction/recorrupted_risk.h"
#include "mesh/tangential_noise.h"
#include "mesh/faces_near_creases.h"

#include <Eigen/SparseCholesky>

#include <cstdio>
#include <random>
#include <map>
#include <set>
#include <algorithm>
#include <chrono>
#include <array>
#include <functional>

using namespace hht;

namespace {

Positions face_normals(const Positions& p, const Faces& f) {
  Positions n(f.rows(), 3);
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    Eigen::Vector3d a = p.row(f(i, 0)), b = p.row(f(i, 1)), c = p.row(f(i, 2));
    Eigen::Vector3d x = (b - a).cross(c - a);
    double l = x.norm();
    n.row(i) = l > 0 ? Eigen::Vector3d(x / l) : Eigen::Vector3d::Zero();
  }
  return n;
}

struct Score {
  double ea, rms;
  int flips;
  int new_flips;  // over the faces not folded in the clean mesh (the harness's count)
};

std::vector<char> g_clean_folded;  // set in main

Score score(const Positions& v, const Positions& clean, const Faces& f) {
  const double diag = (clean.colwise().maxCoeff() - clean.colwise().minCoeff()).norm();
  Positions a = face_normals(v, f), b = face_normals(clean, f);
  int flips = 0;
  int new_flips = 0;
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    flips += a.row(i).dot(b.row(i)) < 0;
    new_flips += a.row(i).dot(b.row(i)) < 0 && !(size_t(i) < g_clean_folded.size() && g_clean_folded[i]);
  }
  return {mean_face_normal_error_degrees(v, clean, f),
          1e4 * std::sqrt((v - clean).rowwise().squaredNorm().mean()) / diag, flips, new_flips};
}

Eigen::SparseMatrix<double> uniform_laplacian(const Faces& f, int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      int a = f(i, k), b = f(i, (k + 1) % 3);
      t.emplace_back(a, b, 1.0);
      t.emplace_back(b, a, 1.0);
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) it.valueRef() = 1.0;
  Eigen::VectorXd deg = A * Eigen::VectorXd::Ones(n);
  Eigen::SparseMatrix<double> L(n, n);
  std::vector<Eigen::Triplet<double>> u;
  for (int k = 0; k < A.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) u.emplace_back(it.row(), it.col(), -1.0 / deg[it.row()]);
  for (int i = 0; i < n; ++i) u.emplace_back(i, i, 1.0);
  L.setFromTriplets(u.begin(), u.end());
  return L;
}

Positions taubin(const Positions& p, const Faces& f, int steps, double lambda, double mu) {
  return taubin_smoothing(vertex_adjacency(f, static_cast<int>(p.rows())), p, steps, lambda, mu);
}

// Taubin steps whose tangential part (w.r.t. the current vertex normals) is scaled by tau.
Positions taubin_damped(Positions p, const Faces& f, int steps, double lambda, double mu, double tau) {
  Eigen::SparseMatrix<double> L = uniform_laplacian(f, p.rows());
  std::string err;
  auto move = [&](double w) {
    MeanCurvature mc;
    mean_curvature(p, f, mc, err);
    Positions d = -w * Positions(L * p);
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
      Eigen::RowVector3d nn = mc.normals.row(i);
      double a = d.row(i).dot(nn);
      d.row(i) = a * nn + tau * (d.row(i) - a * nn);
    }
    p += d;
  };
  for (int s = 0; s < steps; ++s) {
    move(lambda);
    move(mu);
  }
  return p;
}

std::vector<std::vector<int>> adjacency(const Faces& f, int n) {
  std::vector<std::vector<int>> a(n);
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) {
      a[f(i, k)].push_back(f(i, (k + 1) % 3));
      a[f(i, (k + 1) % 3)].push_back(f(i, k));
    }
  for (auto& v : a) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  return a;
}

// Each vertex of `base` moved along base's normal onto a weighted quadric fitted to the
// `data` positions of its k-ring.
// Patches grown breadth-first from the lowest unassigned vertex, `size` vertices at most each:
// each vertex's patch index; `count` gets their number.
std::vector<int> breadth_first_patches(const std::vector<std::vector<int>>& adj, int size, int& count) {
  const int n = static_cast<int>(adj.size());
  std::vector<int> patch(n, -1);
  count = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (patch[seed] >= 0) continue;
    std::vector<int> queue{seed};
    patch[seed] = count;
    for (size_t head = 0; head < queue.size() && int(queue.size()) < size; ++head)
      for (int j : adj[queue[head]])
        if (patch[j] < 0 && int(queue.size()) < size) { patch[j] = count; queue.push_back(j); }
    ++count;
  }
  return patch;
}

Positions quadric_projection(const Positions& base, const Positions& data, const Faces& f, int rings, double width) {
  const int n = base.rows();
  auto adj = adjacency(f, n);
  MeanCurvature mb;
  std::string err;
  mean_curvature(base, f, mb, err);
  Positions out = base;
  std::vector<int> mark(n, -1), ring;
  for (int i = 0; i < n; ++i) {
    ring.assign(1, i);
    mark[i] = i;
    size_t begin = 0;
    for (int r = 0; r < rings; ++r) {
      size_t end = ring.size();
      for (size_t q = begin; q < end; ++q)
        for (int j : adj[ring[q]])
          if (mark[j] != i) { mark[j] = i; ring.push_back(j); }
      begin = end;
    }
    Eigen::Vector3d nn = mb.normals.row(i).transpose();
    Eigen::Vector3d u = nn.unitOrthogonal(), w = nn.cross(u);
    Eigen::Vector3d c = base.row(i).transpose();
    double r2 = 0;
    for (int j : ring) r2 = std::max(r2, (data.row(j).transpose() - c).squaredNorm());
    const double s2 = width * width * r2;
    Eigen::MatrixXd A(ring.size(), 6);
    Eigen::VectorXd b(ring.size());
    for (size_t q = 0; q < ring.size(); ++q) {
      Eigen::Vector3d d = data.row(ring[q]).transpose() - c;
      double x = d.dot(u), y = d.dot(w), z = d.dot(nn);
      double wt = std::exp(-d.squaredNorm() / (2 * s2));
      A.row(q) << wt, wt * x, wt * y, wt * x * x, wt * x * y, wt * y * y;
      b[q] = wt * z;
    }
    if (ring.size() < 10) continue;
    Eigen::VectorXd coef = A.colPivHouseholderQr().solve(b);
    out.row(i) += coef[0] * nn.transpose();
  }
  return out;
}

// min ||L x||^2 + sum_i (x_i - v_i)^T W_i (x_i - v_i), W_i = mn^2 n n^T + mt^2 (I - n n^T).
Positions ls_aniso(const Eigen::SparseMatrix<double>& L, const Positions& v, const Positions& normals, double mn, double mt) {
  const int n = v.rows();
  Eigen::SparseMatrix<double> K = L.transpose() * L;
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < K.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, k); it; ++it)
      for (int c = 0; c < 3; ++c) t.emplace_back(3 * it.row() + c, 3 * it.col() + c, it.value());
  Eigen::VectorXd b(3 * n);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d nn = normals.row(i).transpose();
    Eigen::Matrix3d W = mn * mn * nn * nn.transpose() + mt * mt * (Eigen::Matrix3d::Identity() - nn * nn.transpose());
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) t.emplace_back(3 * i + r, 3 * i + c, W(r, c));
    b.segment<3>(3 * i) = W * v.row(i).transpose();
  }
  Eigen::SparseMatrix<double> A(3 * n, 3 * n);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> s(A);
  Eigen::VectorXd x = s.solve(b);
  Positions out(n, 3);
  for (int i = 0; i < n; ++i) out.row(i) = x.segment<3>(3 * i).transpose();
  return out;
}

// Face normals averaged over faces sharing a vertex (area weighted), `passes` times.
Positions smoothed_face_normals(const Positions& p, const Faces& f, int passes) {
  const int n = p.rows();
  Positions fn(f.rows(), 3);
  Eigen::VectorXd area(f.rows());
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    Eigen::Vector3d a = p.row(f(i, 0)), b = p.row(f(i, 1)), c = p.row(f(i, 2));
    Eigen::Vector3d x = (b - a).cross(c - a);
    area[i] = 0.5 * x.norm();
    fn.row(i) = x.normalized();
  }
  std::vector<std::vector<int>> vf(n);
  for (Eigen::Index i = 0; i < f.rows(); ++i)
    for (int k = 0; k < 3; ++k) vf[f(i, k)].push_back(i);
  for (int s = 0; s < passes; ++s) {
    Positions vn = Positions::Zero(n, 3);
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      for (int k = 0; k < 3; ++k) vn.row(f(i, k)) += area[i] * fn.row(i);
    Positions next(f.rows(), 3);
    for (Eigen::Index i = 0; i < f.rows(); ++i) {
      Eigen::RowVector3d acc = Eigen::RowVector3d::Zero();
      for (int k = 0; k < 3; ++k) acc += vn.row(f(i, k));
      next.row(i) = acc.normalized();
    }
    fn = next;
  }
  return fn;
}

// min ||L x - d||^2 + mu^2 ||x - v||^2
Positions ls_solve(const Eigen::SparseMatrix<double>& L, const Positions& d, const Positions& v, double mu) {
  Eigen::SparseMatrix<double> I(L.rows(), L.rows());
  I.setIdentity();
  Eigen::SparseMatrix<double> A = Eigen::SparseMatrix<double>(L.transpose() * L) + mu * mu * I;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> s(A);
  Positions out(v.rows(), 3);
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd b = L.transpose() * d.col(k) + mu * mu * v.col(k);
    out.col(k) = s.solve(b);
  }
  return out;
}

// Low-pass (gain 0 above cutoff) of a per-vertex signal, averaged over `cycles` cycles.
Eigen::VectorXd hht_lowpass(const Eigen::VectorXd& s, const Faces& f, int n, int cycles, double cutoff) {
  Eigen::VectorXd acc = Eigen::VectorXd::Zero(n);
  std::string err;
  for (int k = 0; k < cycles; ++k) {
    CycleOptions co;
    co.seed = 7919 * k;
    HamiltonianCycle c;
    hamiltonian_cycle(f, n, co, c, err);
    CycleDecomposition d;
    decompose_along_cycle(c, s, EmdOptions{}, d, err);
    compute_spectra(d);
    acc += filtered_on_vertices(c, d, {cutoff, 0.5, false}, 0.0, f, s);
  }
  return acc / cycles;
}

}  // namespace

// The adaptive smoothing's options with the lab's knobs (LAB_NOSELECT, LAB_CAP, LAB_MUSCALE,
// LAB_WEAKER, LAB_FIRST, LAB_NOBORDERS) applied: every mode runs the same filter.
NoiseAdaptiveSmoothingOptions lab_options() {
  NoiseAdaptiveSmoothingOptions o;
  o.select_cutoff = !std::getenv("LAB_NOSELECT");
  if (const char* cap = std::getenv("LAB_CAP")) o.tangential_cap = std::atof(cap);
  if (const char* ms = std::getenv("LAB_MUSCALE")) o.mu_scale = std::atof(ms);
  if (const char* wa = std::getenv("LAB_WEAKER")) o.weaker_allowed = std::atof(wa);
  if (const char* g = std::getenv("LAB_FIRST")) o.first_order = std::atof(g);
  if (const char* b = std::getenv("LAB_CVBIAS")) o.selection_bias = std::atof(b);
  if (std::getenv("LAB_NOBORDERS")) o.hold_borders = false;  // border vertices may move across their border (before item 35)
  if (const char* x = std::getenv("LAB_GIVEN")) o.noise = std::atof(x);  // the noise given (sigma / mean edge)
  if (std::getenv("LAB_SURE")) o.unbiased_risk = true;  // with LAB_GIVEN: the cut-off by Stein's risk
  if (const char* x = std::getenv("LAB_STRONGEST")) o.strongest_selected = std::atof(x);
  if (const char* x = std::getenv("LAB_MOVERADIUS")) o.move_radius = std::atof(x);
  if (std::getenv("LAB_NOPASS")) o.face_normal_pass = false;  // item 20's face-normal pass off
  if (std::getenv("LAB_NOSLIDE")) o.taubin_slide = false;  // item 22's Taubin slide off
  if (std::getenv("LAB_NOTSHARE")) o.tangential_share = false;
  if (std::getenv("LAB_NOSPIKES")) o.remove_scattered_spikes = false;  // item 26's spike removal off  // item 21's tangential share off
  if (const char* x = std::getenv("LAB_FINISH")) o.forced_finish = std::atoi(x);  // step 4b's finish forced (bits: 1 slide, 2 pass)
  if (const char* x = std::getenv("LAB_COPYSCALE")) o.copy_noise_scale = std::atof(x);  // the recorrupted copies' noise scaled
  return o;
}

// The numbers of a comma-separated list in an environment variable (none if it is unset).
std::vector<double> list_from_env(const char* name) {
  std::vector<double> values;
  if (const char* list = std::getenv(name))
    for (const char* c = list; *c;) {
      char* end;
      values.push_back(std::strtod(c, &end));
      c = *end ? end + 1 : end;
    }
  return values;
}

// The noise estimate the smoothing starts from, sigma / mean edge.
double estimated_sigma(const Positions& p, const Faces& f) {
  std::string err;
  HamiltonianCycle cycle;
  NoiseEstimate estimate;
  if (!hamiltonian_cycle(f, static_cast<int>(p.rows()), CycleOptions{}, cycle, err) ||
      !estimate_noise(p, f, cycle, EmdOptions{}, estimate, err))
    std::printf("  noise estimate failed: %s\n", err.c_str());
  return estimate.relative();
}

// Each face normal replaced by the area-weighted mean over the faces sharing a vertex with it,
// each weighted further by exp(-|n_g - n_f|^2 / 2 w^2) (w = infinity: the plain mean).
Positions averaged_face_normals(const Positions& p, const Faces& f, const std::vector<std::vector<int>>& faces_of, double width) {
  const Positions fn = face_normals(p, f);
  Positions averaged(f.rows(), 3);
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    std::vector<int> around;
    for (int k = 0; k < 3; ++k) around.insert(around.end(), faces_of[f(i, k)].begin(), faces_of[f(i, k)].end());
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (int g : around) {
      const Eigen::Vector3d a = p.row(f(g, 0)), b = p.row(f(g, 1)), c = p.row(f(g, 2));
      sum += 0.5 * (b - a).cross(c - a).norm() * std::exp(-(fn.row(g) - fn.row(i)).squaredNorm() / (2 * width * width)) * fn.row(g);
    }
    averaged.row(i) = sum.normalized();
  }
  return averaged;
}

// Recorrupted copies (Pang et al. 2021): y1 = y + a z, y2 = y - z / a, z isotropic of `sigma`.
void recorrupted_copies(const Positions& y, double sigma, double alpha, int seed, Positions& y1, Positions& y2) {
  std::mt19937 r2(seed);
  std::normal_distribution<double> z(0, sigma);
  Positions zn(y.rows(), 3);
  for (Eigen::Index i = 0; i < y.rows(); ++i) for (int k = 0; k < 3; ++k) zn(i, k) = z(r2);
  y1 = y + alpha * zn;
  y2 = y - zn / alpha;
}

// The smoothing's last step: no vertex further than `radius` from the input.
void hold(Positions& out, const Positions& input, double radius) {
  for (Eigen::Index i = 0; i < out.rows(); ++i) {
    const Eigen::RowVector3d d = out.row(i) - input.row(i);
    if (d.norm() > radius) out.row(i) = input.row(i) + d * (radius / d.norm());
  }
}


// The denoiser's untangling smoothing at noise `sigma` (mean edges): the second-order filter at
// the noise law's cut-off, without cross-validation.
NoiseAdaptiveSmoothingOptions untangling_options(double sigma) {
  NoiseAdaptiveSmoothingOptions o;
  o.noise = sigma;
  o.select_cutoff = false;
  o.first_order = kUntangleFirstOrder;
  o.mu_scale = kUntangleMuScale;
  return o;
}

// Near-flat regions: grown over shared (manifold) edges from each face not yet taken, holding the
// faces whose unit normal `fn` stays within `degrees` of the seed's; their sizes in faces.
std::vector<int> flat_region_labels(const Positions& fn, const Faces& f, double degrees, std::vector<size_t>& sizes);
std::vector<size_t> flat_region_sizes(const Positions& fn, const Faces& f, double degrees) {
  std::vector<size_t> sizes;
  flat_region_labels(fn, f, degrees, sizes);
  return sizes;
}
std::vector<int> flat_region_labels(const Positions& fn, const Faces& f, double degrees, std::vector<size_t>& sizes) {
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (Eigen::Index g = 0; g < f.rows(); ++g)
    for (int k = 0; k < 3; ++k) {
      const int a = f(g, k), b = f(g, (k + 1) % 3);
      by_edge[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(g));
    }
  std::vector<std::vector<int>> nb(f.rows());
  for (const auto& [e, fs] : by_edge)
    if (fs.size() == 2) { nb[fs[0]].push_back(fs[1]); nb[fs[1]].push_back(fs[0]); }
  const double c = std::cos(degrees * M_PI / 180);
  std::vector<int> region(f.rows(), -1);
  sizes.clear();
  for (Eigen::Index s0 = 0; s0 < f.rows(); ++s0) {
    if (region[s0] >= 0) continue;
    std::vector<int> q{static_cast<int>(s0)};
    region[s0] = static_cast<int>(sizes.size());
    for (size_t k = 0; k < q.size(); ++k)
      for (int g : nb[q[k]])
        if (region[g] < 0 && fn.row(g).dot(fn.row(s0)) > c) { region[g] = region[s0]; q.push_back(g); }
    sizes.push_back(q.size());
  }
  return region;
}

// Share of the faces of `a` whose normal points against the same face's in `b`.
double turned_share(const Positions& a, const Positions& b, const Faces& f) {
  const Positions na = face_normals(a, f), nb = face_normals(b, f);
  int c = 0;
  for (Eigen::Index i = 0; i < f.rows(); ++i) c += na.row(i).dot(nb.row(i)) < 0;
  return double(c) / f.rows();
}

// The mean face-normal tilt that normal noise of `sigma` (length unit) gives each face: the
// gradient of the linear interpolant of the vertices' offsets, g ~ N(0, sigma^2 sum grad phi_i
// grad phi_i^T), angle atan|g|, its mean by 8 x 8 Gauss-Hermite nodes.
double predicted_noise_angle_degrees(const Positions& p, const Faces& f, double sigma) {
  static const double x[8] = {-2.930637420257244, -1.981656756695843, -1.157193712446780, -0.381186990207322,
                              0.381186990207322, 1.157193712446780, 1.981656756695843, 2.930637420257244};
  static const double w[8] = {0.000199604072211, 0.017077983007413, 0.207802325814892, 0.661147012558241,
                              0.661147012558241, 0.207802325814892, 0.017077983007413, 0.000199604072211};
  double total = 0;
  int counted = 0;
  for (Eigen::Index t = 0; t < f.rows(); ++t) {
    const Eigen::Vector3d a = p.row(f(t, 0)), b = p.row(f(t, 1)), c = p.row(f(t, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double area2 = n.norm();
    if (!(area2 > 0)) continue;
    const Eigen::Vector3d nn = n / area2;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    const Eigen::Vector3d e[3] = {c - b, a - c, b - a};
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d g = nn.cross(e[i]) / area2;  // grad phi_i, |.| = 1 / height_i
      cov += g * g.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov * sigma * sigma);
    const double l1 = std::sqrt(std::max(0.0, es.eigenvalues()[2])), l2 = std::sqrt(std::max(0.0, es.eigenvalues()[1]));
    double mean = 0;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) mean += w[i] * w[j] * std::atan(std::hypot(std::sqrt(2.0) * x[i] * l1, std::sqrt(2.0) * x[j] * l2));
    total += mean / M_PI;
    ++counted;
  }
  return counted ? total / counted * 180 / M_PI : 0;
}

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  if (argc < 3) return 1;
  Positions clean;
  Faces f;
  if (!bench::load_mesh(argv[1], clean, f)) return 1;
  const double level = std::atof(argv[2]);
  const int n = clean.rows();
  const double h = mean_edge_length(clean, f);
  std::mt19937 rng(std::getenv("LAB_SEED") ? std::atoi(std::getenv("LAB_SEED")) : 11);
  std::normal_distribution<double> g(0, level * h);
  Positions noisy = clean;
  const bool along_normals = argc > 4 && std::string(argv[4]) == "normal";
  if (along_normals) {
    noisy = add_gaussian_noise(clean, f, 100 * level, NoiseDirection::Normal, std::getenv("LAB_SEED") ? std::atoi(std::getenv("LAB_SEED")) : 11);
  } else if (argc > 4 && std::string(argv[4]) == "axis") {  // a scanner's line of sight: along one fixed direction (1, 2, 3)/|.|
    const Eigen::RowVector3d axis = Eigen::RowVector3d(1, 2, 3).normalized();
    for (int i = 0; i < n; ++i) noisy.row(i) += g(rng) * axis;
  } else if (argc > 4 && std::string(argv[4]) == "impulsive") {  // impulsive: a share of the vertices (LAB_IMPULSE, 0.5) moved along the normals (LAB_IMPULSERANDOM: random directions)
    noisy = add_gaussian_noise(clean, f, 100 * level, std::getenv("LAB_IMPULSERANDOM") ? NoiseDirection::Random : NoiseDirection::Normal,
                               std::getenv("LAB_SEED") ? std::atoi(std::getenv("LAB_SEED")) : 11,
                               std::getenv("LAB_IMPULSE") ? std::atof(std::getenv("LAB_IMPULSE")) : 0.5);
  } else if (argc > 4 && std::string(argv[4]) == "random") {  // the paper's model: a random direction per vertex
    noisy = add_gaussian_noise(clean, f, 100 * level, NoiseDirection::Random, std::getenv("LAB_SEED") ? std::atoi(std::getenv("LAB_SEED")) : 11);
  } else {
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) noisy(i, k) += g(rng);
  }
  if (const char* share = std::getenv("LAB_OUTLIERS")) {  // mixed noise: a share of the vertices moved by half a mean edge more, along the normals
    noisy = add_gaussian_noise(noisy, f, 50, NoiseDirection::Normal, 1000 + (std::getenv("LAB_SEED") ? std::atoi(std::getenv("LAB_SEED")) : 11),
                               std::atof(share));
  }
  if (const char* file = std::getenv("LAB_NOISYFILE")) {  // a given noisy mesh of the same connectivity (e.g. a meshlabserver run's input)
    Faces nf;
    if (!bench::load_mesh(file, noisy, nf) || nf.rows() != f.rows() || noisy.rows() != n) return 1;
  }
  if (std::getenv("LAB_GIVENLOG")) {  // the noise given as HHT: Add Gaussian Noise logs it: along the normals, in the noisy mesh's edge
    const std::string given = std::to_string(noise_along_normals(clean, noisy, f));
    setenv("LAB_GIVEN", given.c_str(), 1);
  }
  if (std::getenv("LAB_COPYTRUE")) {  // step 4b's copies at the noise's true RMS along the normals, not the estimate's
    const std::string scale = std::to_string(noise_along_normals(clean, noisy, f) / estimated_sigma(noisy, f));
    std::printf("  copy scale %s\n", scale.c_str());
    setenv("LAB_COPYSCALE", scale.c_str(), 1);
  }
  // LAB_CREASESPLIT=DEG: E_a also over the faces near the clean mesh's creases (a vertex on an edge bent more than DEG) and the rest
  const std::vector<unsigned char> near_crease =
      std::getenv("LAB_CREASESPLIT")
          ? faces_near_creases(dihedral_angles(clean, f), f, n, std::atof(std::getenv("LAB_CREASESPLIT")))
          : std::vector<unsigned char>();
  // LAB_CREASEANGLES=1 (with LAB_CREASESPLIT): each face's class by the sharpest clean crease at
  // its vertices, to tell shallow creases from right-angled ones
  constexpr int kCreaseClasses = 5;
  std::vector<unsigned char> crease_class;
  if (!near_crease.empty() && std::getenv("LAB_CREASEANGLES")) {
    std::vector<double> sharpest(n, 0.0);
    for (const DihedralAngle& d : dihedral_angles(clean, f)) {
      const double deg = d.radians * 180 / M_PI;
      if (deg <= std::atof(std::getenv("LAB_CREASESPLIT"))) continue;
      sharpest[d.a] = std::max(sharpest[d.a], deg);
      sharpest[d.b] = std::max(sharpest[d.b], deg);
    }
    crease_class.resize(f.rows());
    for (Eigen::Index i = 0; i < f.rows(); ++i) {
      const double deg = std::max({sharpest[f(i, 0)], sharpest[f(i, 1)], sharpest[f(i, 2)]});
      crease_class[i] = deg <= 0 ? 0 : deg <= 60 ? 1 : deg <= 80 ? 2 : deg <= 100 ? 3 : 4;
    }
  }
  auto show = [&](const char* name, const Positions& p) {
    Score s = score(p, clean, f);
    std::printf("  %-28s E_a %6.2f  rms %6.1f  flips %d (%d not folded in clean)\n", name, s.ea, s.rms, s.flips, s.new_flips);
    if (near_crease.empty()) return;
    const Positions a = unit_face_normals(p, f), b = unit_face_normals(clean, f);
    double sum[2] = {0, 0};
    int count[2] = {0, 0};
    for (Eigen::Index i = 0; i < f.rows(); ++i) {
      const int k = near_crease[i] ? 1 : 0;
      sum[k] += std::acos(std::clamp(a.row(i).dot(b.row(i)), -1.0, 1.0)) * 180 / M_PI;
      ++count[k];
    }
    std::printf("      near creases %d faces E_a %.2f (share of the sum %.2f); elsewhere %d faces E_a %.2f\n", count[1],
                sum[1] / std::max(1, count[1]), sum[1] / (sum[0] + sum[1]), count[0], sum[0] / std::max(1, count[0]));
    if (!crease_class.empty()) {  // LAB_CREASEANGLES: the faces by the sharpest clean crease at their vertices
      double class_sum[kCreaseClasses] = {0};
      int class_count[kCreaseClasses] = {0};
      for (Eigen::Index i = 0; i < f.rows(); ++i) {
        class_sum[crease_class[i]] += std::acos(std::clamp(a.row(i).dot(b.row(i)), -1.0, 1.0)) * 180 / M_PI;
        ++class_count[crease_class[i]];
      }
      std::printf("      by crease angle (none/30-60/60-80/80-100/100+ degrees): faces, E_a");
      for (int k = 0; k < kCreaseClasses; ++k) std::printf(" %d %.2f;", class_count[k], class_sum[k] / std::max(1, class_count[k]));
      std::printf("\n");
    }
  };
  std::printf("%s n=%d level %.2f\n", argv[1], n, level);
  if (argc > 3 && std::string(argv[3]) == "I") {  // the noise estimates only: IMF, and |hinge height| quantiles over |N(0,1)|'s
    auto read = [&](const Positions& p) {
      std::string err;
      HamiltonianCycle cycle;
      hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
      NoiseEstimate est;
      estimate_noise(p, f, cycle, EmdOptions{}, est, err);
      std::vector<double> hs = hinge_heights(p, f, vertex_adjacency(f, n));
      for (double& x : hs) x = std::abs(x) / h;
      std::sort(hs.begin(), hs.end());
      std::printf(" imf %.4f hinge", est.imf_sigma / h);
      for (double q : {0.02, 0.05, 0.1, 0.2, 0.3, 0.5}) {
        const double x = hs[static_cast<size_t>(q * (hs.size() - 1))];
        std::printf(" %.4f", x / folded_normal_quantile(q));
      }
      std::printf(" zero %.3f", double(std::count(hs.begin(), hs.end(), 0.0)) / hs.size());
      // Mixture fit of the low half of the CDF: q = p erf(x / (sigma sqrt 2)) + c1 x + c2 x^2 (flat hinges: pure noise;
      // the others spread wider), sigma on a log grid, (p, c1, c2) by least squares.
      const int K = 50;
      std::vector<double> xs(K), qs(K);
      for (int k = 0; k < K; ++k) {
        qs[k] = 0.5 * (k + 1) / K;
        xs[k] = hs[static_cast<size_t>(qs[k] * (hs.size() - 1))];
      }
      double best = 1e300, best_sigma = 0, best_p = 0;
      const double top = xs[K - 1];
      for (int g = 0; g < 120 && top > 0; ++g) {
        const double sg = top * std::pow(10.0, -3.0 + 3.5 * g / 119.0);
        Eigen::MatrixXd A(K, 3);
        Eigen::VectorXd b(K);
        for (int k = 0; k < K; ++k) {
          A(k, 0) = std::erf(xs[k] / (sg * std::sqrt(2.0)));
          A(k, 1) = xs[k] / top;
          A(k, 2) = (xs[k] / top) * (xs[k] / top);
          b[k] = qs[k];
        }
        Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
        if (c[0] < 0.02 || c[0] > 1.05 || c[1] < 0) continue;
        const double r = (A * c - b).squaredNorm();
        if (r < best) { best = r; best_sigma = sg; best_p = c[0]; }
      }
      std::printf(" fit %.4f p %.2f", best_sigma, best_p);
    };
    if (std::getenv("LAB_FLATHINGES")) {  // the noisy heights of the clean mesh's exactly flat hinges, by divisor
      const VertexAdjacency adj = vertex_adjacency(f, n);
      std::map<std::pair<int, int>, std::vector<int>> opposite;
      for (Eigen::Index i = 0; i < f.rows(); ++i)
        for (int k = 0; k < 3; ++k) {
          int a = f(i, (k + 1) % 3), b = f(i, (k + 2) % 3);
          opposite[{std::min(a, b), std::max(a, b)}].push_back(f(i, k));
        }
      auto hinge = [&](const Positions& p, int a, int b, int c, int d, double& divisor) {
        const Eigen::Vector3d A = p.row(a), B = p.row(b), C = p.row(c), D = p.row(d);
        Eigen::Vector3d nn = (B - A).cross(C - A);
        const double ta = nn.norm();
        nn /= ta;
        const double height = nn.dot(D - A);
        const Eigen::Vector3d foot = D - height * nn;
        const double beta = (foot - A).cross(C - A).dot(nn) / ta, gamma = (B - A).cross(foot - A).dot(nn) / ta, alpha = 1 - beta - gamma;
        divisor = std::sqrt(1 + alpha * alpha + beta * beta + gamma * gamma);
        return height / divisor;
      };
      std::vector<std::vector<double>> bins(4);
      for (const auto& [e, opp] : opposite) {
        if (opp.size() != 2) continue;
        double dv;
        const double hc = hinge(clean, e.first, e.second, opp[0], opp[1], dv);
        if (!(std::abs(hc) < 1e-9 * h)) continue;
        const double hn = hinge(noisy, e.first, e.second, opp[0], opp[1], dv) / h;
        bins[dv < 1.5 ? 0 : dv < 3 ? 1 : dv < 10 ? 2 : 3].push_back(hn * hn);
      }
      for (int b = 0; b < 4; ++b) {
        double m = 0;
        for (double x : bins[b]) m += x;
        std::printf("  divisor bin %d: %zu flat hinges, rms/true %.3f\n", b, bins[b].size(), bins[b].empty() ? 0 : std::sqrt(m / bins[b].size()) / level);
      }
    }
    std::printf("clean");
    read(clean);
    std::printf(" | noisy");
    read(noisy);
    std::printf(" | true %.3f\n", level);
    return 0;
  }
  {
    const Positions vn = summed_area_vectors(clean, f);  // unnormalised, as the harness sums them
    const Positions fn = face_normals(clean, f);
    int folded = 0;
    g_clean_folded.assign(f.rows(), 0);
    for (Eigen::Index i = 0; i < f.rows(); ++i) {
      Eigen::RowVector3d s = vn.row(f(i, 0)) + vn.row(f(i, 1)) + vn.row(f(i, 2));
      g_clean_folded[i] = fn.row(i).dot(s) < 0;
      folded += g_clean_folded[i];
    }
    std::printf("  clean faces folded against their vertex normals: %d\n", folded);
  }
  show("noisy", noisy);
  show("taubin3", taubin(noisy, f, 3, 0.5, -0.53));
  show("taubin5", taubin(noisy, f, 5, 0.5, -0.53));
  show("taubin10", taubin(noisy, f, 10, 0.5, -0.53));
  show("taubin20", taubin(noisy, f, 20, 0.5, -0.53));
  show("taubin40", taubin(noisy, f, 40, 0.5, -0.53));

  {
    MeanCurvature mc;
    std::string err;
    mean_curvature(clean, f, mc, err);
    const Positions& nc = mc.normals;
    auto split = [&](const Positions& p, bool keep_normal) {
      Positions out = clean;
      for (int i = 0; i < n; ++i) {
        Eigen::RowVector3d dlt = p.row(i) - clean.row(i);
        Eigen::RowVector3d nn = nc.row(i) * dlt.dot(nc.row(i));
        out.row(i) += keep_normal ? nn : Eigen::RowVector3d(dlt - nn);
      }
      return out;
    };
    show("O noise normal part", split(noisy, true));
    show("O noise tangential part", split(noisy, false));
    Positions t = taubin(noisy, f, 10, 0.5, -0.53);
    show("O taubin normal part", split(t, true));
    show("O taubin tangential part", split(t, false));
  }
  if (argc > 3 && std::string(argv[3]) == "x") return 0;
  if (argc > 3 && std::string(argv[3]) == "t") {
    for (double tau : {0.0, 0.3, 0.6})
      for (int steps : {3, 5, 10, 20}) {
        char name[64];
        std::snprintf(name, sizeof name, "taubin%d tau %.1f", steps, tau);
        show(name, taubin_damped(noisy, f, steps, 0.5, -0.53, tau));
      }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "d") {
    std::string err;
    Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    for (double tau : {0.5, 0.75, 1.0})
      for (double kappa : {0.7, 1.0}) {
        Positions p = noisy;
        int steps = 0;
        for (; steps < 60; ++steps) {
          for (double w : {0.5, -0.53}) {
            MeanCurvature mc;
            mean_curvature(p, f, mc, err);
            Positions d = -w * Positions(L * p);
            for (int i = 0; i < n; ++i) {
              Eigen::RowVector3d nn = mc.normals.row(i);
              double a = d.row(i).dot(nn);
              d.row(i) = a * nn + tau * (d.row(i) - a * nn);
            }
            p += d;
          }
          MeanCurvature mc;
          mean_curvature(p, f, mc, err);
          double r = 0;
          for (int i = 0; i < n; ++i) r += std::pow((p.row(i) - noisy.row(i)).dot(mc.normals.row(i)), 2);
          if (std::sqrt(r / n) >= kappa * level * h) { ++steps; break; }
        }
        char name[64];
        std::snprintf(name, sizeof name, "discrepancy tau %.2f k %.1f (%d)", tau, kappa, steps);
        show(name, p);
      }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "q") {
    for (int nt : {3, 10}) {
      Positions a = taubin(noisy, f, nt, 0.5, -0.53);
      for (int rings : {2, 3})
        for (double width : {0.5, 1.0}) {
          char name[64];
          std::snprintf(name, sizeof name, "T%d + quadric r%d w%.1f", nt, rings, width);
          show(name, quadric_projection(a, noisy, f, rings, width));
        }
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "n") {
    for (int nt : {3, 10}) {
      Positions a = taubin(noisy, f, nt, 0.5, -0.53);
      for (int passes : {1, 2, 4})
        for (int it : {5, 20}) {
          char name[64];
          std::snprintf(name, sizeof name, "T%d + nrm %d + vu %d", nt, passes, it);
          show(name, fit_vertices_to_normals(a, f, smoothed_face_normals(a, f, passes), it));
        }
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "l") {
    std::string err;
    const double scale = 1.0 / h;
    Positions v = noisy * scale;
    Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    for (double mu : {0.3, 0.4, 0.5, 0.7}) {
      Positions iso = ls_solve(L, Positions::Zero(n, 3), v, mu);
      char name[64];
      std::snprintf(name, sizeof name, "LS0 mu %.2f", mu);
      show(name, iso / scale);
      MeanCurvature mc;
      mean_curvature(iso, f, mc, err);
      for (double r : {1.5, 2.5}) {
        std::snprintf(name, sizeof name, "LSA mu %.2f tang x%.1f", mu, r);
        show(name, ls_aniso(L, v, mc.normals, mu, mu * r) / scale);
      }
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "r") {  // risk of the normal edge differences: truth against SURE
    std::string err;
    NoiseAdaptiveSmoothingOptions o = lab_options();
    Positions base;
    NoiseAdaptiveSmoothingReport rep;
    if (!noise_adaptive_smooth(noisy, f, o, base, rep, err)) return 1;
    const double sigma = std::getenv("LAB_TRUE_SIGMA") ? level : rep.sigma_used;
    const Eigen::RowVector3d centre = noisy.colwise().mean();
    const Positions v = (noisy.rowwise() - centre) / h, c = (clean.rowwise() - centre) / h;
    const Positions nn = area_weighted_vertex_normals(base, f);
    const VertexAdjacency adj = vertex_adjacency(f, n);
    std::mt19937 zr(5);
    Positions z(n, 3);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) z(i, k) = (zr() & 1) ? 1.0 : -1.0;
    auto edges = [&](auto&& fn) {
      for (int i = 0; i < n; ++i)
        for (const int* j = adj.begin(i); j != adj.end(i); ++j)
          if (*j > i) fn(i, *j);
    };
    std::printf("  sigma %.3f\n", sigma);
    for (double s : {0.25, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8, 4.0, 5.6, 8.0}) {
      const double mu = lab_options().mu_scale / std::sqrt(s * sigma);
      Positions x, az;
      BiharmonicLowPassReport br;
      biharmonic_low_pass(adj, v, mu, 0, 1e-7, x, br);
      biharmonic_low_pass(adj, z, mu, 0, 1e-7, az, br);
      Eigen::VectorXd a(n), t(n);
      for (int i = 0; i < n; ++i) {
        a(i) = nn.row(i).dot(x.row(i) - v.row(i));
        t(i) = nn.row(i).dot(x.row(i) - c.row(i));
      }
      double D = 0, T = 0, tr = 0, trk = 0;
      edges([&](int i, int j) {
        D += std::pow(a(i) - a(j), 2);
        T += std::pow(t(i) - t(j), 2);
        for (int k = 0; k < 3; ++k) tr += (z(i, k) - z(j, k)) * (az(i, k) - az(j, k)) / 3;
        trk += 2;
      });
      const double sure = D + 2 * sigma * sigma * tr - sigma * sigma * trk;
      const double gcv = D / std::pow(1 - tr / trk, 2);
      NoiseAdaptiveSmoothingOptions os;
      os.strength = s;
      Positions full;
      NoiseAdaptiveSmoothingReport r2;
      noise_adaptive_smooth(noisy, f, os, full, r2, err);
      Score sl = score((x * h).rowwise() + centre, clean, f), sf = score(full, clean, f);
      std::printf("  s %4.2f  true %9.1f  SURE %9.1f GCV %9.1f | linear E_a %6.2f rms %5.1f | NAS E_a %6.2f rms %5.1f\n", s, T, sure, gcv,
                  sl.ea, sl.rms, sf.ea, sf.rms);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "h") {  // dihedral angles of the adaptive smoothing's result
    std::string err;
    NoiseAdaptiveSmoothingOptions o = lab_options();
    Positions out;
    NoiseAdaptiveSmoothingReport r;
    if (!noise_adaptive_smooth(noisy, f, o, out, r, err)) return 1;
    const Positions fn = face_normals(out, f);
    std::map<std::pair<int, int>, int> first;
    std::vector<double> angles;
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = f(i, k), b = f(i, (k + 1) % 3);
        const auto key = std::minmax(a, b);
        auto it = first.find(key);
        if (it == first.end()) first[key] = static_cast<int>(i);
        else angles.push_back(std::acos(std::clamp(fn.row(i).dot(fn.row(it->second)), -1.0, 1.0)) * 180 / M_PI);
      }
    std::sort(angles.begin(), angles.end());
    auto q = [&](double p) { return angles[static_cast<size_t>(p * (angles.size() - 1))]; };
    std::printf("  dihedral q25 %.2f median %.2f q90 %.2f q98 %.2f  ratio98/50 %.2f  under1deg %.3f\n", q(0.25), q(0.5), q(0.9), q(0.98),
                q(0.98) / q(0.5), double(std::lower_bound(angles.begin(), angles.end(), 1.0) - angles.begin()) / angles.size());
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "v") {  // adaptive smoothing, then face normals averaged + vertex update
    std::string err;
    Positions nas;
    NoiseAdaptiveSmoothingReport r;
    noise_adaptive_smooth(noisy, f, lab_options(), nas, r, err);
    show("NAS", nas);
    show("taubin10", taubin(noisy, f, 10, 0.5, -0.53));
    {
      HamiltonianCycle c;
      hamiltonian_cycle(f, n, CycleOptions{}, c, err);
      NoiseEstimate after;
      estimate_noise(nas, f, c, EmdOptions{}, after, err);
      std::printf("  sigma %.3f, of the smoothing %.4f (ratio %.3f), mu %.3f%s\n", r.sigma_used, after.relative(), after.relative() / r.sigma_used,
                  r.mu, r.cutoff_selected ? " selected" : "");
    }
    std::vector<std::vector<int>> vf(n);
    for (Eigen::Index i = 0; i < f.rows(); ++i) for (int k = 0; k < 3; ++k) vf[f(i, k)].push_back(int(i));
    for (double width : {0.1, 0.2, 0.3, 0.5, 1e9}) {  // then 2 vertex update iterations and the smoothing's hold
      Positions out = fit_vertices_to_normals(nas, f, averaged_face_normals(nas, f, vf, width), 2);
      hold(out, noisy, kMoveRadius * r.sigma_used * h);
      char name[64];
      std::snprintf(name, sizeof name, "+ normal pass width %.1f", width);
      show(name, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "o") {  // filter order p: min ||L^p X||^2 + mu^2p ||X - V||^2, best mu (oracle), raw
    const double scale = 1.0 / h;
    const Positions v = noisy * scale;
    const Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    Eigen::SparseMatrix<double> Lp = L;
    for (int order = 1; order <= 4; ++order) {
      if (order > 1) Lp = Eigen::SparseMatrix<double>(Lp * L);
      double best = 1e9, best_mu = 0, best_rms = 0;
      for (double mu = 0.08; mu < 1.2; mu *= 1.12) {
        const Positions out = ls_solve(Lp, Positions::Zero(n, 3), v, std::pow(mu, order)) / scale;
        const Score s = score(out, clean, f);
        if (s.ea < best) best = s.ea, best_mu = mu, best_rms = s.rms;
      }
      std::printf("  order %d best mu %.3f  E_a %6.2f  rms %6.1f\n", order, best_mu, best, best_rms);
    }
    {  // mixed: min ||X - V||^2 + (||L X|| / m1)^2 + (||L^2 X|| / m2^2)^2
      const Eigen::SparseMatrix<double> L2 = L * L;
      Eigen::SparseMatrix<double> I(n, n);
      I.setIdentity();
      const Eigen::SparseMatrix<double> A1 = L.transpose() * L, A2 = L2.transpose() * L2;
      for (double ratio : {0.64, 0.8, 1.0, 1.25, 100.0}) {
      double best = 1e9, bm1 = 0, bm2 = 0, brms = 0;
        for (double m2 = 0.3; m2 < 2; m2 *= 1.08) {
          const double m1 = ratio * m2;
          Eigen::SparseMatrix<double> A = Eigen::SparseMatrix<double>(A1 / (m1 * m1) + A2 / std::pow(m2, 4)) + I;
          Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
          Positions out(n, 3);
          for (int k = 0; k < 3; ++k) out.col(k) = solver.solve(Eigen::VectorXd(v.col(k)));
          const Score s = score(out / scale, clean, f);
          if (s.ea < best) best = s.ea, bm1 = m1, bm2 = m2, brms = s.rms;
        }
      std::printf("  mixed ratio %.2f best m1 %.3f m2 %.3f  E_a %6.2f  rms %6.1f\n", ratio, bm1, bm2, best, brms);
      }
    }
    double best = 1e9, best_rms = 0;
    int best_steps = 0;
    for (int steps : {2, 3, 4, 5, 7, 10, 14, 20, 28, 40}) {
      const Score s = score(taubin(noisy, f, steps, 0.5, -0.53), clean, f);
      if (s.ea < best) best = s.ea, best_steps = steps, best_rms = s.rms;
    }
    std::printf("  taubin best steps %d  E_a %6.2f  rms %6.1f\n", best_steps, best, best_rms);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "R") {  // recorrupted-to-recorrupted risk of candidate pipelines against their true E_a
    std::string err;
    std::vector<std::vector<int>> vf(n);
    for (Eigen::Index i = 0; i < f.rows(); ++i) for (int k = 0; k < 3; ++k) vf[f(i, k)].push_back(int(i));
    auto pass = [&](const Positions& p, const Positions& input, double sigma) {
      Positions out = fit_vertices_to_normals(p, f, averaged_face_normals(p, f, vf, 1e9), 2);
      hold(out, input, kMoveRadius * sigma * h);
      return out;
    };
    auto run = [&](int which, const Positions& in) {
      NoiseAdaptiveSmoothingOptions o = lab_options();
      o.face_normal_pass = false;  // the candidates add their own
      o.taubin_slide = false;
      if (which == 2) o.tangential_cap = 1e9;
      Positions out;
      NoiseAdaptiveSmoothingReport r;
      noise_adaptive_smooth(in, f, o, out, r, err);
      if (which == 1) out = pass(out, in, r.sigma_used);
      if (which == 3) out = taubin(in, f, 10, 0.5, -0.53);
      return std::make_pair(out, r.sigma_used);
    };
    const Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    const double alpha = std::getenv("LAB_ALPHA") ? std::atof(std::getenv("LAB_ALPHA")) : 0.5;
    const char* names[] = {"NAS", "NAS + normal pass", "NAS uncapped", "taubin10"};
    const double sigma = run(0, noisy).second * h;
    for (int which = 0; which < 4; ++which) {
      const Positions truth_run = run(which, noisy).first;
      double lap = 0, pos = 0, ang = 0;
      const int draws = std::getenv("LAB_DRAWS") ? std::atoi(std::getenv("LAB_DRAWS")) : 3;
      const int seed0 = std::getenv("LAB_R2RSEED") ? std::atoi(std::getenv("LAB_R2RSEED")) : 100;
      for (int d = 0; d < draws; ++d) {
        Positions y1, y2;
        recorrupted_copies(noisy, sigma, alpha, seed0 + d, y1, y2);
        const Positions out = run(which, y1).first;
        lap += Positions(L * Positions(out - y2)).squaredNorm() / n;
        pos += (out - y2).squaredNorm() / n;
        ang += mean_face_normal_error_degrees(out, y2, f);
      }
      const Score s = score(truth_run, clean, f);
      std::printf("  %-20s true E_a %6.2f rms %5.1f | R2R lap %.5f pos %.5f ang %.2f\n", names[which], s.ea, s.rms, lap / draws / (h * h),
                  pos / draws / (h * h), ang / draws);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "Z") {  // the normal pass chosen by a recorrupted risk of the face normals
    // With y1 = y + a z, y2 = y - z / a (z of the estimated sigma), y2's area vectors are unbiased
    // for the clean ones (quadratic in independent noise), so sum_f w_f n_f(out(y1)) . A_f(y2),
    // w_f fixed per draw (1 / |A_f| of the smoothing of y1), estimates sum_f cos(angle to the clean
    // normal): the candidate with the larger sum has the smaller normal error.
    std::string err;
    std::vector<std::vector<int>> vf(n);
    for (Eigen::Index i = 0; i < f.rows(); ++i) for (int k = 0; k < 3; ++k) vf[f(i, k)].push_back(int(i));
    NoiseAdaptiveSmoothingOptions o = lab_options();
    o.face_normal_pass = false;  // the pass is the candidate here, applied after the whole smoothing
    o.taubin_slide = false;
    Positions nas;
    NoiseAdaptiveSmoothingReport r;
    noise_adaptive_smooth(noisy, f, o, nas, r, err);
    const double sigma = r.sigma_used * h;
    auto pass = [&](const Positions& p, const Positions& input) {
      Positions out = fit_vertices_to_normals(p, f, averaged_face_normals(p, f, vf, 1e9), 2);
      hold(out, input, kMoveRadius * sigma);
      return out;
    };
    const Positions nas_pass = pass(nas, noisy);
    const double alpha = std::getenv("LAB_ALPHA") ? std::atof(std::getenv("LAB_ALPHA")) : 0.5;
    const int draws = std::getenv("LAB_DRAWS") ? std::atoi(std::getenv("LAB_DRAWS")) : 3;
    const int seed0 = std::getenv("LAB_R2RSEED") ? std::atoi(std::getenv("LAB_R2RSEED")) : 100;
    const bool fixed_mu = std::getenv("LAB_FIXEDMU") != nullptr;  // the copies smoothed at the data's cut-off, no selection
    double gain = 0, gain_sq = 0, pos_gain = 0, pos_base = 0;
    for (int d = 0; d < draws; ++d) {
      Positions y1, y2;
      recorrupted_copies(noisy, sigma, alpha, seed0 + d, y1, y2);
      NoiseAdaptiveSmoothingOptions o1 = o;
      if (fixed_mu) o1.mu = r.mu;
      Positions s1;
      NoiseAdaptiveSmoothingReport r1;
      noise_adaptive_smooth(y1, f, o1, s1, r1, err);
      const Positions p1 = pass(s1, y1);
      const Positions ns = face_normals(s1, f), np = face_normals(p1, f);
      double g = 0;
      for (Eigen::Index i = 0; i < f.rows(); ++i) {
        const Eigen::RowVector3d a = y2.row(f(i, 0));
        const Eigen::RowVector3d A2 = (y2.row(f(i, 1)) - a).cross(y2.row(f(i, 2)) - a);
        const Eigen::RowVector3d b = s1.row(f(i, 0));
        const double w = 1.0 / std::max((s1.row(f(i, 1)) - b).cross(s1.row(f(i, 2)) - b).norm(), 1e-300);
        g += w * (np.row(i) - ns.row(i)).dot(A2);
      }
      g /= f.rows();
      gain += g;
      gain_sq += g * g;
      pos_gain += ((s1 - y2).squaredNorm() - (p1 - y2).squaredNorm()) / n / (h * h);
      pos_base += (s1 - y2).squaredNorm() / n / (h * h);
    }
    const double mean = gain / draws, sd = std::sqrt(std::max(0.0, gain_sq / draws - mean * mean));
    const Score a = score(nas, clean, f), b = score(nas_pass, clean, f);
    std::printf("  Z NAS %.2f / %.1f pass %.2f / %.1f | cos gain %.5f (sd %.5f) pos gain %.5f rel %.1f mu %.3f%s\n", a.ea, a.rms, b.ea, b.rms, mean, sd,
                pos_gain / draws, 1e4 * pos_gain / pos_base, r.mu, fixed_mu ? " fixed" : "");
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "S") {  // strength chosen by recorrupted-to-recorrupted face-normal angle, against the true E_a
    std::string err;
    NoiseAdaptiveSmoothingOptions base = lab_options();
    base.select_cutoff = false;
    Positions out;
    NoiseAdaptiveSmoothingReport r;
    const double sigma = estimated_sigma(noisy, f) * h;
    const double alpha = std::getenv("LAB_ALPHA") ? std::atof(std::getenv("LAB_ALPHA")) : 0.5;
    const int draws = 3;
    std::vector<Positions> y1s, y2s;
    for (int d = 0; d < draws; ++d) {
      Positions y1, y2;
      recorrupted_copies(noisy, sigma, alpha, 100 + d, y1, y2);
      y1s.push_back(y1);
      y2s.push_back(y2);
    }
    for (double strength : {0.35, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8}) {
      NoiseAdaptiveSmoothingOptions o = base;
      o.strength = strength;
      noise_adaptive_smooth(noisy, f, o, out, r, err);
      const Score truth = score(out, clean, f);
      double ang = 0, area = 0, area_weighted = 0;
      auto area_vector = [&](const Positions& p, Eigen::Index g) {
        const Eigen::RowVector3d a = p.row(f(g, 0));
        return Eigen::RowVector3d((p.row(f(g, 1)) - a).cross(p.row(f(g, 2)) - a));
      };
      for (int d = 0; d < draws; ++d) {
        o.noise = sigma / h;  // the same cut-off law as on the data
        Positions o1;
        noise_adaptive_smooth(y1s[d], f, o, o1, r, err);
        ang += mean_face_normal_error_degrees(o1, y2s[d], f);
        // area vectors are quadratic in the positions, so y2's are unbiased for the clean ones
        for (Eigen::Index g = 0; g < f.rows(); ++g) {
          const Eigen::RowVector3d a1 = area_vector(o1, g), a2 = area_vector(y2s[d], g);
          area += (a1 - a2).squaredNorm() / (h * h * h * h);
          area_weighted += (a1 - a2).squaredNorm() / std::max(a1.squaredNorm(), 1e-30);
        }
      }
      std::printf("  strength %.2f  true E_a %6.2f rms %5.1f | R2R angle %.3f area %.4f weighted %.4f\n", strength, truth.ea, truth.rms, ang / draws,
                  area / draws / f.rows(), area_weighted / draws / f.rows());
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "K") {  // the low-pass's normal part with clamped cotangent weights
    const double sig = estimated_sigma(noisy, f);
    const double scale = 1.0 / h;
    const Positions v = noisy * scale;
    const Eigen::SparseMatrix<double> Lu = uniform_laplacian(f, n);
    // row-normalised cotangent weights, clamped to a small positive floor (a proxy for the intrinsic Delaunay Laplacian)
    const Positions cot = corner_cotangents(noisy, f);
    std::map<std::pair<int, int>, double> w;
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      for (int k = 0; k < 3; ++k) {
        int a = f(i, (k + 1) % 3), b = f(i, (k + 2) % 3);
        if (a > b) std::swap(a, b);
        w[{a, b}] += 0.5 * cot(i, k);
      }
    double mean_w = 0;
    for (auto& [e, x] : w) mean_w += std::max(x, 0.0);
    mean_w /= w.size();
    const double floor_w = std::getenv("LAB_WFLOOR") ? std::atof(std::getenv("LAB_WFLOOR")) : 0.05;
    Eigen::VectorXd rowsum = Eigen::VectorXd::Zero(n);
    for (auto& [e, x] : w) {
      x = std::max(x, floor_w * mean_w);
      rowsum[e.first] += x;
      rowsum[e.second] += x;
    }
    std::vector<Eigen::Triplet<double>> t;
    for (auto& [e, x] : w) {
      t.emplace_back(e.first, e.second, -x / rowsum[e.first]);
      t.emplace_back(e.second, e.first, -x / rowsum[e.second]);
    }
    for (int i = 0; i < n; ++i) t.emplace_back(i, i, 1.0);
    Eigen::SparseMatrix<double> Lc(n, n);
    Lc.setFromTriplets(t.begin(), t.end());
    auto lowpass = [&](const Eigen::SparseMatrix<double>& L, double mu) {
      const Eigen::SparseMatrix<double> L2 = L * L;
      Eigen::SparseMatrix<double> A = Eigen::SparseMatrix<double>(L2.transpose() * L2) + mu * mu * Eigen::SparseMatrix<double>(L.transpose() * L);
      for (int i = 0; i < n; ++i) A.coeffRef(i, i) += std::pow(mu, 4);
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
      Positions out(n, 3);
      for (int k = 0; k < 3; ++k) out.col(k) = solver.solve(Eigen::VectorXd(std::pow(mu, 4) * v.col(k)));
      return out;
    };
    for (double st : {0.5, 0.7, 1.0, 1.4, 2.0}) {
      const double mu = kMuScale / std::sqrt(st * sig);
      const Positions xu = lowpass(Lu, mu), xc = lowpass(Lc, mu);
      const Positions nu = area_weighted_vertex_normals(xu, f);
      Positions comb = v;
      for (int i = 0; i < n; ++i) {
        const Eigen::RowVector3d du = xu.row(i) - v.row(i), dc = xc.row(i) - v.row(i), nn = nu.row(i);
        comb.row(i) = v.row(i) + nn * dc.dot(nn) + (du - nn * du.dot(nn));
      }
      char name[80];
      std::snprintf(name, sizeof name, "s%.1f uniform", st);
      show(name, xu / scale);
      std::snprintf(name, sizeof name, "s%.1f cot", st);
      show(name, xc / scale);
      std::snprintf(name, sizeof name, "s%.1f cot normal+uni tang", st);
      show(name, comb / scale);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "AX") {  // the noise covariance's shape from the heights' second differences along each normal
    const VertexAdjacency va = vertex_adjacency(f, n);
    const double hn = mean_edge_length(noisy, f);
    const Positions p = noisy / hn;
    // smoothed normals: area-weighted, averaged over 3 rings
    Positions nn = area_weighted_vertex_normals(p, f), next(n, 3);
    for (int sweep = 0; sweep < 3; ++sweep) {
      for (int i = 0; i < n; ++i) {
        Eigen::RowVector3d sum = nn.row(i);
        for (const int* j = va.begin(i); j != va.end(i); ++j) sum += nn.row(*j);
        next.row(i) = sum.normalized();
      }
      nn.swap(next);
    }
    Eigen::VectorXd ht(n);
    for (int i = 0; i < n; ++i) {
      Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
      for (const int* j = va.begin(i); j != va.end(i); ++j) c += p.row(*j);
      ht[i] = va.valence(i) ? nn.row(i).dot(p.row(i) - c / va.valence(i)) : 0;
    }
    std::vector<double> coefficient(n, 0.0);
    std::vector<int> touched;
    std::vector<std::pair<double, int>> values;
    for (int i = 0; i < n; ++i) {
      if (!va.valence(i) || va.boundary[i]) continue;
      bool ok = true;
      double m = 0;
      for (const int* j = va.begin(i); j != va.end(i); ++j) ok = ok && !va.boundary[*j], m += ht[*j];
      if (!ok) continue;
      const double gain = squared_laplacian_row_gain(va, i, coefficient, touched);
      const double d = ht[i] - m / va.valence(i);
      values.push_back({d * d / gain, i});
    }
    std::sort(values.begin(), values.end());
    const double trim = std::getenv("LAB_ZTRIM") ? std::atof(std::getenv("LAB_ZTRIM")) : 0.98;
    const size_t keep = size_t(trim * values.size());
    Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
    for (size_t k = 0; k < keep; ++k) {
      const Eigen::RowVector3d u = nn.row(values[k].second);
      Eigen::Matrix<double, 6, 1> row;
      row << u[0] * u[0], u[1] * u[1], u[2] * u[2], 2 * u[0] * u[1], 2 * u[0] * u[2], 2 * u[1] * u[2];
      ata += row * row.transpose();
      atb += row * values[k].first;
    }
    const Eigen::Matrix<double, 6, 1> x = ata.ldlt().solve(atb);
    Eigen::Matrix3d cov;
    cov << x[0], x[3], x[4], x[3], x[1], x[5], x[4], x[5], x[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    const Eigen::Vector3d ev = es.eigenvalues();
    const Eigen::Vector3d top = es.eigenvectors().col(2);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> cs(ata);
    std::printf("  AX eig %.5f %.5f %.5f ratio min/max %.3f mid/max %.3f top axis (%.2f %.2f %.2f) normals' cond %.1f\n", ev[0], ev[1], ev[2],
                ev[0] / ev[2], ev[1] / ev[2], top[0], top[1], top[2], cs.eigenvalues()[5] / std::max(1e-300, cs.eigenvalues()[0]));
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "P") {  // a cut-off per patch: oracle and cross-validation, against the global ones (raw filter)
    const double mu0 = lab_options().mu_scale / std::sqrt(estimated_sigma(noisy, f));
    const double scale = 1.0 / h;
    const Positions v = noisy * scale;
    const Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    const Eigen::SparseMatrix<double> L2 = L * L;
    const Eigen::SparseMatrix<double> A0 = L2.transpose() * L2;
    const std::vector<double> strengths{0.25, 0.35, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8, 4.0};
    const int S = int(strengths.size());
    auto solve_weights = [&](const Eigen::VectorXd& w, const Positions& rhs_base) {
      Eigen::SparseMatrix<double> A = A0;
      for (int i = 0; i < n; ++i) A.coeffRef(i, i) += w[i];
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
      Positions out(n, 3);
      for (int k = 0; k < 3; ++k) out.col(k) = solver.solve(Eigen::VectorXd(w.cwiseProduct(rhs_base.col(k))));
      return out;
    };
    Positions probes(n, 3);
    std::mt19937 pr(5);
    for (int i = 0; i < n; ++i) for (int k = 0; k < 3; ++k) probes(i, k) = (pr() & 1) ? 1.0 : -1.0;
    std::vector<Positions> xs, as;
    for (double st : strengths) {
      const Eigen::VectorXd w = Eigen::VectorXd::Constant(n, std::pow(mu0 / std::sqrt(st), 4));
      xs.push_back(solve_weights(w, v));
      as.push_back(solve_weights(w, probes));
    }
    const Positions normals = area_weighted_vertex_normals(xs[4], f);
    const auto adj = adjacency(f, n);
    const int patch_size = std::getenv("LAB_PATCH") ? std::atoi(std::getenv("LAB_PATCH")) : 400;
    int patches = 0;
    const std::vector<int> patch = breadth_first_patches(adj, patch_size, patches);
    // per patch and strength: GCV score parts and true E_a sums
    std::vector<std::vector<double>> d(patches, std::vector<double>(S, 0)), tka(patches, std::vector<double>(S, 0)),
        ea(patches, std::vector<double>(S, 0));
    std::vector<double> tk(patches, 0);
    std::vector<int> nf(patches, 0);
    const Positions cn = face_normals(clean, f);
    for (int s_ = 0; s_ < S; ++s_) {
      Eigen::VectorXd removed(n);
      for (int i = 0; i < n; ++i) removed[i] = normals.row(i).dot(xs[s_].row(i) - v.row(i));
      for (int i = 0; i < n; ++i)
        for (int j : adj[i]) {
          if (j < i) continue;
          const int p = patch[i];
          d[p][s_] += std::pow(removed[i] - removed[j], 2);
          tka[p][s_] += (probes.row(i) - probes.row(j)).dot(as[s_].row(i) - as[s_].row(j)) / 3;
          if (s_ == 0) tk[p] += 1;
        }
      const Positions fn = face_normals(xs[s_], f);
      for (Eigen::Index g = 0; g < f.rows(); ++g) {
        const int p = patch[f(g, 0)];
        ea[p][s_] += std::acos(std::clamp(fn.row(g).dot(cn.row(g)), -1.0, 1.0)) * 180 / M_PI;
        if (s_ == 0) ++nf[p];
      }
    }
    // a strength per patch -> per vertex log strength, smoothed over a few rings
    auto field = [&](const std::vector<int>& choice) -> Positions {
      Eigen::VectorXd ls(n);
      for (int i = 0; i < n; ++i) ls[i] = std::log(strengths[choice[patch[i]]]);
      for (int sweep = 0; sweep < 10; ++sweep) {
        Eigen::VectorXd next(n);
        for (int i = 0; i < n; ++i) {
          double sum = ls[i];
          for (int j : adj[i]) sum += ls[j];
          next[i] = sum / (1 + adj[i].size());
        }
        ls = next;
      }
      Eigen::VectorXd w(n);
      for (int i = 0; i < n; ++i) w[i] = std::pow(mu0, 4) / std::exp(2 * ls[i]);
      return solve_weights(w, v) / scale;
    };
    std::vector<int> oracle(patches), gcv(patches);
    std::vector<double> gtot(S, 0), dtot(S, 0), ttot(S, 0), ktot(S, 0);
    for (int p = 0; p < patches; ++p) {
      int bo = 0, bg = 0;
      double bgs = 1e300;
      for (int s_ = 0; s_ < S; ++s_) {
        if (ea[p][s_] < ea[p][bo]) bo = s_;
        const double kept = 1 - tka[p][s_] / (2 * tk[p]);
        const double g = kept > 0 ? d[p][s_] / (kept * kept) : 1e300;
        if (g < bgs) bgs = g, bg = s_;
        dtot[s_] += d[p][s_];
        ttot[s_] += tka[p][s_];
        ktot[s_] += 2 * tk[p];
      }
      oracle[p] = bo;
      gcv[p] = bg;
    }
    if (std::getenv("LAB_PATCHDUMP")) {  // per patch: the oracle's strength and the base smoothing's height energies
      const VertexAdjacency va = vertex_adjacency(f, n);
      const Eigen::VectorXd hb = one_ring_heights(xs[4], f, va), hn = one_ring_heights(v, f, va);
      std::vector<double> e1(patches, 0), e2(patches, 0), e3(patches, 0);
      std::vector<int> cnt(patches, 0);
      for (int i = 0; i < n; ++i) {
        double m = 0;
        for (int j : adj[i]) m += hb[j];
        m /= std::max<size_t>(1, adj[i].size());
        e1[patch[i]] += hb[i] * hb[i];
        e2[patch[i]] += (hb[i] - m) * (hb[i] - m);
        e3[patch[i]] += hn[i] * hn[i];
        ++cnt[patch[i]];
      }
      const double sg = estimated_sigma(noisy, f);
      for (int q = 0; q < patches; ++q)
        std::printf("PATCH %d %.3f %.3f %.6f %.6f %.6f %.4f\n", q, strengths[oracle[q]], ea[q][oracle[q]] / std::max(1, nf[q]) - ea[q][4] / std::max(1, nf[q]),
                    e1[q] / cnt[q], e2[q] / cnt[q], e3[q] / cnt[q], sg);
    }
    int global_gcv = 0;
    for (int s_ = 0; s_ < S; ++s_) {
      const double kept = 1 - ttot[s_] / ktot[s_];
      gtot[s_] = d.size() ? dtot[s_] / (kept * kept) : 0;
      if (gtot[s_] < gtot[global_gcv]) global_gcv = s_;
      char name[64];
      std::snprintf(name, sizeof name, "raw strength %.2f", strengths[s_]);
      show(name, xs[s_] / scale);
    }
    std::printf("  %d patches of %d; global GCV chooses %.2f\n", patches, patch_size, strengths[global_gcv]);
    {  // per patch, the discrepancy principle: the strongest strength whose removed normal energy is at most kappa times noise's
      const double sg = estimated_sigma(noisy, f);
      const double kappa = std::getenv("LAB_KAPPA") ? std::atof(std::getenv("LAB_KAPPA")) : 1.0;
      std::vector<std::vector<double>> rem(patches, std::vector<double>(S, 0)), prem(patches, std::vector<double>(S, 0));
      for (int s_ = 0; s_ < S; ++s_)
        for (int i = 0; i < n; ++i) {
          const Eigen::RowVector3d nn = normals.row(i);
          rem[patch[i]][s_] += std::pow(nn.dot(xs[s_].row(i) - v.row(i)), 2);
          prem[patch[i]][s_] += std::pow(nn.dot(as[s_].row(i) - probes.row(i)), 2);
        }
      std::vector<int> disc(patches, 0);
      for (int p = 0; p < patches; ++p) {
        int best = 0;
        for (int s_ = 0; s_ < S; ++s_)
          if (std::getenv("LAB_GROWTH") ? rem[p][s_] / prem[p][s_] <= kappa * rem[p][0] / prem[p][0]
                                        : rem[p][s_] <= kappa * sg * sg * prem[p][s_])
            best = s_;
        disc[p] = best;
        if (std::getenv("LAB_RATIODUMP")) {
          std::printf("  patch %2d oracle %d:", p, oracle[p]);
          for (int s_ = 0; s_ < S; ++s_) std::printf(" %.2f", rem[p][s_] / (sg * sg * prem[p][s_]));
          std::printf("\n");
        }
      }
      show("per-patch discrepancy", field(disc));
      std::map<double, int> hd;
      for (int p = 0; p < patches; ++p) hd[strengths[disc[p]]]++;
      std::printf("  discrepancy choices:");
      for (auto& [k, c] : hd) std::printf(" %.2f:%d", k, c);
      std::printf("\n  (disc, oracle) pairs:");
      std::map<std::pair<int, int>, int> dp;
      for (int p = 0; p < patches; ++p) dp[{disc[p], oracle[p]}]++;
      for (auto& [k, c] : dp) std::printf(" (%d,%d):%d", k.first, k.second, c);
      std::printf("\n");
    }
    show("per-patch oracle", field(oracle));
    show("per-patch GCV", field(gcv));
    std::map<double, int> histogram;
    std::map<std::pair<int, int>, int> pairs;
    for (int p = 0; p < patches; ++p) histogram[strengths[gcv[p]]]++, pairs[{gcv[p], oracle[p]}]++;
    std::printf("  (GCV, oracle) index pairs:");
    for (auto& [k, c] : pairs) std::printf(" (%d,%d):%d", k.first, k.second, c);
    std::printf("\n");
    std::printf("  GCV choices:");
    for (auto& [k, c] : histogram) std::printf(" %.2f:%d", k, c);
    std::printf("\n");
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "G") {  // guard: the denoiser's normal change against the noise's predicted tilt
    std::string err;
    DenoiseOptions o;
    Positions out;
    DenoiseReport r;
    if (!feature_preserving_denoise(noisy, f, o, out, r, err)) { std::printf("%s\n", err.c_str()); return 1; }
    const double edge = mean_edge_length(noisy, f);
    const double pred_est = predicted_noise_angle_degrees(noisy, f, r.sigma_used * edge);
    const double pred_true = predicted_noise_angle_degrees(clean, f, level * h);
    const double change = mean_face_normal_error_degrees(out, noisy, f);
    std::printf("  sigma %.3f (s%d)  predicted tilt: from estimate %.2f, true %.2f | noisy E_a %.2f | change %.2f  ratio %.2f\n", r.sigma_used,
                int(r.smoothed_instead()), pred_est, pred_true, mean_face_normal_error_degrees(noisy, clean, f), change, change / std::max(1e-9, pred_est));
    show("denoise", out);
    for (double kappa : {1.0, 1.25, 1.5, 2.0}) {
      double lo = 0, hi = 1;
      if (change <= kappa * pred_est) { lo = 1; } else {
        for (int it = 0; it < 30; ++it) {
          const double mid = 0.5 * (lo + hi);
          const Positions b = noisy + mid * (out - noisy);
          (mean_face_normal_error_degrees(b, noisy, f) <= kappa * pred_est ? lo : hi) = mid;
        }
      }
      char name[64];
      std::snprintf(name, sizeof name, "guard k%.2f t%.2f", kappa, lo);
      show(name, Positions(noisy + lo * (out - noisy)));
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "U") {  // tangles: faces turned by the untangling's smoothing, and by a second one
    std::string err;
    HamiltonianCycle cycle;
    hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
    NoiseEstimate ne;
    estimate_noise(noisy, f, cycle, EmdOptions{}, ne, err);
    const NoiseAdaptiveSmoothingOptions so = untangling_options(std::max(ne.relative(), 1e-6));
    NoiseAdaptiveSmoothingReport sr;
    Positions s1, s2;
    noise_adaptive_smooth(noisy, f, so, s1, sr, err);
    noise_adaptive_smooth(s1, f, so, s2, sr, err);
    const double t1 = 100 * turned_share(noisy, s1, f), t2 = 100 * turned_share(s1, s2, f);
    std::printf("  sigma %.3f capped %d | turned by the smoothing %.2f%%, by a second %.2f%%, ratio %.1f\n", ne.relative(), int(ne.capped()), t1, t2,
                t1 / std::max(t2, 1e-9));
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "B") {  // blend: the refinement near its creases, the adaptive smoothing elsewhere
    std::string err;
    DenoiseOptions o;
    o.smooth_surfaces_by_smoothing = false;
    Positions refined;
    DenoiseReport r;
    if (!feature_preserving_denoise(noisy, f, o, refined, r, err)) { std::printf("%s\n", err.c_str()); return 1; }
    NoiseAdaptiveSmoothingOptions so;
    so.noise = std::max(r.sigma_used, 1e-6);
    NoiseAdaptiveSmoothingReport sr;
    Positions smoothed;
    noise_adaptive_smooth(noisy, f, so, smoothed, sr, err);
    const double crease = std::atof(std::getenv("LAB_CREASE") ? std::getenv("LAB_CREASE") : "30");
    const int rings = std::atoi(std::getenv("LAB_RINGS") ? std::getenv("LAB_RINGS") : "2");
    const Positions fnr = face_normals(refined, f);
    std::map<std::pair<int, int>, std::vector<int>> owners;
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int a = f(i, k), b = f(i, (k + 1) % 3);
        owners[{std::min(a, b), std::max(a, b)}].push_back(int(i));
      }
    std::vector<int> ring(n, 1 << 20);
    for (const auto& [e, fs] : owners)
      if (fs.size() == 2 && fnr.row(fs[0]).dot(fnr.row(fs[1])) < std::cos(crease * M_PI / 180)) ring[e.first] = ring[e.second] = 0;
    const VertexAdjacency adj = vertex_adjacency(f, n);
    for (int step = 0; step < rings + 2; ++step)
      for (int i = 0; i < n; ++i)
        for (const int* j = adj.begin(i); j != adj.end(i); ++j) ring[i] = std::min(ring[i], ring[*j] + 1);
    Positions blend = smoothed;
    int near = 0;
    for (int i = 0; i < n; ++i) {
      const double w = ring[i] <= rings ? 1.0 : ring[i] == rings + 1 ? 0.5 : 0.0;
      blend.row(i) = w * refined.row(i) + (1 - w) * smoothed.row(i);
      near += w > 0;
    }
    std::printf("  sigma %.3f u%d capped %d sc %.2f contrast %.2f | %.1f%% of the vertices near creases\n", r.sigma_used, int(r.untangled),
                int(r.noise.capped()), r.refine_scaled, r.crease_contrast, 100.0 * near / n);
    show("refined", refined);
    show("smoothed", smoothed);
    show("blend", blend);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "E") {  // noise estimate: the IMF's MAD against low quantiles of the hinge residuals
    std::string err;
    HamiltonianCycle cycle;
    hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
    for (int which = 0; which < 2; ++which) {
      const Positions& p = which == 0 ? clean : noisy;
      NoiseEstimate ne;
      estimate_noise(p, f, cycle, EmdOptions{}, ne, err);
      std::vector<double> r = hinge_heights(p, f, vertex_adjacency(f, n));
      for (double& x : r) x = std::abs(x) / h;
      std::sort(r.begin(), r.end());
      auto quant = [&](double q) { return r.empty() ? 0.0 : r[size_t(q * (r.size() - 1))]; };
      std::printf("  %s: imf %.4f | hinge q0.10 %.4f q0.25 %.4f q0.50 %.4f | tiny(<1e-4) %.2f | capped to %.4f\n", which == 0 ? "clean" : "noisy",
                  ne.imf_sigma / ne.mean_edge, quant(0.10) / 0.12566, quant(0.25) / 0.31864, quant(0.5) / 0.67449,
                  double(std::lower_bound(r.begin(), r.end(), 1e-4) - r.begin()) / std::max<size_t>(1, r.size()), ne.relative());
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "Q") {  // noise estimate from 2-ring quadric fits: the leave-one-out residual of each vertex
    std::string err;
    HamiltonianCycle cycle;
    hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
    const VertexAdjacency a = vertex_adjacency(f, n);
    for (int which = 0; which < 2; ++which) {
      const Positions& p = which == 0 ? clean : noisy;
      NoiseEstimate ne;
      estimate_noise(p, f, cycle, EmdOptions{}, ne, err);
      const Positions nrm = area_weighted_vertex_normals(p, f);
      std::vector<double> r;
      std::vector<int> ring;
      std::vector<int> mark(n, -1);
      for (int i = 0; i < n; ++i) {
        if (a.boundary[i] || a.valence(i) == 0) continue;
        ring.clear();
        mark[i] = i;
        for (const int* j = a.begin(i); j != a.end(i); ++j) if (mark[*j] != i) { mark[*j] = i; ring.push_back(*j); }
        const size_t first = ring.size();
        for (size_t k = 0; k < first; ++k)
          for (const int* j = a.begin(ring[k]); j != a.end(ring[k]); ++j) if (mark[*j] != i) { mark[*j] = i; ring.push_back(*j); }
        if (ring.size() < 10) continue;
        Eigen::Vector3d nz = nrm.row(i).transpose();
        if (nz.norm() == 0) continue;
        nz.normalize();
        Eigen::Vector3d t1 = nz.unitOrthogonal(), t2 = nz.cross(t1);
        Eigen::MatrixXd A(ring.size(), 6);
        Eigen::VectorXd z(ring.size());
        double scale = 0;
        for (size_t k = 0; k < ring.size(); ++k) scale += (p.row(ring[k]) - p.row(i)).norm();
        scale /= ring.size();
        for (size_t k = 0; k < ring.size(); ++k) {
          Eigen::Vector3d d = (p.row(ring[k]) - p.row(i)).transpose() / scale;
          const double x = d.dot(t1), y = d.dot(t2);
          A.row(k) << 1, x, y, x * x, x * y, y * y;
          z[k] = d.dot(nz) * scale;
        }
        Eigen::MatrixXd AtA = A.transpose() * A;
        Eigen::LDLT<Eigen::MatrixXd> ldlt(AtA);
        Eigen::VectorXd e0 = Eigen::VectorXd::Zero(6);
        e0[0] = 1;
        Eigen::VectorXd c = ldlt.solve(e0);        // (A^T A)^-1 e0
        Eigen::VectorXd w = A * c;                 // prediction at 0 = w . z
        if (!w.allFinite()) continue;
        r.push_back(-w.dot(z) / std::sqrt(1 + w.squaredNorm()));
      }
      std::vector<double> ab = r;
      for (double& x : ab) x = std::abs(x) / h;
      std::sort(ab.begin(), ab.end());
      auto quant = [&](double q) { return ab.empty() ? 0.0 : ab[size_t(q * (ab.size() - 1))]; };
      std::printf("  %s: imf %.4f capped %.4f | quadric q0.25 %.4f q0.50 %.4f q0.75 %.4f (n %zu)\n", which == 0 ? "clean" : "noisy",
                  ne.imf_sigma / ne.mean_edge, ne.relative(), quant(0.25) / 0.31864, quant(0.5) / 0.67449, quant(0.75) / 1.15035, ab.size());
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "C") {  // correlation of the one-ring heights across edges and at two edges
    const VertexAdjacency a = vertex_adjacency(f, n);
    for (int which = 0; which < 2; ++which) {
      const Positions& p = which == 0 ? clean : noisy;
      Eigen::VectorXd hh = one_ring_heights(p, f, a);
      const double mean = hh.mean();
      hh.array() -= mean;
      double v0 = hh.squaredNorm() / n, c1 = 0, c2 = 0;
      long n1 = 0, n2 = 0;
      std::vector<int> mark(n, -1);
      for (int i = 0; i < n; ++i) {
        mark[i] = i;
        for (const int* j = a.begin(i); j != a.end(i); ++j) { mark[*j] = i; c1 += hh[i] * hh[*j]; ++n1; }
        for (const int* j = a.begin(i); j != a.end(i); ++j)
          for (const int* k = a.begin(*j); k != a.end(*j); ++k)
            if (mark[*k] != i) { mark[*k] = i; c2 += hh[i] * hh[*k]; ++n2; }
      }
      std::printf("  %s: rms height %.4f  corr lag1 %.3f  lag2 %.3f\n", which == 0 ? "clean" : "noisy", std::sqrt(v0) / h, c1 / n1 / v0, c2 / n2 / v0);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "X") {  // how white the smoothing's residual is: its normal part's correlation across edges
    std::string err;
    const VertexAdjacency a = vertex_adjacency(f, n);
    for (int which = 0; which < 2; ++which) {
      const Positions& p = which == 0 ? clean : noisy;
      Positions out;
      NoiseAdaptiveSmoothingReport r;
      noise_adaptive_smooth(p, f, lab_options(), out, r, err);
      const Positions nrm = area_weighted_vertex_normals(out, f);
      Eigen::VectorXd res(n);
      for (int i = 0; i < n; ++i) res[i] = (p.row(i) - out.row(i)).dot(nrm.row(i));
      res.array() -= res.mean();
      double v0 = res.squaredNorm() / n, c1 = 0;
      long n1 = 0;
      for (int i = 0; i < n; ++i)
        for (const int* j = a.begin(i); j != a.end(i); ++j) { c1 += res[i] * res[*j]; ++n1; }
      Score sc = score(out, clean, f), in = score(p, clean, f);
      std::printf("  %s: sigma %.3f  residual rms %.4f corr lag1 %.3f | E_a %.2f -> %.2f\n", which == 0 ? "clean" : "noisy", r.sigma_used,
                  std::sqrt(v0) / h, c1 / n1 / v0, in.ea, sc.ea);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "F") {  // the noise estimate's floor: one-ring heights with the curvature's share taken out
    std::string err;
    HamiltonianCycle cycle;
    hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
    auto estimate = [&](const Positions& p, bool corrected) {
      const VertexAdjacency a = vertex_adjacency(f, n);
      Eigen::VectorXd hgt = one_ring_heights(p, f, a), spread(n);
      for (int i = 0; i < n; ++i) {
        double sum = 0;
        for (const int* j = a.begin(i); j != a.end(i); ++j) sum += (p.row(*j) - p.row(i)).squaredNorm();
        spread[i] = a.valence(i) > 0 ? sum / a.valence(i) / 2 : 0;
      }
      if (corrected) {
        Eigen::VectorXd kappa(n), out = hgt;
        for (int i = 0; i < n; ++i) kappa[i] = spread[i] > 0 ? hgt[i] / spread[i] : 0;
        for (int i = 0; i < n; ++i) {
          if (a.valence(i) == 0) continue;
          double k = 0;
          for (const int* j = a.begin(i); j != a.end(i); ++j) k += kappa[*j];
          out[i] = hgt[i] - k / a.valence(i) * spread[i];
        }
        hgt = out;
      }
      std::vector<double> finest;
      for (const auto& seg : signals_along_cycle(cycle, hgt)) {
        EmdOptions o;
        o.max_imfs = 1;
        const EmdResult e = emd(seg, o);
        if (!e.imfs.empty()) finest.insert(finest.end(), e.imfs[0].begin(), e.imfs[0].end());
      }
      std::vector<double> d(finest);
      std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
      const double med = d[d.size() / 2];
      for (double& x : d) x = std::abs(x - med);
      std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
      return d[d.size() / 2] / 0.6745 / std::sqrt(1 + 1.0 / 6) / h;
    };
    std::printf("  sigma read, raw heights: clean %.4f noisy %.4f | curvature taken out: clean %.4f noisy %.4f (true %.3f)\n", estimate(clean, false),
                estimate(noisy, false), estimate(clean, true), estimate(noisy, true), level);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "M") {  // order 2 against the mix of orders 1 and 2, both at mu = c / sqrt(sigma estimated), raw
    const double sigma = estimated_sigma(noisy, f);
    const double scale = 1.0 / h;
    const Positions v = noisy * scale;
    const Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    const Eigen::SparseMatrix<double> L2 = L * L;
    const Eigen::SparseMatrix<double> A2 = L2.transpose() * L2, A1 = L.transpose() * L;
    Eigen::SparseMatrix<double> I(n, n);
    I.setIdentity();
    for (int mixed = 0; mixed < 2; ++mixed) {
      std::printf("  %s:", mixed ? "mix" : "order2");
      for (double c : {0.14, 0.17, 0.2, 0.233, 0.27, 0.32, 0.38, 0.45}) {
        const double mu = c / std::sqrt(sigma);
        Eigen::SparseMatrix<double> A = Eigen::SparseMatrix<double>(A2 + (mixed ? mu * mu : 0.0) * A1) + std::pow(mu, 4) * I;
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
        Positions out(n, 3);
        for (int k = 0; k < 3; ++k) out.col(k) = solver.solve(Eigen::VectorXd(std::pow(mu, 4) * v.col(k)));
        const Score sc = score(out / scale, clean, f);
        std::printf(" %.3f:%.2f/%.1f", c, sc.ea, sc.rms);
      }
      std::printf("\n");
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "H") {  // the smoothing's move against the noise's RMS, and scaled back to it
    std::string err;
    Positions nas;
    NoiseAdaptiveSmoothingReport r;
    noise_adaptive_smooth(noisy, f, lab_options(), nas, r, err);
    const double noise_rms = std::sqrt(3.0) * r.sigma_used * h;
    const double moved = std::sqrt((nas - noisy).rowwise().squaredNorm().mean());
    char name[80];
    std::snprintf(name, sizeof name, "NAS (move / noise RMS %.3f, sigma %.3f)", moved / noise_rms, r.sigma_used);
    show(name, nas);
    for (double c : {1.0, 0.9, 0.8}) {
      if (moved <= c * noise_rms) continue;
      Positions out = noisy + (nas - noisy) * (c * noise_rms / moved);
      std::snprintf(name, sizeof name, "scaled to %.1f of the noise RMS", c);
      show(name, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "T") {  // does the refinement from the noisy mesh leave it tangled?
    std::string err;
    DenoiseOptions o;
    Positions with, without;
    DenoiseReport r1, r2;
    feature_preserving_denoise(noisy, f, o, with, r1, err);
    o.untangle = false;
    feature_preserving_denoise(noisy, f, o, without, r2, err);
    Positions smoothed;
    NoiseAdaptiveSmoothingReport sr;
    noise_adaptive_smooth(noisy, f, untangling_options(r1.sigma_used), smoothed, sr, err);
    auto share = [&](const Positions& p) { return turned_share(p, smoothed, f); };
    char name[100];
    std::snprintf(name, sizeof name, "untangled %d (input share %.4f)", int(r1.untangled), share(noisy));
    show(name, with);
    std::snprintf(name, sizeof name, "from noisy (result share %.4f)", share(without));
    show(name, without);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "N") {  // the noise estimate over the vertices with the shortest edges
    std::string err;
    for (int which = 0; which < 2; ++which) {
      const Positions& p = which == 0 ? clean : noisy;
      HamiltonianCycle cycle;
      hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
      const VertexAdjacency adj = vertex_adjacency(f, n);
      const Eigen::VectorXd hts = one_ring_heights(p, f, adj);
      const double edge = mean_edge_length(p, f);
      std::vector<double> local(n, 0.0);
      for (int i = 0; i < n; ++i) {
        for (const int* j = adj.begin(i); j != adj.end(i); ++j) local[i] += (p.row(*j) - p.row(i)).norm();
        if (adj.valence(i) > 0) local[i] /= adj.valence(i);
      }
      std::vector<double> sorted = local;
      std::sort(sorted.begin(), sorted.end());
      std::printf("  %s:", which == 0 ? "clean" : "noisy");
      for (double q : {1.0, 0.5, 0.25}) {
        const double limit = sorted[std::min<size_t>(sorted.size() - 1, size_t(q * (sorted.size() - 1)))];
        std::vector<double> finest;
        double inv = 0;
        const auto segments = signals_along_cycle(cycle, hts);
        for (size_t sg = 0; sg < segments.size(); ++sg) {
          EmdOptions o;
          o.max_imfs = 1;
          const EmdResult e = emd(segments[sg], o);
          if (e.imfs.empty()) continue;
          for (size_t t = 0; t < segments[sg].size(); ++t) {
            const int v = cycle.order[cycle.segment_begin[sg] + static_cast<int>(t)];
            if (adj.boundary[v] || adj.valence(v) == 0 || local[v] > limit) continue;
            finest.push_back(e.imfs[0][t]);
            inv += 1.0 / adj.valence(v);
          }
        }
        const int m = finest.size();
        std::vector<double> c2 = finest;
        std::nth_element(c2.begin(), c2.begin() + m / 2, c2.end());
        const double centre = c2[m / 2];
        for (double& x : finest) x = std::abs(x - centre);
        std::nth_element(finest.begin(), finest.begin() + m / 2, finest.end());
        const double sig = finest[m / 2] / 0.6745 / std::sqrt(1 + inv / m) / edge;
        std::printf("  q%.2f sigma %.3f (local edge <= %.2f)", q, sig, limit / edge);
      }
      std::printf("\n");
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "Q") {  // the refinement's rounds: how far each moves the mesh
    std::string err;
    Positions prev;
    for (int rounds = 1; rounds <= 5; ++rounds) {
      DenoiseOptions o;
      o.refine_rounds = rounds;
      Positions out;
      DenoiseReport r;
      if (!feature_preserving_denoise(noisy, f, o, out, r, err)) return 1;
      const double unit = r.sigma_used * h;
      const double step = rounds == 1 ? 0 : std::sqrt((out - prev).rowwise().squaredNorm().mean()) / unit;
      const double from = std::sqrt((out - noisy).rowwise().squaredNorm().mean()) / unit;
      char name[80];
      std::snprintf(name, sizeof name, "rounds %d step %.3f from-noisy %.3f", rounds, step, from);
      show(name, out);
      prev = out;
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "CL") {  // the route's statistics: the untangling smoothing's dihedral angles
    std::string err;
    HamiltonianCycle cycle;
    hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
    NoiseEstimate est;
    estimate_noise(noisy, f, cycle, EmdOptions{}, est, err);
    NoiseAdaptiveSmoothingOptions so = untangling_options(est.relative());
    so.unturn_wrinkles = false;
    so.face_normal_pass = false;
    so.taubin_slide = false;
    so.keep_untouched = false;
    Positions smoothed;
    NoiseAdaptiveSmoothingReport sr;
    if (!noise_adaptive_smooth(noisy, f, so, smoothed, sr, err)) { std::printf("%s\n", err.c_str()); return 1; }
    std::vector<double> d;
    for (const auto& a : dihedral_angles(smoothed, f)) d.push_back(a.radians * 180 / M_PI);
    std::sort(d.begin(), d.end());
    auto at = [&](double q) { return d[static_cast<size_t>(q * (d.size() - 1))]; };
    const double med = std::max(at(0.5), 0.573);
    std::printf("CL edges %zu sigma %.4f median %.3f ratios", d.size(), est.relative(), at(0.5));
    for (double q : {0.9, 0.95, 0.98, 0.99, 0.995, 0.998, 0.999}) std::printf(" %.2f", at(q) / med);
    // the share of edges whose angle exceeds k times the median, times sqrt(edges) (lines scale so)
    {  // crease lines: edges over k times the median, joined where they share a vertex; edges in components of at least 5% of sqrt(E), and the largest, per sqrt(E)
      const std::vector<DihedralAngle> da = dihedral_angles(smoothed, f);
      for (double k : {8.0, 10.0, 12.0, 16.0}) {
        std::vector<int> parent(n);
        for (int i = 0; i < n; ++i) parent[i] = i;
        std::function<int(int)> find = [&](int x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
        std::vector<std::pair<int, int>> sharp;
        for (const DihedralAngle& a : da)
          if (a.radians * 180 / M_PI > k * med) { sharp.push_back({a.a, a.b}); parent[find(a.a)] = find(a.b); }
        std::map<int, int> size;
        for (const auto& e : sharp) ++size[find(e.first)];
        const double root = std::sqrt(static_cast<double>(d.size()));
        long in_long = 0;
        int largest = 0;
        for (const auto& [r, z] : size) { if (z >= 0.05 * root) in_long += z; largest = std::max(largest, z); }
        std::printf(" | lines k%.0f: %.3f largest %.3f", k, in_long / root, largest / root);
      }
    }
    std::printf(" | over k*median per sqrt(E):");
    for (double k : {6.0, 9.0, 12.0, 16.0}) {
      const double c = static_cast<double>(d.end() - std::upper_bound(d.begin(), d.end(), k * med));
      std::printf(" %.3f", c / std::sqrt(static_cast<double>(d.size())));
    }
    {  // flat share: faces in near-flat regions holding at least q of the faces
      const Positions fn = face_normals(smoothed, f);
      std::printf(" | flat share (deg: q 0.5%% 1%% 2%%)");
      for (double deg : {3.0, 5.0, 8.0}) {
        const std::vector<size_t> sizes = flat_region_sizes(fn, f, deg);
        std::printf(" %.0f:", deg);
        for (double qq : {0.005, 0.01, 0.02}) {
          size_t in = 0;
          for (size_t z : sizes) if (z >= qq * f.rows()) in += z;
          std::printf(" %.3f", double(in) / f.rows());
        }
      }
    }
    std::printf("\n");
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "RT") {  // the denoiser's route (smoothing or refinement) scored by the recorrupted risk
    std::string err;
    DenoiseOptions o;
    Positions out;
    DenoiseReport r;
    if (!feature_preserving_denoise(noisy, f, o, out, r, err)) { std::printf("%s\n", err.c_str()); return 1; }
    const double sigma = r.sigma_used;
    auto smooth_route = [&](const Positions& y, double s, Positions& x) {
      NoiseAdaptiveSmoothingOptions so;
      so.noise = s;
      so.keep_untouched = false;
      NoiseAdaptiveSmoothingReport sr;
      return noise_adaptive_smooth(y, f, so, x, sr, err);
    };
    auto refine_route = [&](const Positions& y, double s, Positions& x) {
      DenoiseOptions ro;
      ro.noise = s;
      ro.smooth_surfaces_by_smoothing = false;
      DenoiseReport rr;
      return feature_preserving_denoise(y, f, ro, x, rr, err);
    };
    Positions xs, xr;
    if (!smooth_route(noisy, sigma, xs) || !refine_route(noisy, sigma, xr)) { std::printf("%s\n", err.c_str()); return 1; }
    const Score ss = score(xs, clean, f), sr = score(xr, clean, f), sd = score(out, clean, f), sn = score(noisy, clean, f);
    const double copy_sigma = sigma * std::sqrt(1 + kRecorruptionScale * kRecorruptionScale);
    const VertexAdjacency adj = vertex_adjacency(f, n);
    NoiseShape shape;
    const Positions normals = smoothed_vertex_normals(noisy, f, adj);
    shape.tangential_share = std::getenv("LAB_RTISO") ? 1.0 : std::min(1.0, tangential_noise_share(noisy, normals, adj, sigma * mean_edge_length(noisy, f)));
    if (shape.tangential_share < 1) shape.unit_normals = normals;
    const double edge = mean_edge_length(noisy, f);
    // Both risks by hand: positions (as recorrupted_risks), and face area vectors (bilinear in the
    // positions: y2's are unbiased for the clean mesh's), each face weighted by 1 / its area squared
    // in y1 smoothed by Taubin (floored at a fifth of the mean).
    std::mt19937 gen(kPassSeed);
    std::normal_distribution<double> gz(0, sigma * edge);
    const double across = std::sqrt(shape.tangential_share);
    std::vector<std::array<double, 4>> draws;
    auto area_vectors = [&](const Positions& p) {
      Positions a(f.rows(), 3);
      for (Eigen::Index g = 0; g < f.rows(); ++g)
        a.row(g) = 0.5 * (p.row(f(g, 1)) - p.row(f(g, 0))).cross(p.row(f(g, 2)) - p.row(f(g, 0)));
      return a;
    };
    for (int d = 0; d < kPassDraws; ++d) {
      Positions z(n, 3);
      for (int i = 0; i < n; ++i) for (int k = 0; k < 3; ++k) z(i, k) = gz(gen);
      if (shape.tangential_share < 1)
        for (int i = 0; i < n; ++i) {
          const Eigen::RowVector3d nn = normals.row(i), along = z.row(i).dot(nn) * nn;
          z.row(i) = along + across * (z.row(i) - along);
        }
      const Positions y1 = noisy + kRecorruptionScale * z, y2 = noisy - z / kRecorruptionScale;
      Positions o1, o2;
      if (!smooth_route(y1, copy_sigma, o1) || !refine_route(y1, copy_sigma, o2)) { std::printf("copy failed %s\n", err.c_str()); return 1; }
      const Positions ref = area_vectors(taubin(y1, f, 10, 0.5, -0.53));
      double mean_area = 0;
      for (Eigen::Index g = 0; g < f.rows(); ++g) mean_area += ref.row(g).norm() / f.rows();
      const Positions a2 = area_vectors(y2), a1s = area_vectors(o1), a1r = area_vectors(o2);
      double as = 0, ar = 0;
      for (Eigen::Index g = 0; g < f.rows(); ++g) {
        const double w = 1 / std::pow(std::max(ref.row(g).norm(), 0.2 * mean_area), 2);
        as += w * (a1s.row(g) - a2.row(g)).squaredNorm();
        ar += w * (a1r.row(g) - a2.row(g)).squaredNorm();
      }
      if (std::getenv("LAB_RTCOPY")) {
        const Score c1 = score(o1, clean, f), c2 = score(o2, clean, f);
        std::printf("  copy %d: smooth %.2f/%.1f refine %.2f/%.1f; pos risk %.5g %.5g area %.5g %.5g\n", d, c1.ea, c1.rms, c2.ea, c2.rms, (o1 - y2).squaredNorm() / n, (o2 - y2).squaredNorm() / n, as / f.rows(), ar / f.rows());
      }
      draws.push_back({(o1 - y2).squaredNorm() / n, (o2 - y2).squaredNorm() / n, as / f.rows(), ar / f.rows()});
    }
    RecorruptedRisks risks, area_risks;
    for (const auto& d : draws) { risks.per_draw.push_back({d[0], d[1]}); area_risks.per_draw.push_back({d[2], d[3]}); }
    const std::vector<double> am = area_risks.mean(), m = risks.mean();
    std::printf("RTA area s %.5g r %.5g ratio %.4f pick %s\n", am[0], am[1], am[1] / am[0], am[1] < am[0] ? "refine" : "smooth");
    int refine_every = 1;
    for (const auto& d : risks.per_draw) refine_every &= d[1] < d[0];
    std::printf("RT noisy %.2f/%.1f shipped(s%d c%.2f) %.2f/%.1f smooth %.2f/%.1f refine %.2f/%.1f risk s %.5g r %.5g ratio %.4f every %d share %.2f truth %s pick %s\n",
                sn.ea, sn.rms, int(r.smoothed_instead()), r.crease_contrast, sd.ea, sd.rms, ss.ea, ss.rms, sr.ea, sr.rms, m[0], m[1], m[1] / m[0], refine_every,
                shape.tangential_share, sr.ea < ss.ea ? "refine" : "smooth", m[1] < m[0] ? "refine" : "smooth");
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "D") {  // the denoiser with the untangling's filter from LAB_UFIRST, LAB_USCALE
    std::string err;
    DenoiseOptions o;
    if (const char* g = std::getenv("LAB_UFIRST")) o.untangle_first_order = std::atof(g);
    if (const char* m = std::getenv("LAB_USCALE")) o.untangle_mu_scale = std::atof(m);
    if (const char* x = std::getenv("LAB_RSIGMA")) o.refine_normal_sigma = std::atof(x);
    if (const char* x = std::getenv("LAB_RPASSES")) o.refine_normal_passes = std::atoi(x);
    if (const char* x = std::getenv("LAB_RITER")) o.refine_vertex_iterations = std::atoi(x);
    if (std::getenv("LAB_NOOWN")) o.refine_own_normals = false;
    if (std::getenv("LAB_NOFITEACH")) o.refine_fit_each_pass = false;
    if (std::getenv("LAB_NOPLANAR")) o.flatten_planar_regions = false;  // item 36 off
    if (const char* x = std::getenv("LAB_PLANARSEED")) o.planar_regions.seed_degrees = std::atof(x);  // item 36's thresholds
    if (const char* x = std::getenv("LAB_PLANARBEND")) o.planar_regions.max_bend_degrees = std::atof(x);
    if (const char* x = std::getenv("LAB_PLANARITS")) o.planar_regions.max_vertex_iterations = std::atoi(x);  // item 37's cap
    if (const char* x = std::getenv("LAB_PLANARSETTLED")) o.planar_regions.settled = std::atof(x);
    if (const char* x = std::getenv("LAB_ROUNDS")) o.refine_rounds = std::atoi(x);
    if (std::getenv("LAB_NOUNTANGLE")) o.untangle = false;
    if (std::getenv("LAB_NOBORDERS")) o.hold_borders = false;
    if (const char* x = std::getenv("LAB_DRIFTSTEP")) o.refine_drift_step = std::atof(x);
    if (const char* x = std::getenv("LAB_EXTRAFACTOR")) o.refine_extra_rounds_factor = std::atof(x);
    if (const char* x = std::getenv("LAB_SLIVERALT")) o.refine_sliver_altitude = std::atof(x);  // 0: as before item 41
    if (const char* x = std::getenv("LAB_CONVERGEDSTEP")) o.refine_converged_step = std::atof(x);
    if (std::getenv("LAB_NOROUTE")) o.smooth_surfaces_by_smoothing = false;
    if (const char* band = std::getenv("LAB_BAND")) std::sscanf(band, "%lf,%lf", &o.no_crease_contrast, &o.crease_contrast);
    if (std::getenv("LAB_NOFLAT")) o.refine_flat_parts = false;
    if (std::getenv("LAB_NODISTORT")) o.refine_where_smoothing_distorts = false;
    if (const char* band = std::getenv("LAB_DBAND")) std::sscanf(band, "%lf,%lf", &o.distorting_move_low, &o.distorting_move_high);
    if (const char* band = std::getenv("LAB_FBAND")) std::sscanf(band, "%lf,%lf", &o.folded_low, &o.folded_high);
    if (const char* x = std::getenv("LAB_SIGMA")) o.noise = std::atof(x);  // given noise (sigma / mean edge)
    if (std::getenv("LAB_NOCAP")) {  // the finest IMF's estimate without the flat hinges' cap
      HamiltonianCycle cycle;
      hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
      NoiseEstimate ne;
      estimate_noise(noisy, f, cycle, EmdOptions{}, ne, err);
      o.noise = ne.imf_sigma / ne.mean_edge;
    }
    Positions out;
    if (std::getenv("LAB_TANGLEBLEND")) {  // experiment: started from the untangling smoothing or from the input, and blends
      DenoiseOptions a = o, b = o;
      a.tangled_share = 0;
      b.untangle = false;
      Positions pa, pb;
      DenoiseReport ra, rb;
      feature_preserving_denoise(noisy, f, a, pa, ra, err);
      feature_preserving_denoise(noisy, f, b, pb, rb, err);
      show("tangle untangled", pa);
      show("tangle from the input", pb);
      const auto share = [&](const Positions& p) {
        const std::vector<unsigned char> folded = folded_faces(p, f);
        return std::count(folded.begin(), folded.end(), 1) / double(f.rows());
      };
      std::printf("  tangle folded: untangled %.4f from the input %.4f input %.4f; moved apart %.3f noise RMS\n", share(pa), share(pb), share(noisy),
                  std::sqrt((pa - pb).rowwise().squaredNorm().mean()) / (std::sqrt(3.0) * ra.sigma_used * h));
      for (double w : {0.25, 0.5, 0.75}) { char nm[40]; std::snprintf(nm, sizeof nm, "tangle blend %.2f untangled", w); show(nm, Positions(w * pa + (1 - w) * pb)); }
    }
    if (std::getenv("LAB_DISTORTBLEND")) {  // experiment: item 17's two outcomes and their blends
      DenoiseOptions a = o, b = o;
      a.distorting_move_low = a.distorting_move_high = 0;
      a.folded_low = a.folded_high = 2;  // whatever the folded share
      b.refine_where_smoothing_distorts = false;
      Positions pa, pb;
      DenoiseReport ra, rb;
      feature_preserving_denoise(noisy, f, a, pa, ra, err);
      feature_preserving_denoise(noisy, f, b, pb, rb, err);
      std::printf("  distort move %.3f\n", ra.smoothing_move);
      show("item 17 refined from the input", pa);
      show("item 17 routed as usual", pb);
      for (double w : {0.25, 0.5, 0.75}) { char nm[40]; std::snprintf(nm, sizeof nm, "item 17 blend %.2f of the input's", w); show(nm, Positions(w * pa + (1 - w) * pb)); }
    }
    DenoiseReport r;
    if (!feature_preserving_denoise(noisy, f, o, out, r, err)) { std::printf("%s\n", err.c_str()); return 1; }
    char name[80];
    std::snprintf(name, sizeof name, "denoise (u%d s%d w%.2f f%d sig %.3f r%d p%d fl%.4f sc%.2f cr%d %.1f)", int(r.untangled), int(r.smoothed_instead()), r.smoothing_weight, int(r.flat_parts_refined),
                  r.sigma_used, r.refine_rounds, r.refine_normal_passes, double(r.flipped_faces) / f.rows(), r.refine_scaled, int(r.creases_revealed),
                  r.refined_crease_contrast);
    show(name, out);
    if (std::getenv("LAB_CREASEORACLE") && !near_crease.empty()) {  // the clean normals as the vertex update's targets
      const Positions own = unit_face_normals(out, f), truth = unit_face_normals(clean, f);
      Positions targets = own;
      for (Eigen::Index i = 0; i < f.rows(); ++i)
        if (near_crease[i]) targets.row(i) = truth.row(i);
      show("O clean normals near creases", fit_vertices_to_normals(out, f, targets, 20));
      show("O clean normals everywhere", fit_vertices_to_normals(out, f, truth, 20));
    }
    const std::vector<unsigned char> folded_out = folded_faces(out, f);
    const int out_folded = static_cast<int>(std::count(folded_out.begin(), folded_out.end(), 1));
    std::printf("  planar regions %d, %.3f of the faces, %d fit iterations\n", r.planar_regions, double(r.planar_region_faces) / f.rows(),
                r.planar_fit_iterations);
    std::printf("  item 17: smoothing move %.3f noise RMS, folded %.4f, distorts %d (weight %.2f); result folded %.4f\n", r.smoothing_move,
                double(r.folded_faces) / f.rows(), int(r.smoothing_distorts()), r.distort_weight, double(out_folded) / f.rows());
    {  // how white the removed part is: its correlation across edges (normal part, and 3D)
      const VertexAdjacency adj = vertex_adjacency(f, n);
      const Positions nn = area_weighted_vertex_normals(out, f);
      double cn = 0, sn = 0, c3 = 0, s3 = 0;
      for (int i = 0; i < n; ++i)
        for (const int* j = adj.begin(i); j != adj.end(i); ++j) {
          if (*j < i) continue;
          const Eigen::RowVector3d ri = noisy.row(i) - out.row(i), rj = noisy.row(*j) - out.row(*j);
          const double a = ri.dot(nn.row(i)), b = rj.dot(nn.row(*j));
          cn += a * b; sn += 0.5 * (a * a + b * b);
          c3 += ri.dot(rj); s3 += 0.5 * (ri.squaredNorm() + rj.squaredNorm());
        }
      std::printf("  removed part's edge correlation: normal %.3f, 3D %.3f; removed RMS %.3f sigma\n", cn / sn, c3 / s3,
                  std::sqrt((noisy - out).rowwise().squaredNorm().mean()) / (r.sigma_used * h));
    }
    std::printf("  crease lines %.3f\n", r.crease_lines);
    std::printf("  crease contrast %.2f (input %.2f, result %.2f); estimate imf %.4f hinge %.4f capped %d\n", r.crease_contrast, crease_contrast(noisy, f), crease_contrast(out, f), r.noise.imf_sigma / std::max(1e-300, r.noise.mean_edge), r.noise.hinge_sigma / std::max(1e-300, r.noise.mean_edge), int(r.noise.capped()));
    std::printf("  steps");
    for (double st : r.refine_steps) std::printf(" %.3f", st);
    std::printf("\n");
    if (std::getenv("LAB_BOUNDARY")) {  // the angle error on faces near the boundary (within 2 rings) and elsewhere
      const VertexAdjacency adj = vertex_adjacency(f, n);
      std::vector<int> ring(n, 99);
      std::vector<int> q;
      for (int i = 0; i < n; ++i) if (adj.boundary[i]) { ring[i] = 0; q.push_back(i); }
      for (size_t k = 0; k < q.size(); ++k)
        for (const int* j = adj.begin(q[k]); j != adj.end(q[k]); ++j)
          if (ring[*j] > ring[q[k]] + 1) { ring[*j] = ring[q[k]] + 1; q.push_back(*j); }
      const Positions a = face_normals(out, f), b = face_normals(clean, f);
      double near = 0, far = 0;
      int nn = 0, nf = 0;
      for (Eigen::Index g = 0; g < f.rows(); ++g) {
        const double e = std::acos(std::clamp(a.row(g).dot(b.row(g)), -1.0, 1.0)) * 180 / M_PI;
        if (std::min({ring[f(g, 0)], ring[f(g, 1)], ring[f(g, 2)]}) <= 2) { near += e; ++nn; } else { far += e; ++nf; }
      }
      std::printf("  E_a near the boundary (2 rings, %d faces) %.2f, elsewhere (%d) %.2f; share of the sum near it %.2f\n", nn, nn ? near / nn : 0.0, nf, nf ? far / nf : 0.0, near / std::max(1e-300, near + far));
    }
    if (std::getenv("LAB_FEATURES")) {  // sharp feature vertices off the boundary, on the input and on the result
      const VertexAdjacency adj = vertex_adjacency(f, n);
      for (const auto& [label, p] : {std::pair<const char*, const Positions*>{"input", &noisy}, {"result", &out}}) {
        std::vector<FeatureType> type;
        std::string e2;
        if (!detect_sharp_features(*p, f, SharpFeatureOptions{}, type, e2)) { std::printf("  features: %s\n", e2.c_str()); continue; }
        int inner = 0;
        for (int i = 0; i < n; ++i) inner += type[i] != FeatureType::None && !adj.boundary[i];
        std::printf("  feature vertices off the boundary (%s): %d (%.4f)\n", label, inner, double(inner) / n);
      }
    }
    {  // the result's dihedral angles: high percentiles and the share of sharp edges
      std::vector<double> d;
      for (const auto& a : dihedral_angles(out, f)) d.push_back(a.radians * 180 / M_PI);
      std::sort(d.begin(), d.end());
      auto at = [&](double q) { return d[static_cast<size_t>(q * (d.size() - 1))]; };
      int over30 = 0, over45 = 0, over60 = 0;
      for (double x : d) { over30 += x > 30; over45 += x > 45; over60 += x > 60; }
      std::printf("  dihedral: median %.2f p98 %.1f p99 %.1f p99.5 %.1f p99.9 %.1f; share over 30/45/60: %.4f %.4f %.4f\n", at(0.5), at(0.98), at(0.99), at(0.995), at(0.999),
                  double(over30) / d.size(), double(over45) / d.size(), double(over60) / d.size());
    }
    {  // planar share: faces in near-flat regions (normals within a few degrees of their seed's) of 30 faces or more
      const Positions fn = face_normals(out, f);
      for (double deg : {2.0, 3.0, 5.0}) {
        long in_large = 0;
        for (size_t z : flat_region_sizes(fn, f, deg)) if (z >= 30) in_large += z;
        std::printf("  planar share (%.0f deg, regions of 30+ faces): %.3f\n", deg, double(in_large) / f.rows());
      }
    }
    if (const char* minimum = std::getenv("LAB_PLANESIGMA")) {  // experiment: the noise read off the result's flat regions, on the noisy positions
      std::vector<size_t> sizes;
      const std::vector<int> label = flat_region_labels(face_normals(out, f), f, 3.0, sizes);
      std::vector<std::vector<int>> members(sizes.size());
      for (Eigen::Index g = 0; g < f.rows(); ++g)
        if (sizes[label[g]] >= static_cast<size_t>(std::atoi(minimum)))
          for (int k = 0; k < 3; ++k) members[label[g]].push_back(f(g, k));
      double rss = 0, dof = 0;
      int regions = 0;
      std::vector<unsigned char> covered(n, 0);
      for (std::vector<int>& m : members) {
        std::sort(m.begin(), m.end());
        m.erase(std::unique(m.begin(), m.end()), m.end());
        if (m.size() < 6) continue;
        Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
        for (int v : m) mean += noisy.row(v);
        mean /= double(m.size());
        Eigen::Matrix3d sc = Eigen::Matrix3d::Zero();
        for (int v : m) sc += (noisy.row(v) - mean).transpose() * (noisy.row(v) - mean);
        rss += Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(sc).eigenvalues()[0];
        dof += double(m.size()) - 3;
        ++regions;
        for (int v : m) covered[v] = 1;
      }
      const double plane_sigma = dof > 0 ? std::sqrt(rss / dof) / mean_edge_length(noisy, f) : 0.0;
      std::printf("  plane sigma %.4f (regions %d, vertices %ld of %d)\n", plane_sigma, regions,
                  long(std::count(covered.begin(), covered.end(), 1)), n);
    }
    if (std::getenv("LAB_ROUTESMOOTH")) {  // the smoothing the route would give, at the denoiser's noise level
      NoiseAdaptiveSmoothingOptions so;
      so.keep_untouched = false;
      so.noise = r.sigma_used;
      NoiseAdaptiveSmoothingReport sr;
      Positions sm;
      if (noise_adaptive_smooth(noisy, f, so, sm, sr, err)) show("route's smoothing", sm);
      if (std::getenv("LAB_BLEND") && sm.rows() == out.rows()) for (double w : {0.25, 0.5, 0.75}) { char nm[40]; std::snprintf(nm, sizeof nm, "blend %.2f of the smoothing", w); show(nm, Positions(w * sm + (1 - w) * out)); }
    }
    if (const char* x = std::getenv("LAB_SMOOTHOWN")) {  // experiment: own-normal rounds after the smoothing route
      GuidedNormalDenoiseOptions b;
      b.guidance = NormalGuidance::OwnNormal;
      b.sigma = kOwnNormalSigma;
      b.normal_passes = std::getenv("LAB_SOP") ? std::atoi(std::getenv("LAB_SOP")) : 8;
      b.vertex_iterations = 20;
      Positions cur = out;
      for (int k = 0; k < std::atoi(x); ++k) {
        Positions g;
        guided_normal_denoise(cur, f, b, g, err);
        {
          const Positions n0 = unit_face_normals(cur, f), n1 = unit_face_normals(g, f);
          double ang = 0;
          for (Eigen::Index i = 0; i < f.rows(); ++i) ang += std::acos(std::clamp(n0.row(i).dot(n1.row(i)), -1.0, 1.0));
          const double mv = std::sqrt((g - cur).rowwise().squaredNorm().mean()) / (r.sigma_used * h);
          int flat0 = 0, flat1 = 0, tot = 0;
          for (const auto& a : dihedral_angles(cur, f)) { flat0 += a.radians < 2.0 * M_PI / 180; ++tot; }
          for (const auto& a : dihedral_angles(g, f)) flat1 += a.radians < 2.0 * M_PI / 180;
          std::printf("  own-round stats: move %.3f sigma, normal change %.2f deg, flat<2deg %.3f -> %.3f\n", mv, ang / f.rows() * 180 / M_PI, double(flat0) / tot, double(flat1) / tot);
        }
        cur = g;
        char nm[80];
        std::snprintf(nm, sizeof nm, "smoothing + own round %d", k + 1);
        show(nm, cur);
      }
    }
    if (std::getenv("LAB_L0R")) {  // experiment: the denoiser against L0 by the recorrupted risk
      const VertexAdjacency adj = vertex_adjacency(f, n);
      const Positions normals = smoothed_vertex_normals(noisy, f, adj);
      const double sigma = r.sigma_used * h;
      NoiseShape shape;
      shape.tangential_share = std::min(1.0, tangential_noise_share(noisy, normals, adj, sigma));
      if (shape.tangential_share < 1) shape.unit_normals = normals;
      const double copy_sigma = sigma * std::sqrt(1 + kRecorruptionScale * kRecorruptionScale);
      const auto run = [&](const Positions& y1, std::vector<Positions>& outs) {
        outs.assign(2, Positions());
        DenoiseOptions c = o;
        c.noise = copy_sigma / mean_edge_length(y1, f);
        DenoiseReport cr;
        std::string e;
        if (!feature_preserving_denoise(y1, f, c, outs[0], cr, e)) return false;
        L0DenoiseOptions l;
        l.dihedral_mean = DihedralMean::Unsigned;
        return l0_denoise(y1, f, l, outs[1], e);
      };
      RecorruptedRisks risks;
      const int draws = std::getenv("LAB_L0RDRAWS") ? std::atoi(std::getenv("LAB_L0RDRAWS")) : 3;
      if (recorrupted_risks(noisy, sigma, shape, draws, 7, run, risks)) {
        const std::vector<double> m = risks.mean();
        int l0_wins = 0;
        for (const auto& d : risks.per_draw) l0_wins += d[1] < d[0];
        std::printf("  L0R share %.3f risk denoise %.6g L0 %.6g (L0 lower by %.3f%%, in %d of %d draws)\n", shape.tangential_share,
                    m[0], m[1], 100 * (m[0] - m[1]) / m[0], l0_wins, risks.draws());
      }
      L0DenoiseOptions l;
      l.dihedral_mean = DihedralMean::Unsigned;
      Positions l0;
      if (l0_denoise(noisy, f, l, l0, err)) show("L0R candidate: L0 unsigned", l0);
    }
    if (std::getenv("LAB_GUIDED")) {
      Positions g;
      GuidedNormalDenoiseOptions shipped;  // guided_denoise.mlx
      shipped.stand_up_turned_faces = true;
      guided_normal_denoise(noisy, f, shipped, g, err);
      show("guided", g);
      GuidedNormalDenoiseOptions b;  // bilateral_normal_denoise.mlx
      b.stand_up_turned_faces = true;
      b.guidance = NormalGuidance::OwnNormal;
      b.normal_passes = 20;
      b.vertex_iterations = 10;
      guided_normal_denoise(noisy, f, b, g, err);
      show("bilateral normal", g);
      std::printf("  crease contrast of bilateral normal %.2f\n", crease_contrast(g, f));
      GuidedNormalDenoiseOptions a;  // the guided filter in its authors' scheme (item 24)
      a.rounds = 20;
      a.normal_passes = 1;
      a.vertex_iterations = 10;
      guided_normal_denoise(noisy, f, a, g, err);
      show("guided (authors' scheme)", g);
      if (std::getenv("LAB_SD")) {  // the SD filter (Zhang et al. 2019) at its authors' DenoisingOptions.txt
        const auto start = std::chrono::steady_clock::now();
        Positions sd;
        if (sd_normal_denoise(noisy, f, SdNormalDenoiseOptions{}, sd, err)) {
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          show("SD filter (Zhang et al. 2019)", sd);
          std::printf("  SD filter time %.2f s\n", seconds);
        } else {
          std::printf("  SD filter failed: %s\n", err.c_str());
        }
        // Its weight tuned per case, as its paper does: LAB_SD_LAMBDAS=0.1,0.3,1 (Lambda; the default 2)
        for (const double lambda : list_from_env("LAB_SD_LAMBDAS")) {
          SdNormalDenoiseOptions o;
          o.lambda = lambda;
          char name[60];
          std::snprintf(name, sizeof name, "SD filter, Lambda %g", lambda);
          if (sd_normal_denoise(noisy, f, o, sd, err)) show(name, sd);
        }
      }
      if (std::getenv("LAB_L0")) {  // L0 minimization at the reference code's defaults, and with the unsigned mean dihedral
        for (const DihedralMean mean : {DihedralMean::Signed, DihedralMean::Unsigned}) {
          const bool is_signed = mean == DihedralMean::Signed;
          L0DenoiseOptions o;
          o.dihedral_mean = mean;
          const auto start = std::chrono::steady_clock::now();
          if (!l0_denoise(noisy, f, o, g, err)) {
            std::printf("  L0 failed: %s\n", err.c_str());
            continue;
          }
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          show(is_signed ? "L0 (He and Schaefer 2013)" : "L0, unsigned mean dihedral", g);
          L0Weights w;
          l0_default_weights(noisy, f, mean, w, err);
          std::printf("  L0%s time %.2f s (alpha %.4g, lambda %.4g, mean dihedral %.4g rad)\n", is_signed ? "" : " unsigned",
                      seconds, w.alpha, w.lambda, w.mean_dihedral);
          if (is_signed) continue;
          if (std::getenv("LAB_L0THEN")) {  // experiment: a normal filtering round from L0's result
            const Positions l0 = g;
            Positions h2;
            GuidedNormalDenoiseOptions b;
            b.guidance = NormalGuidance::OwnNormal;
            b.normal_passes = 2;
            if (guided_normal_denoise(l0, f, b, h2, err)) show("L0 + 2 own-normal passes", h2);
            GuidedNormalDenoiseOptions c;
            c.normal_passes = 2;
            if (guided_normal_denoise(l0, f, c, h2, err)) show("L0 + 2 guided passes", h2);
          }
          // L0 from `start` with the noisy input's unsigned-mean weights, lambda scaled
          const auto l0_scaled = [&](const Positions& start, double scale, const char* label) {
            L0DenoiseOptions t;
            t.alpha = w.alpha;
            t.lambda = scale * w.lambda;
            char name[80];
            std::snprintf(name, sizeof name, "%s x %g", label, scale);
            if (l0_denoise(start, f, t, g, err)) show(name, g);
          };
          if (std::getenv("LAB_L0POLISH")) {  // experiment: L0 from the denoiser's result, lambda from the noisy input or the result
            for (const double scale : {0.1, 0.3, 1.0}) l0_scaled(out, scale, "denoise + L0 (input's lambda)");
            L0DenoiseOptions t;
            t.dihedral_mean = DihedralMean::Unsigned;
            if (l0_denoise(out, f, t, g, err)) show("denoise + L0 (result's own lambda)", g);
          }
          // lambda tuned per case, as its paper does: LAB_L0_SCALES=0.1,1,10 times the unsigned default's
          for (const double scale : list_from_env("LAB_L0_SCALES")) l0_scaled(noisy, scale, "L0, lambda");
        }
      }
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "u") {  // the put-back of turned faces with limits wider than the shipped one
    std::string err;
    Positions nas;
    NoiseAdaptiveSmoothingReport r;
    noise_adaptive_smooth(noisy, f, lab_options(), nas, r, err);
    char name[80];
    std::snprintf(name, sizeof name, "NAS (put back within %.0f: %d, un-turned %d)", kRestoredFaceTilt, r.restored_faces, r.unturned_faces);
    show(name, nas);
    for (double limit : {80.0, 90.0}) {
      Positions out = nas;
      const int restored = restore_turned_faces_that_fit(noisy, f, limit, out);
      std::snprintf(name, sizeof name, "+ put back within %.0f (%d)", limit, restored);
      show(name, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "W") {  // the triangulation's own drift taken out instead of the tangential cap
    std::string err;
    Positions shipped, loose, again;
    NoiseAdaptiveSmoothingReport r0, r1, r2;
    noise_adaptive_smooth(noisy, f, lab_options(), shipped, r0, err);
    show("NAS shipped (cap 7)", shipped);
    NoiseAdaptiveSmoothingOptions o = lab_options();
    o.tangential_cap = 1e9;
    noise_adaptive_smooth(noisy, f, o, loose, r1, err);
    show("NAS no cap", loose);
    NoiseAdaptiveSmoothingOptions o2 = o;
    o2.mu = r1.mu;
    o2.noise = r1.sigma_used;
    o2.select_cutoff = false;
    noise_adaptive_smooth(loose, f, o2, again, r2, err);
    const Positions nrm = area_weighted_vertex_normals(loose, f);
    for (double share : {0.5, 1.0, 1.5}) {
      Positions out = loose;
      for (int i = 0; i < n; ++i) {
        const Eigen::RowVector3d d = again.row(i) - loose.row(i), nn = nrm.row(i);
        out.row(i) -= share * (d - d.dot(nn) * nn);
      }
      char name[64];
      std::snprintf(name, sizeof name, "no cap, drift x%.1f out", share);
      show(name, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "Y") {  // the refinement's range width: wide away from the smoothing's creases, or one width
    std::string err;
    for (double wide : {kRefineSmoothSigma, 0.0}) {
      DenoiseOptions d;
      d.refine_smooth_sigma = wide > 0 && std::getenv("LAB_WIDE") ? std::atof(std::getenv("LAB_WIDE")) : wide;
      Positions out;
      DenoiseReport rep;
      if (!feature_preserving_denoise(noisy, f, d, out, rep, err)) { std::printf("%s\n", err.c_str()); return 1; }
      char label[80];
      std::snprintf(label, sizeof label, "denoise, %s (%.0f%% narrow)", wide > 0 ? "wide off creases" : "one width",
                    100 * std::max(0.0, rep.refine_near_creases));
      show(label, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "V") {  // the denoiser with and without standing up the faces its refinement turned over
    std::string err;
    for (bool unturn : {true, false}) {
      DenoiseOptions d;
      d.refine_unturn = unturn;
      Positions out;
      DenoiseReport rep;
      if (!feature_preserving_denoise(noisy, f, d, out, rep, err)) { std::printf("%s\n", err.c_str()); return 1; }
      double refinement = 0;
      for (const StageTime& t : rep.stages) if (std::string(t.stage) == "refinement") refinement = t.seconds;
      char label[80];
      std::snprintf(label, sizeof label, "denoise (u%d, %d stood up, refinement %.2f s)", int(rep.untangled), rep.refine_unturned_faces, refinement);
      show(label, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "RS") {  // the spike removal alone, read as impulsive or not: its moves and its reading across
    SpikeRemovalReport removal;
    const Positions despiked = remove_spikes(noisy, f, vertex_adjacency(f, n), removal);
    char label[96];
    std::snprintf(label, sizeof label, "despiked (moved %d, %.4f)", removal.moved_vertices, double(removal.moved_vertices) / n);
    std::printf("  across ratio %.2f (across %d)\n", removal.across_ratio, int(removal.across));
    show(label, despiked);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "SP") {  // spikes off exactly flat hinges (impulsive noise) and the noise estimate
    std::string err;
    HamiltonianCycle cycle;
    hamiltonian_cycle(f, n, CycleOptions{}, cycle, err);
    NoiseEstimate ne;
    estimate_noise(noisy, f, cycle, EmdOptions{}, ne, err);
    const auto start = std::chrono::steady_clock::now();
    flat_hinge_spikes(noisy, f, vertex_adjacency(f, n));
    std::printf("  the reading alone (adjacency included): %.3f s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::printf("  spikes %d of %d surrounded (share %.3f, impulsive %d, spikes' RMS height %.4f); estimate imf %.4f hinge %.4f "
                "sigma %.4f; truth %.4f\n", ne.spikes.spikes, ne.spikes.surrounded, ne.spikes.share(), int(ne.impulsive()),
                ne.spike_sigma / h, ne.imf_sigma / h, ne.hinge_sigma / h, ne.relative(), noise_along_normals(clean, noisy, f));
    const auto scattered_start = std::chrono::steady_clock::now();
    scattered_spikes(noisy, f, vertex_adjacency(f, n));
    std::printf("  scattered spikes %d of %d (share %.4f, impulsive %d; read in %.3f s)\n", ne.scattered.spikes,
                ne.scattered.interior, ne.scattered.share(), int(ne.scattered_impulsive()),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - scattered_start).count());
    if (ne.scattered.impulsive()) {  // what the removal leaves: the estimate and the reading again
      SpikeRemovalReport removal;
      const auto removal_start = std::chrono::steady_clock::now();
      const Positions despiked = remove_spikes(noisy, f, vertex_adjacency(f, n), removal);
      std::printf("  the removal (adjacency included): %.3f s\n",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - removal_start).count());
      NoiseEstimate again;
      estimate_noise(despiked, f, cycle, EmdOptions{}, again, err);
      std::printf("  removal moved %d (%.4f of the vertices) in %d rounds; estimate after %.4f (before %.4f, imf %.4f); "
                  "scattered after %d (%.4f); truth left %.4f\n", removal.moved_vertices, double(removal.moved_vertices) / n,
                  removal.rounds, again.relative(), ne.relative(), again.imf_sigma / h, again.scattered.spikes,
                  again.scattered.share(), noise_along_normals(clean, despiked, f));
    if (std::getenv("LAB_DENSEGIVEN")) {  // experiment: the despiked mesh filtered at given levels
      show("despiked", despiked);
      std::printf("  despiked rms reading %.4f (mad %.4f); input rms reading %.4f\n", again.imf_rms_sigma / again.mean_edge, again.imf_sigma / again.mean_edge, ne.imf_rms_sigma / ne.mean_edge);
      for (double given : {again.relative(), again.imf_rms_sigma / again.mean_edge, 0.1, ne.relative()}) {
        DenoiseOptions d;
        d.remove_scattered_spikes = false;
        d.noise = given;
        Positions out;
        DenoiseReport rep;
        feature_preserving_denoise(despiked, f, d, out, rep, err);
        char label[64];
        std::snprintf(label, sizeof label, "denoise given %.3f", given);
        show(label, out);
        NoiseAdaptiveSmoothingOptions o = lab_options();
        o.remove_scattered_spikes = false;
        o.noise = given;
        NoiseAdaptiveSmoothingReport r;
        noise_adaptive_smooth(despiked, f, o, out, r, err);
        std::snprintf(label, sizeof label, "smooth given %.3f", given);
        show(label, out);
      }
    }
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "FE") {  // the denoiser fitting the vertices after every pass from one round's noise on, and once per round
    std::string err;
    for (bool each : {true, false}) {
      DenoiseOptions d;
      d.refine_fit_each_pass = each;
      if (std::getenv("LAB_NOROUTE")) d.smooth_surfaces_by_smoothing = false;
      Positions out;
      DenoiseReport rep;
      if (!feature_preserving_denoise(noisy, f, d, out, rep, err)) { std::printf("%s\n", err.c_str()); return 1; }
      double refinement = 0;
      for (const StageTime& t : rep.stages) if (std::string(t.stage) == "refinement") refinement = t.seconds;
      char label[96];
      std::snprintf(label, sizeof label, "denoise (sig %.3f, fit each pass %d, refinement %.2f s)", rep.sigma_used,
                    int(rep.refine_fit_each_pass), refinement);
      show(label, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "k") {  // normal error near and away from the clean creases
    std::string err;
    Positions nas, den;
    NoiseAdaptiveSmoothingReport r;
    noise_adaptive_smooth(noisy, f, lab_options(), nas, r, err);
    DenoiseOptions d;
    d.smooth_surfaces_by_smoothing = false;
    if (const char* x = std::getenv("LAB_RSIGMA")) d.refine_normal_sigma = std::atof(x);
    DenoiseReport rep;
    feature_preserving_denoise(noisy, f, d, den, rep, err);
    // faces within one ring of an edge whose clean dihedral exceeds 25 degrees
    const Positions cfn = face_normals(clean, f);
    std::map<std::pair<int, int>, int> first;
    std::vector<char> near(f.rows(), 0);
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      for (int k = 0; k < 3; ++k) {
        int a = f(i, k), b = f(i, (k + 1) % 3);
        auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = first.find(key);
        if (it == first.end()) { first[key] = int(i); continue; }
        if (cfn.row(i).dot(cfn.row(it->second)) < std::cos(25 * M_PI / 180)) near[i] = near[it->second] = 1;
      }
    std::vector<char> crease_vertex(n, 0);
    for (Eigen::Index i = 0; i < f.rows(); ++i) if (near[i]) for (int k = 0; k < 3; ++k) crease_vertex[f(i, k)] = 1;
    for (Eigen::Index i = 0; i < f.rows(); ++i) for (int k = 0; k < 3; ++k) near[i] |= crease_vertex[f(i, k)];
    std::vector<int> in_class(near.begin(), near.end());
    auto split = [&](const char* name, const Positions& p) {
      const Positions fn = face_normals(p, f);
      double e[2] = {0, 0}; int c[2] = {0, 0};
      for (Eigen::Index i = 0; i < f.rows(); ++i) {
        const double a = std::acos(std::clamp(fn.row(i).dot(cfn.row(i)), -1.0, 1.0)) * 180 / M_PI;
        e[in_class[i]] += a; c[in_class[i]]++;
      }
      std::printf("  %-14s near creases (%d faces) %6.2f  elsewhere (%d) %6.2f  all %6.2f\n", name, c[1], e[1] / std::max(1, c[1]), c[0],
                  e[0] / std::max(1, c[0]), (e[0] + e[1]) / f.rows());
    };
    split("noisy", noisy);
    split("smoothing", nas);
    split("refinement", den);
    split("taubin10", taubin(noisy, f, 10, 0.5, -0.53));
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "z") {  // where the smoothing's vertex error lives
    std::string err;
    NoiseAdaptiveSmoothingOptions o = lab_options();
    Positions out;
    NoiseAdaptiveSmoothingReport r;
    if (!noise_adaptive_smooth(noisy, f, o, out, r, err)) { std::printf("%s\n", err.c_str()); return 1; }
    show("NAS", out);
    {
      const Positions on = area_weighted_vertex_normals(out, f);
      const double cap = kTangentialCap * r.sigma_used * r.sigma_used * h;
      int over = 0;
      for (int i = 0; i < n; ++i) {
        const Eigen::RowVector3d d = out.row(i) - noisy.row(i);
        const Eigen::RowVector3d nn = on.row(i).normalized();
        over += (d - d.dot(nn) * nn).norm() > 1.05 * cap;
      }
      std::printf("  unfolded %d  vertices sliding past the cap %d of %d  sigma %.3f mu %.3f\n", r.unfolded_vertices, over, n, r.sigma_used, r.mu);
    }
    {  // the flipped faces: slivers? near-folds in the clean mesh? folded in the result?
      const Positions a = face_normals(out, f), b = face_normals(clean, f);
      const Positions cv = area_weighted_vertex_normals(clean, f), ov = area_weighted_vertex_normals(out, f);
      int shown = 0;
      for (Eigen::Index i = 0; i < f.rows() && shown < 15; ++i) {
        if (a.row(i).dot(b.row(i)) >= 0 || g_clean_folded[i]) continue;
        ++shown;
        double min_angle = 180;
        for (int k = 0; k < 3; ++k) {
          Eigen::RowVector3d e1 = clean.row(f(i, (k + 1) % 3)) - clean.row(f(i, k)), e2 = clean.row(f(i, (k + 2) % 3)) - clean.row(f(i, k));
          min_angle = std::min(min_angle, std::acos(std::clamp(e1.normalized().dot(e2.normalized()), -1.0, 1.0)) * 180 / M_PI);
        }
        const Eigen::RowVector3d cs = (cv.row(f(i, 0)) + cv.row(f(i, 1)) + cv.row(f(i, 2))).normalized();
        const Eigen::RowVector3d os = (ov.row(f(i, 0)) + ov.row(f(i, 1)) + ov.row(f(i, 2))).normalized();
        std::printf("    face %ld: min angle %.1f, clean normal vs its corners %.0f deg, result normal vs its corners %.0f deg, moves %.3f %.3f %.3f\n",
                    long(i), min_angle, std::acos(std::clamp(b.row(i).dot(cs), -1.0, 1.0)) * 180 / M_PI,
                    std::acos(std::clamp(a.row(i).dot(os), -1.0, 1.0)) * 180 / M_PI, (out.row(f(i, 0)) - noisy.row(f(i, 0))).norm() / h,
                    (out.row(f(i, 1)) - noisy.row(f(i, 1))).norm() / h, (out.row(f(i, 2)) - noisy.row(f(i, 2))).norm() / h);
      }
    }
    std::map<std::pair<int, int>, int> edge_count;
    for (Eigen::Index i = 0; i < f.rows(); ++i)
      for (int k = 0; k < 3; ++k) {
        int a = f(i, k), b = f(i, (k + 1) % 3);
        edge_count[{std::min(a, b), std::max(a, b)}]++;
      }
    std::vector<int> ring(n, -1);  // rings from the boundary
    std::vector<int> queue;
    for (auto& e : edge_count)
      if (e.second == 1) { ring[e.first.first] = 0; ring[e.first.second] = 0; }
    for (int i = 0; i < n; ++i) if (ring[i] == 0) queue.push_back(i);
    const VertexAdjacency adj = vertex_adjacency(f, n);
    for (size_t q = 0; q < queue.size(); ++q)
      for (const int* j = adj.begin(queue[q]); j != adj.end(queue[q]); ++j)
        if (ring[*j] < 0) { ring[*j] = ring[queue[q]] + 1; queue.push_back(*j); }
    const Positions cn = area_weighted_vertex_normals(clean, f);
    const double diag = (clean.colwise().maxCoeff() - clean.colwise().minCoeff()).norm();
    double sums[4][3] = {};  // ring 0, 1, 2-4, 5+: count, normal^2, tangential^2
    for (int i = 0; i < n; ++i) {
      const int b = ring[i] < 0 ? 3 : ring[i] == 0 ? 0 : ring[i] == 1 ? 1 : ring[i] <= 4 ? 2 : 3;
      const Eigen::RowVector3d d = out.row(i) - clean.row(i);
      const double dn = d.dot(cn.row(i).normalized());
      sums[b][0] += 1; sums[b][1] += dn * dn; sums[b][2] += d.squaredNorm() - dn * dn;
    }
    {
      std::vector<double> e2(n);
      for (int i = 0; i < n; ++i) e2[i] = (out.row(i) - clean.row(i)).squaredNorm();
      std::vector<double> sorted = e2;
      std::sort(sorted.rbegin(), sorted.rend());
      double total = 0, top1 = 0, top5 = 0, top20 = 0;
      for (int i = 0; i < n; ++i) { total += sorted[i]; if (i < n / 100) top1 += sorted[i]; if (i < n / 20) top5 += sorted[i]; if (i < n / 5) top20 += sorted[i]; }
      std::printf("  squared error share of the worst 1%% %.2f 5%% %.2f 20%% %.2f; largest error %.2f mean edges\n", top1 / total, top5 / total, top20 / total, std::sqrt(sorted[0]) / h);
      std::vector<int> order(n);
      for (int i = 0; i < n; ++i) order[i] = i;
      std::sort(order.begin(), order.end(), [&](int a, int b) { return e2[a] > e2[b]; });
      for (int k = 0; k < 5; ++k) {
        const int i = order[k];
        const Eigen::RowVector3d d = out.row(i) - clean.row(i), dn = noisy.row(i) - clean.row(i);
        double local = 0, longest = 0;
        for (const int* j = adj.begin(i); j != adj.end(i); ++j) { double l = (clean.row(*j) - clean.row(i)).norm() / h; local += l; longest = std::max(longest, l); }
        std::printf("    v%d error %.2f (noise %.2f) valence %d normal part %.2f  local edge %.2f longest %.2f\n", i, d.norm() / h, dn.norm() / h, adj.valence(i), std::abs(d.dot(cn.row(i).normalized())) / h, local / adj.valence(i), longest);
      }
    }
    const char* names[4] = {"boundary", "ring 1", "rings 2-4", "rings 5+"};
    double total = 0;
    for (auto& b : sums) total += b[1] + b[2];
    for (int b = 0; b < 4; ++b) {
      const double count = std::max(1.0, sums[b][0]);
      std::printf("  %-10s %6d vertices  share of squared error: normal %.3f tangential %.3f  rms normal %.1f tangential %.1f\n",
                  names[b], int(sums[b][0]), sums[b][1] / total, sums[b][2] / total, 1e4 * std::sqrt(sums[b][1] / count) / diag,
                  1e4 * std::sqrt(sums[b][2] / count) / diag);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "L") {  // oracle: which loss of the normal error tracks E_a over the strengths
    std::string err;
    const VertexAdjacency adj = vertex_adjacency(f, n);
    int patches = 0;
    const std::vector<int> patch = breadth_first_patches(adjacency(f, n), 100, patches);
    for (double strength : {0.25, 0.35, 0.5, 0.7, 1.0, 1.4, 2.0, 2.8, 4.0, 5.6}) {
      NoiseAdaptiveSmoothingOptions o = lab_options();
      o.select_cutoff = false;
      o.strength = strength;
      Positions out;
      NoiseAdaptiveSmoothingReport r;
      if (!noise_adaptive_smooth(noisy, f, o, out, r, err)) return 1;
      const Positions nn = area_weighted_vertex_normals(out, f);
      std::vector<double> e(n);
      for (int i = 0; i < n; ++i) e[i] = (out.row(i) - clean.row(i)).dot(nn.row(i)) / h;
      double l2 = 0, l1 = 0, v2 = 0, v1 = 0, wn2 = 0, w32 = 0, w31 = 0;
      std::vector<double> p2(patches, 0);
      for (int i = 0; i < n; ++i) {
        v2 += e[i] * e[i];
        v1 += std::abs(e[i]);
        for (const int* it = adj.begin(i); it != adj.end(i); ++it)
          if (const int j = *it; j > i) {
            const double d = e[i] - e[j];
            l2 += d * d;
            l1 += std::abs(d);
            p2[patch[i]] += d * d;
            const double len2 = (clean.row(i) - clean.row(j)).squaredNorm() / (h * h);
            wn2 += d * d / len2;
            const double d3 = ((out.row(i) - clean.row(i)) - (out.row(j) - clean.row(j))).squaredNorm() / (h * h);
            w32 += d3 / len2;
            w31 += std::sqrt(d3 / len2);
          }
      }
      double psq = 0;
      for (double x : p2) psq += std::sqrt(x);
      const Score sc = score(out, clean, f);
      std::printf("  L s%.2f E_a %.3f rms %.2f edgeL2 %.4g edgeL1 %.4g patchsqrt %.4g vertL2 %.4g vertL1 %.4g wn2 %.4g w32 %.4g w31 %.4g\n", strength, sc.ea, sc.rms, l2, l1, psq, v2, v1, wn2, w32, w31);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "a") {
    std::string err;
    std::vector<double> strengths = list_from_env("LAB_STRENGTHS");  // e.g. LAB_STRENGTHS=0.5,1,2
    if (strengths.empty()) strengths = {1.0};
      for (double strength : strengths) {
        NoiseAdaptiveSmoothingOptions o = lab_options();
        o.strength = strength;
        if (std::getenv("LAB_SUREEST")) {  // Stein's risk with the estimated noise
          o.noise = estimated_sigma(noisy, f);
          o.unbiased_risk = true;
        }
        Positions out;
        NoiseAdaptiveSmoothingReport r;
        if (!noise_adaptive_smooth(noisy, f, o, out, r, err)) { std::printf("%s\n", err.c_str()); return 1; }
        char name[64];
        std::snprintf(name, sizeof name, "NAS s%.2f mu %.3f%s (%.3f)%s", strength, r.mu, r.cutoff_selected ? "*" : "", r.sigma_used,
                      r.face_normal_pass ? (r.taubin_slide ? " pass slide" : " pass") : (r.taubin_slide ? " slide" : ""));
        std::printf("  finish risk change %+.5f\n", r.finish_risk_change);
        std::printf("  tangential share %.3f\n", r.tangential_share);
        if (r.spikes_removed)
          std::printf("  scattered spikes %d of %d: %d vertices put back in %d rounds\n", r.noise.scattered.spikes,
                      r.noise.scattered.interior, r.spike_removal.moved_vertices, r.spike_removal.rounds);
        show(name, out);
        if (std::getenv("LAB_TURNED")) {  // the faces left turned against the input: their tilts from the result's surface
          const Positions sn = area_weighted_vertex_normals(out, f), in_n = face_normals(noisy, f), out_n = face_normals(out, f);
          const Positions in_vn = area_weighted_vertex_normals(noisy, f);
          std::vector<std::pair<double, double>> tilts;
          for (Eigen::Index g = 0; g < f.rows(); ++g) {
            const Eigen::RowVector3d around_in = in_vn.row(f(g, 0)) + in_vn.row(f(g, 1)) + in_vn.row(f(g, 2));
            if (in_n.row(g).dot(out_n.row(g)) >= 0 || in_n.row(g).dot(around_in) < 0) continue;
            const Eigen::RowVector3d s_ = (sn.row(f(g, 0)) + sn.row(f(g, 1)) + sn.row(f(g, 2))).normalized();
            tilts.push_back({std::acos(std::clamp(in_n.row(g).dot(s_), -1.0, 1.0)) * 180 / M_PI,
                             std::acos(std::clamp(out_n.row(g).dot(s_), -1.0, 1.0)) * 180 / M_PI});
          }
          std::sort(tilts.begin(), tilts.end(), [](auto a, auto b) { return a.second < b.second; });
          std::printf("    turned %zu (%.3f%%): (input tilt, output tilt)", tilts.size(), 100.0 * tilts.size() / f.rows());
          for (size_t k = 0; k < tilts.size(); k += std::max<size_t>(1, tilts.size() / 12)) std::printf(" (%.0f,%.0f)", tilts[k].first, tilts[k].second);
          int out_over_20 = 0;
          for (auto t : tilts) out_over_20 += t.second > 20;
          std::printf(" | output tilt > 20: %d\n", out_over_20);
        }
        if (std::getenv("LAB_SPLIT")) {  // the RMS error's parts along the clean normals and across them
          const Positions cn = area_weighted_vertex_normals(clean, f);
          const Positions tb = taubin(noisy, f, 10, 0.5, -0.53);
          const double diag = (clean.colwise().maxCoeff() - clean.colwise().minCoeff()).norm();
          for (const auto& [label, p] : {std::pair<const char*, const Positions*>{"noisy", &noisy}, {"taubin10", &tb}, {"NAS", &out}}) {
            double nn2 = 0, tt2 = 0;
            for (int i = 0; i < n; ++i) {
              const Eigen::RowVector3d e = p->row(i) - clean.row(i);
              const double a = e.dot(cn.row(i).normalized());
              nn2 += a * a;
              tt2 += e.squaredNorm() - a * a;
            }
            std::printf("    %-9s RMS along the normals %.1f, across %.1f (1e-4 diag)\n", label, 1e4 * std::sqrt(nn2 / n) / diag, 1e4 * std::sqrt(tt2 / n) / diag);
          }
        }
        if (std::getenv("LAB_QUANT")) {  // where the angle error lives: quantiles, and by face size
          const Positions tb = taubin(noisy, f, 10, 0.5, -0.53);
          const Positions nc = face_normals(clean, f);
          std::vector<double> area(f.rows());
          for (Eigen::Index i = 0; i < f.rows(); ++i)
            area[i] = (clean.row(f(i, 1)) - clean.row(f(i, 0))).cross(clean.row(f(i, 2)) - clean.row(f(i, 0))).norm();
          std::vector<double> sorted_area = area;
          std::sort(sorted_area.begin(), sorted_area.end());
          const double small = sorted_area[sorted_area.size() / 4], large = sorted_area[3 * sorted_area.size() / 4];
          for (const auto& [label, p] : {std::pair<const char*, const Positions*>{"taubin10", &tb}, {"NAS", &out}}) {
            const Positions np = face_normals(*p, f);
            std::vector<double> e(f.rows());
            double s_small = 0, s_mid = 0, s_large = 0, big = 0;
            for (Eigen::Index i = 0; i < f.rows(); ++i) {
              e[i] = std::acos(std::clamp(np.row(i).dot(nc.row(i)), -1.0, 1.0)) * 180 / M_PI;
              (area[i] <= small ? s_small : area[i] >= large ? s_large : s_mid) += e[i];
              if (e[i] > 30) big += e[i];
            }
            double total = 0;
            for (double x : e) total += x;
            std::vector<double> q = e;
            std::sort(q.begin(), q.end());
            auto at = [&](double t) { return q[static_cast<size_t>(t * (q.size() - 1))]; };
            std::printf("    %-9s mean %.2f q50 %.2f q75 %.2f q90 %.2f q99 %.2f | above 30 deg: %.2f of the mean | smallest quarter %.2f, middle %.2f, largest quarter %.2f\n",
                        label, total / e.size(), at(0.5), at(0.75), at(0.9), at(0.99), big / e.size(), s_small / e.size(), s_mid / e.size(), s_large / e.size());
          }
        }
        // how much was removed along the result's normals, against the noise estimate
        const Positions nn = area_weighted_vertex_normals(out, f);
        double normal2 = 0, all2 = 0;
        for (int i = 0; i < n; ++i) {
          const Eigen::RowVector3d d = noisy.row(i) - out.row(i);
          normal2 += std::pow(d.dot(nn.row(i)), 2);
          all2 += d.squaredNorm();
        }
        std::printf("      removed: normal %.3f  all %.3f (x sigma)\n", std::sqrt(normal2 / n) / (h * r.sigma_used),
                    std::sqrt(all2 / n) / (h * r.sigma_used));
      }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "b") {
    std::string err;
    const double scale = 1.0 / h;
    Positions v = noisy * scale;
    Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
    Eigen::SparseMatrix<double> L2 = L * L;
    for (double mu : {0.3, 0.4, 0.5, 0.7}) {
      Positions b2 = ls_solve(L2, Positions::Zero(n, 3), v, mu * mu);
      char name[64];
      std::snprintf(name, sizeof name, "BW2 mu %.2f", mu);
      show(name, b2 / scale);
      for (double cap : {1.0, 2.0}) {
        // tangential moves capped at cap * level (in mean edges)
        MeanCurvature mc;
        mean_curvature(b2, f, mc, err);
        Positions out = b2;
        for (int i = 0; i < n; ++i) {
          Eigen::RowVector3d d = b2.row(i) - v.row(i);
          Eigen::RowVector3d nn = mc.normals.row(i);
          Eigen::RowVector3d t = d - d.dot(nn) * nn;
          double len = t.norm(), lim = cap * level;
          if (len > lim) out.row(i) -= t * (1 - lim / len);
        }
        std::snprintf(name, sizeof name, "BW2 mu %.2f tcap %.1f", mu, cap);
        show(name, out / scale);
      }
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "m") {
    std::string err;
    NoiseAdaptiveSmoothingOptions o = lab_options();
    Positions out;
    NoiseAdaptiveSmoothingReport r;
    noise_adaptive_smooth(noisy, f, o, out, r, err);
    const double sig = r.sigma_used;
    show("NAS default", out);
    for (double kappa : {0.8, 1.0, 1.2}) {
      double mu = 1.5;
      Positions best;
      double removed = 0;
      for (int it = 0; it < 20; ++it, mu /= 1.15) {
        o.mu = mu;
        o.noise = sig;
        o.select_cutoff = false;
        noise_adaptive_smooth(noisy, f, o, out, r, err);
        MeanCurvature mc;
        mean_curvature(out, f, mc, err);
        removed = 0;
        for (int i = 0; i < n; ++i) removed += std::pow((out.row(i) - noisy.row(i)).dot(mc.normals.row(i)), 2);
        removed = std::sqrt(removed / n) / h;
        if (removed >= kappa * sig) break;
      }
      char name[64];
      std::snprintf(name, sizeof name, "discrepancy k%.1f mu %.2f", kappa, mu);
      show(name, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "g") {
    std::string err;
    {
      HamiltonianCycle c;
      hamiltonian_cycle(f, n, CycleOptions{}, c, err);
      NoiseEstimate ne;
      estimate_noise(noisy, f, c, EmdOptions{}, ne, err);
      std::printf("  estimated sigma %.3f\n", ne.relative());
    }
    for (double sig : {0.25, 0.35})
    for (int rounds : {1, 2, 3})
      for (int passes : {4, 8})
        for (int vit : {20}) {
          GuidedNormalDenoiseOptions o;
          o.sigma = sig;
          o.rounds = rounds;
          o.normal_passes = passes;
          o.vertex_iterations = vit;
          Positions out;
          guided_normal_denoise(noisy, f, o, out, err);
          char name[64];
          std::snprintf(name, sizeof name, "GND s%.2f r%d p%d v%d", sig, rounds, passes, vit);
          show(name, out);
        }
    DenoiseOptions d;
    d.features.filter_iterations = 8;
    Positions out;
    DenoiseReport rep;
    feature_preserving_denoise(noisy, f, d, out, rep, err);
    show("denoise.mlx", out);
    std::printf("  flipped %d of %d, untangled %d, sigma %.3f rounds %d\n", rep.flipped_faces, int(f.rows()), int(rep.untangled), rep.sigma_used, rep.refine_rounds);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "c") {
    std::string err;
    for (double strength : {0.3, 1.0}) {
      NoiseAdaptiveSmoothingOptions o = lab_options();
      o.strength = strength;
      Positions pre;
      NoiseAdaptiveSmoothingReport r;
      noise_adaptive_smooth(noisy, f, o, pre, r, err);
      const int rounds = std::max(1, int(std::lround(r.sigma_used / 0.12)));
      GuidedNormalDenoiseOptions g;
      g.sigma = 0.25;
      g.rounds = rounds;
      Positions out;
      guided_normal_denoise(pre, f, g, out, err);
      char name[64];
      std::snprintf(name, sizeof name, "NAS s%.1f + GND r%d", strength, rounds);
      show(name, out);
      guided_normal_denoise(noisy, f, g, out, err);
      std::snprintf(name, sizeof name, "GND r%d", rounds);
      show(name, out);
    }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "e") {
    std::string err;
    SpectralMeshFilterOptions o;
    o.band = {0.1, 0.5, false};
    o.gain = 2;
    o.reconstruction.lambda = 0.1;
    if (std::getenv("LAB_IDT")) o.laplacian_triangles = LaplacianTriangles::IntrinsicDelaunay;
    Positions out;
    SpectralMeshFilterReport r;
    spectral_mesh_filter(noisy, f, o, out, r, err);
    show("enhance.mlx", out);
    std::printf("  vertices the flip guard put back: %d\n", r.restored_vertices);
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "spec") {  // the Spectral Filter's smoothing at other settings (item 39)
    std::string err;
    std::vector<double> lambdas = list_from_env("LAB_SPEC_LAMBDAS"), cycle_counts = list_from_env("LAB_SPEC_CYCLES");
    if (lambdas.empty()) lambdas = {0.01};
    if (cycle_counts.empty()) cycle_counts = {1};
    for (double lambda : lambdas)
      for (double cycles : cycle_counts) {
        SpectralMeshFilterOptions o;  // gain 0 above 0.1: the paper's smoothing
        o.cycles = int(cycles);
        o.reconstruction.lambda = lambda;
        if (std::getenv("LAB_IDT")) o.laplacian_triangles = LaplacianTriangles::IntrinsicDelaunay;
        Positions out;
        SpectralMeshFilterReport r;
        if (!spectral_mesh_filter(noisy, f, o, out, r, err)) { std::printf("%s\n", err.c_str()); continue; }
        char name[64];
        std::snprintf(name, sizeof name, "spectral lambda %.3f, %d cycles", lambda, int(cycles));
        show(name, out);
        if (std::getenv("LAB_SPEC_GUARD")) {  // every face turned over against the input stood up
          unturn_few_turned_faces(noisy, f, 1.0, out);
          std::snprintf(name, sizeof name, "  + turned faces stood up");
          show(name, out);
        }
      }
    return 0;
  }
  if (argc > 3 && std::string(argv[3]) == "s") {
    std::string err;
    for (int nt : {3, 10})
      for (int nn : {5, 10, 20, 40}) {
        Positions a = taubin(noisy, f, nt, 0.5, -0.53), b = taubin(noisy, f, nn, 0.5, -0.53);
        MeanCurvature ma;
        mean_curvature(a, f, ma, err);
        Positions out = a;
        for (int i = 0; i < n; ++i) out.row(i) += ma.normals.row(i) * (b.row(i) - a.row(i)).dot(ma.normals.row(i));
        char name[64];
        std::snprintf(name, sizeof name, "tangential T%d normal T%d", nt, nn);
        show(name, out);
      }
    return 0;
  }
  {
    std::string err;
    for (int steps : {10, 30}) {
      Positions base = taubin(noisy, f, steps, 0.5, -0.53);
      MeanCurvature mb;
      mean_curvature(base, f, mb, err);
      Eigen::VectorXd hgt(n);
      for (int i = 0; i < n; ++i) hgt[i] = (noisy.row(i) - base.row(i)).dot(mb.normals.row(i));
      for (int cycles : {4, 16})
        for (double cut : {0.02, 0.05, 0.1}) {
          Eigen::VectorXd hf = hht_lowpass(hgt, f, n, cycles, cut);
          Positions out = base;
          for (int i = 0; i < n; ++i) out.row(i) += hf[i] * mb.normals.row(i);
          char name[64];
          std::snprintf(name, sizeof name, "base T%d + h cyc %d cut %.2f", steps, cycles, cut);
          show(name, out);
        }
    }
  }
  if (argc > 3) return 0;
  const double scale = 1.0 / h;
  Positions v = noisy * scale;
  Eigen::SparseMatrix<double> L = uniform_laplacian(f, n);
  Positions d = L * v;
  for (double mu : {0.3, 0.5, 1.0}) {
    char name[64];
    std::snprintf(name, sizeof name, "LS0 mu %.2f", mu);
    show(name, ls_solve(L, Positions::Zero(n, 3), v, mu) / scale);
    for (double cut : {0.05, 0.1}) {
      Positions dl(n, 3);
      for (int k = 0; k < 3; ++k) dl.col(k) = hht_lowpass(d.col(k), f, n, 4, cut);
      std::snprintf(name, sizeof name, "LSH mu %.2f cut %.2f", mu, cut);
      show(name, ls_solve(L, dl, v, mu) / scale);
    }
  }
  return 0;
}
