#include "filters/surface_emd.h"

#include "mesh/cotangent_laplacian.h"
#include "mesh/mesh_checks.h"

#include <Eigen/Sparse>

#include <cholmod.h>
#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <thread>

namespace hht {

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The lower triangle of a symmetric Eigen matrix, as CHOLMOD reads it (no copy).
cholmod_sparse view(Sparse& m) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(m.rows());
  s.ncol = static_cast<size_t>(m.cols());
  s.nzmax = static_cast<size_t>(m.nonZeros());
  s.p = m.outerIndexPtr();
  s.i = m.innerIndexPtr();
  s.x = m.valuePtr();
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

// While the two envelopes are factored on two threads, a multi-threaded BLAS (OpenBLAS) would
// start its own threads inside each factorisation: more threads than cores, which made the
// surface EMD 1.7x slower than with reference BLAS at 70k vertices. OpenBLAS is held to one
// thread per call for the scope; with any other BLAS (no such symbol) nothing changes.
class SingleThreadedBlas {
 public:
  SingleThreadedBlas() {
    set_ = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    auto get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    if (set_ == nullptr || get == nullptr) {
      set_ = nullptr;
      return;
    }
    previous_ = get();
    set_(1);
  }
  ~SingleThreadedBlas() {
    if (set_ != nullptr) set_(previous_);
  }
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  void (*set_)(int) = nullptr;
  int previous_ = 1;
};

// (value, index) ordering: a strict total order, so ties cannot hide every extremum.
inline bool above(double a, int i, double b, int j) { return a > b || (a == b && i > j); }

// The bi-harmonic envelope through a changing set of constrained vertices (see the header), with
// CHOLMOD's own interface: one analysis, copied to the second envelope's solver, and numeric
// refactorisations into the same factor.
class EnvelopeSolver {
 public:
  explicit EnvelopeSolver(const Sparse& a) : a_(a), k_(a) {
    const int n = static_cast<int>(a.rows());
    diagonal_.resize(n);
    for (int j = 0; j < n; ++j) {
      const double d = a.coeff(j, j);
      diagonal_[j] = d > 0.0 ? d : 1.0;  // vertices of no face: any positive scale
    }
    cholmod_start(&common_);
  }
  EnvelopeSolver(const EnvelopeSolver&) = delete;
  EnvelopeSolver& operator=(const EnvelopeSolver&) = delete;
  ~EnvelopeSolver() {
    if (factor_ != nullptr) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }

  // Symbolic analysis of the (fixed) pattern: AMD and METIS orderings are both tried and the one
  // with less fill kept (METIS halves the fill on meshes of 100k vertices and more).
  bool analyse() {
    common_.nmethods = 2;
    common_.method[0].ordering = CHOLMOD_AMD;
    common_.method[1].ordering = CHOLMOD_METIS;
    cholmod_sparse k = view(k_);
    factor_ = cholmod_analyze(&k, &common_);
    return factor_ != nullptr;
  }

  bool copy_analysis(EnvelopeSolver& from) {
    factor_ = cholmod_copy_factor(from.factor_, &common_);
    return factor_ != nullptr;
  }

  bool solve(const std::vector<unsigned char>& constrained, const Eigen::VectorXd& s, Eigen::VectorXd& envelope) {
    assemble(constrained, s);
    cholmod_sparse k = view(k_);
    if (!cholmod_factorize(&k, factor_, &common_) || common_.status < CHOLMOD_OK || factor_->minor < factor_->n)
      return false;
    cholmod_dense b{};
    b.nrow = b.nzmax = b.d = static_cast<size_t>(b_.size());
    b.ncol = 1;
    b.x = b_.data();
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &b, &common_);
    if (x == nullptr) return false;
    envelope = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b_.size());
    cholmod_free_dense(&x, &common_);
    for (Eigen::Index i = 0; i < s.size(); ++i)
      if (constrained[i]) envelope[i] = s[i];  // exact at the constraints
    return envelope.allFinite();
  }

 private:
  // K: a_ with constrained rows and columns replaced by their diagonal (pattern unchanged);
  // b: -a_FX s_X on free rows, diagonal * s on constrained ones.
  void assemble(const std::vector<unsigned char>& constrained, const Eigen::VectorXd& s) {
    const int n = static_cast<int>(a_.cols());
    const double* from = a_.valuePtr();
    double* to = k_.valuePtr();
    const int* inner = a_.innerIndexPtr();
    const int* outer = a_.outerIndexPtr();
    Eigen::VectorXd fixed(n);
    for (int j = 0; j < n; ++j) {
      fixed[j] = constrained[j] ? s[j] : 0.0;
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int i = inner[k];
        if (!constrained[i] && !constrained[j]) {
          to[k] = from[k];
        } else {
          to[k] = i == j ? diagonal_[j] : 0.0;
        }
      }
    }
    b_ = -(a_ * fixed);
    for (int i = 0; i < n; ++i)
      if (constrained[i]) b_[i] = diagonal_[i] * s[i];
  }

  const Sparse& a_;
  Sparse k_;
  Eigen::VectorXd diagonal_, b_;
  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
};

bool check_faces(const Faces& faces, int n, std::string& error) {
  Eigen::Index out_of_range = 0, repeated = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    for (int k = 0; k < 3; ++k) out_of_range += faces(f, k) < 0 || faces(f, k) >= n ? 1 : 0;
    repeated += faces(f, 0) == faces(f, 1) || faces(f, 1) == faces(f, 2) || faces(f, 0) == faces(f, 2) ? 1 : 0;
  }
  if (out_of_range > 0) {
    error = std::to_string(out_of_range) + " face corners index no vertex";
    return false;
  }
  if (repeated > 0) {
    error = std::to_string(repeated) + " faces repeat a vertex; remove degenerate faces first";
    return false;
  }
  return true;
}

}  // namespace

void one_ring_adjacency(const Faces& faces, int vertex_count, std::vector<int>& offset, std::vector<int>& neighbours) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(static_cast<size_t>(faces.rows()) * 6);
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % 3);
      edges.emplace_back(a, b);
      edges.emplace_back(b, a);
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  offset.assign(vertex_count + 1, 0);
  for (const auto& e : edges) ++offset[e.first + 1];
  for (int v = 0; v < vertex_count; ++v) offset[v + 1] += offset[v];
  neighbours.resize(edges.size());
  for (size_t k = 0; k < edges.size(); ++k) neighbours[k] = edges[k].second;
}

void surface_extrema(const std::vector<int>& offset, const std::vector<int>& neighbours, const Eigen::VectorXd& s,
                     const std::vector<unsigned char>* excluded, SurfaceExtrema& out) {
  out.maxima.clear();
  out.minima.clear();
  const int n = static_cast<int>(s.size());
  for (int v = 0; v < n; ++v) {
    if (excluded != nullptr && (*excluded)[v]) continue;
    bool is_max = true, is_min = true;
    for (int k = offset[v]; k < offset[v + 1] && (is_max || is_min); ++k) {
      const int u = neighbours[k];
      if (excluded != nullptr && (*excluded)[u]) continue;
      if (above(s[v], v, s[u], u)) {
        is_min = false;
      } else {
        is_max = false;
      }
    }
    if (offset[v] == offset[v + 1]) continue;  // a vertex of no face
    if (is_max) out.maxima.push_back(v);
    if (is_min) out.minima.push_back(v);
  }
}

bool surface_emd(const Positions& positions, const Faces& faces, const Eigen::VectorXd& signal,
                 const SurfaceEmdOptions& options, SurfaceEmdResult& result, std::string& error) {
  result = SurfaceEmdResult{};
  const int n = static_cast<int>(positions.rows());
  if (!check_triangle_mesh(positions, faces, error) || !check_faces(faces, n, error)) return false;
  if (signal.size() != n) {
    error = "the signal has " + std::to_string(signal.size()) + " values for " + std::to_string(n) + " vertices";
    return false;
  }
  if (!signal.allFinite()) {
    error = "the signal holds NaN or infinite values";
    return false;
  }
  if (options.feature_vertices != nullptr && options.feature_vertices->size() != static_cast<size_t>(n)) {
    error = "the feature mask has " + std::to_string(options.feature_vertices->size()) + " flags for " +
            std::to_string(n) + " vertices";
    return false;
  }

  std::vector<int> offset, neighbours;
  one_ring_adjacency(faces, n, offset, neighbours);

  // Pinned: in both constraint sets always, IMFs zero there. Vertices of no face, and every
  // vertex of a component made of feature vertices only (no extremum would constrain it).
  std::vector<unsigned char> pinned(n, 0), excluded(n, 0);
  {
    std::vector<int> component(n, -1);
    for (int seed = 0; seed < n; ++seed) {
      if (component[seed] >= 0) continue;
      std::vector<int> members{seed};
      component[seed] = seed;
      bool has_free = false;
      for (size_t m = 0; m < members.size(); ++m) {
        const int v = members[m];
        if (offset[v] < offset[v + 1] && (options.feature_vertices == nullptr || !(*options.feature_vertices)[v]))
          has_free = true;
        for (int k = offset[v]; k < offset[v + 1]; ++k)
          if (component[neighbours[k]] < 0) {
            component[neighbours[k]] = seed;
            members.push_back(neighbours[k]);
          }
      }
      if (!has_free)
        for (int v : members) pinned[v] = 1;
    }
    for (int v = 0; v < n; ++v)
      excluded[v] = pinned[v] || (options.feature_vertices != nullptr && (*options.feature_vertices)[v]) ? 1 : 0;
  }

  // A = C M^-1 C with every diagonal entry stored (vertices of no face have an empty row).
  const CotangentLaplacian laplacian = extrinsic_cotangent_laplacian(positions, faces);  // as published
  const Sparse c = cotangent_matrix(laplacian, n);
  Eigen::VectorXd areas = laplacian.areas;
  const double floor_area = 1e-8 * std::max(areas.sum() / std::max(n, 1), std::numeric_limits<double>::min());
  for (Eigen::Index i = 0; i < areas.size(); ++i) areas[i] = 1.0 / std::max(areas[i], floor_area);
  Sparse diagonal(n, n);
  {
    std::vector<Eigen::Triplet<double>> zeros;
    zeros.reserve(n);
    for (int i = 0; i < n; ++i) zeros.emplace_back(i, i, 0.0);
    diagonal.setFromTriplets(zeros.begin(), zeros.end());
  }
  Sparse a = Sparse(c * areas.asDiagonal() * c) + diagonal;
  a.makeCompressed();

  EnvelopeSolver upper(a), lower(a);
  const auto analysis_start = Clock::now();
  if (!upper.analyse() || !lower.copy_analysis(upper)) {
    error = "the analysis of the bi-harmonic envelope system failed (out of memory?)";
    return false;
  }
  result.report.analysis_seconds = since(analysis_start);

  const int min_extrema = std::max(options.min_extrema, 1);
  const int max_sifts = std::max(options.max_sifts, 1);
  const bool parallel = options.threads >= 2;
  std::optional<SingleThreadedBlas> blas_scope;
  if (parallel) blas_scope.emplace();
  result.residue = signal;
  Eigen::VectorXd& r = result.residue;
  Eigen::VectorXd upper_envelope, lower_envelope;
  std::vector<unsigned char> at_max(n), at_min(n);
  SurfaceExtrema extrema;
  long previous_extrema = std::numeric_limits<long>::max();
  while (options.max_imfs <= 0 || static_cast<int>(result.imfs.size()) < options.max_imfs) {
    surface_extrema(offset, neighbours, r, &excluded, extrema);
    const long count = static_cast<long>(extrema.maxima.size()) + static_cast<long>(extrema.minima.size());
    if (static_cast<int>(extrema.maxima.size()) < min_extrema || static_cast<int>(extrema.minima.size()) < min_extrema ||
        count >= previous_extrema)
      break;
    previous_extrema = count;
    Eigen::VectorXd s = r;
    int sifts = 0;
    while (sifts < max_sifts) {
      surface_extrema(offset, neighbours, s, &excluded, extrema);
      if (extrema.maxima.empty() || extrema.minima.empty()) break;
      at_max = pinned;
      at_min = pinned;
      for (int v : extrema.maxima) at_max[v] = 1;
      for (int v : extrema.minima) at_min[v] = 1;
      bool upper_ok = false, lower_ok = false;
      if (parallel) {
        std::exception_ptr lower_failure;
        std::thread worker([&] {
          try {
            lower_ok = lower.solve(at_min, s, lower_envelope);
          } catch (...) {
            lower_failure = std::current_exception();
          }
        });
        try {
          upper_ok = upper.solve(at_max, s, upper_envelope);
        } catch (...) {
          worker.join();
          throw;
        }
        worker.join();
        if (lower_failure) std::rethrow_exception(lower_failure);
      } else {
        upper_ok = upper.solve(at_max, s, upper_envelope);
        lower_ok = lower.solve(at_min, s, lower_envelope);
      }
      result.report.factorizations += 2;
      if (!upper_ok || !lower_ok) {
        error = "the factorisation of the bi-harmonic envelope system failed (degenerate triangles?)";
        return false;
      }
      double change = 0.0, before = 0.0;
      for (int v = 0; v < n; ++v) {
        const double mean = excluded[v] ? s[v] : 0.5 * (upper_envelope[v] + lower_envelope[v]);
        change += mean * mean;
        before += s[v] * s[v];
        s[v] -= mean;
      }
      ++sifts;
      if ((before > 0.0 ? change / before : 0.0) < options.sd_threshold) break;
    }
    r -= s;
    result.imfs.push_back(std::move(s));
    result.sifts.push_back(sifts);
  }
  return true;
}

}  // namespace hht
