// The reconstruction of eq. 9-11 on mesh files: (1) the drift of the paper's literal target
// (G~ n) against the keep-tangential target when the signal is unchanged, (2) the time of the
// preconditioned CG solve against the direct Cholesky factorisation of the normal equations,
// for a smoothing-sized change of the signal (G halved).
//   reconstruction_bench [--direct] mesh [more meshes]   (--direct: also time the direct solve)
#include "bench_util.h"
#include "reconstruction/laplacian_reconstruction.h"

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  bool direct = false;
  std::printf("| mesh | vertices | drift, literal target | drift, keep-tangential | CG: factor + solve (s) | CG iterations | direct: factor + solve (s) | CG vs direct |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--direct")) {
      direct = true;
      continue;
    }
    hht::Positions p, r;
    hht::Faces f;
    if (!hht::bench::load_mesh(argv[i], p, f)) return 1;
    const double diag = (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm();
    hht::MeanCurvature h;
    std::string error;
    hht::mean_curvature(p, f, h, error);
    hht::ReconstructionReport rep;
    double drift[2];
    for (int t = 0; t < 2; ++t) {
      hht::ReconstructionOptions o;
      o.target = t == 0 ? hht::ReconstructionTarget::NormalOnly : hht::ReconstructionTarget::KeepTangential;
      hht::reconstruct_positions(p, f, h, h.signal, o, r, rep, error);
      drift[t] = (r - p).rowwise().norm().maxCoeff() / diag;
    }
    const Eigen::VectorXd half = 0.5 * h.signal;
    hht::Positions iterative, exact;
    hht::reconstruct_positions(p, f, h, half, {}, iterative, rep, error);
    const hht::ReconstructionReport cg = rep;
    std::printf("| %s | %lld | %.2e | %.2e | %.2f + %.2f | %d |", argv[i], static_cast<long long>(p.rows()), drift[0],
                drift[1], cg.factor_seconds, cg.solve_seconds, cg.iterations);
    if (direct) {
      hht::ReconstructionOptions o;
      o.direct = true;
      hht::reconstruct_positions(p, f, h, half, o, exact, rep, error);
      std::printf(" %.2f + %.2f | %.1e |\n", rep.factor_seconds, rep.solve_seconds,
                  (iterative - exact).rowwise().norm().maxCoeff() / diag);
    } else {
      std::printf(" - | - |\n");
    }
  }
  return 0;
}
