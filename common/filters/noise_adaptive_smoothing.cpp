#include "filters/noise_adaptive_smoothing.h"

#include "evaluation/gaussian_noise.h"
#include "mesh/border_neighbours.h"
#include "mesh/breadth_first_patches.h"
#include "mesh/mesh_checks.h"
#include "mesh/tangential_noise.h"
#include "mesh/vertex_adjacency.h"
#include "mesh/vertex_normals.h"
#include "reconstruction/biharmonic_low_pass.h"
#include "reconstruction/cutoff_selection.h"
#include "reconstruction/keep_untouched_vertices.h"
#include "reconstruction/face_normal_pass.h"
#include "reconstruction/flip_guard.h"
#include "reconstruction/recorrupted_risk.h"
#include "reconstruction/taubin_smoothing.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace hht {

namespace {

// Faces pointing away from the surface around them (their normal against the mean of their
// vertices' normals) are folds, left where a sliver's vertices slid past each other: their
// vertices are moved to their one-ring centroids until none is left (a few passes at most).
int unfold(Positions& x, const Faces& faces, const VertexAdjacency& adjacency) {
  std::vector<unsigned char> moved(x.rows(), 0);
  for (int pass = 0; pass < 10; ++pass) {
    const Positions vertex_normals = area_weighted_vertex_normals(x, faces);
    const Positions normals = unit_face_normals(x, faces);
    std::vector<int> folded;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      const Eigen::RowVector3d around =
          vertex_normals.row(faces(f, 0)) + vertex_normals.row(faces(f, 1)) + vertex_normals.row(faces(f, 2));
      if (normals.row(f).dot(around) < 0)
        for (int k = 0; k < 3; ++k) folded.push_back(faces(f, k));
    }
    if (folded.empty()) break;
    for (int i : folded) {
      if (adjacency.valence(i) == 0) continue;
      Eigen::RowVector3d centroid = Eigen::RowVector3d::Zero();
      for (const int* j = adjacency.begin(i); j != adjacency.end(i); ++j) centroid += x.row(*j);
      x.row(i) = centroid / static_cast<double>(adjacency.valence(i));
      moved[i] = 1;
    }
  }
  return static_cast<int>(std::count(moved.begin(), moved.end(), 1));
}

// No vertex is moved further than `radius` from where it was: the graph filter moves a vertex
// whose edges are long (a CAD fan) by a fraction of those edges, several mean edges, though the
// noise displaced it by a few sigma only. Returns how many vertices were held.
int hold_within_noise(Positions& x, const Positions& v, double radius) {
  int held = 0;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const Eigen::RowVector3d move = x.row(i) - v.row(i);
    const double length = move.norm();
    if (length <= radius) continue;
    x.row(i) = v.row(i) + move * (radius / length);
    ++held;
  }
  return held;
}

struct FinishCounts {
  int border_held = 0, unfolded = 0, held = 0, restored = 0, unturned = 0;
};

// Step 3 by the cap, on the solve's output `solved` for the input `v` (unit mean edge); `share`
// scales the cap (tangential_noise.h).
Positions capped_slides(const Positions& solved, const Positions& v, const Faces& faces, double sigma, double share,
                        const NoiseAdaptiveSmoothingOptions& options) {
  // Tangential moves capped, by as much less as the input holds less tangential noise than
  // isotropic noise of sigma would give it, except around faces the cap would leave tilted (more
  // than 60 degrees from the uncapped result's face): there the slide untangles noise-flipped
  // triangles.
  Positions x = solved;
  const double cap = options.tangential_cap * sigma * sigma * share * options.strength;
  const Positions normals = area_weighted_vertex_normals(x, faces);
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const Eigen::RowVector3d move = x.row(i) - v.row(i);
    const Eigen::RowVector3d normal = normals.row(i);
    const Eigen::RowVector3d tangential = move - move.dot(normal) * normal;
    const double length = tangential.norm();
    if (length > cap) x.row(i) -= tangential * (1 - cap / length);
  }
  // The faces left tilted are read before any is put back in a pass; one flag a face, not two
  // arrays of normals (this step is near the smoothing's peak memory on large meshes).
  std::vector<unsigned char> tilted(faces.rows());
  for (int pass = 0; pass < 3; ++pass) {
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
      tilted[f] = !(unit_face_normal(x, faces, f).dot(unit_face_normal(solved, faces, f)) >= 0.5);
    bool changed = false;
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
      if (!tilted[f]) continue;
      for (int k = 0; k < 3; ++k) {
        const int i = faces(f, k);
        changed |= x.row(i) != solved.row(i);
        x.row(i) = solved.row(i);
      }
    }
    if (!changed) break;
  }
  return x;
}

// Step 3 by Taubin's slide: the solve's move along `unit_normals` (v's smoothed vertex normals),
// Taubin's smoothing's move across them, uncapped.
Positions taubin_slides(const Positions& solved, const Positions& v, const Positions& unit_normals,
                        const VertexAdjacency& adjacency) {
  const Positions taubin = taubin_smoothing(adjacency, v);
  Positions x(v.rows(), 3);
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    const Eigen::RowVector3d normal = unit_normals.row(i);
    const Eigen::RowVector3d along = (solved.row(i) - v.row(i)).dot(normal) * normal, slide = taubin.row(i) - v.row(i);
    x.row(i) = v.row(i) + along + slide - slide.dot(normal) * normal;
  }
  return x;
}

std::vector<SmoothingFinish> allowed_finishes(const NoiseAdaptiveSmoothingOptions& options, double share) {
  if (options.forced_finish >= 0) return {{(options.forced_finish & 1) != 0, (options.forced_finish & 2) != 0}};
  // Where the input holds clearly less tangential noise than isotropic noise of sigma (share
  // below kSlideShare), the slide would be mostly error, and the copies' risk cannot see it:
  // their tangential noise is drawn at the share, which the triangulation's own offsets fill
  // (docs/quality.md items 22 and 23).
  const bool slide_allowed = options.taubin_slide && share >= kSlideShare;
  std::vector<SmoothingFinish> finishes;
  for (bool slide : {false, true})
    for (bool pass : {false, true})
      if ((!slide || slide_allowed) && (!pass || options.face_normal_pass)) finishes.push_back({slide, pass});
  return finishes;
}

// Step 3, Taubin's slide or the cap, then the borders held (item 35), and step 4 on the solve's
// output `solved` for the input `v`; `v_normals`: v's smoothed vertex normals.
Positions slid_and_unfolded(const Positions& solved, const Positions& v, const Positions& v_normals, const Faces& faces,
                            const VertexAdjacency& adjacency, const BorderNeighbours& border, double sigma,
                            double share, bool taubin_slide, const NoiseAdaptiveSmoothingOptions& options,
                            FinishCounts& counts) {
  Positions x = taubin_slide ? taubin_slides(solved, v, v_normals, adjacency)
                             : capped_slides(solved, v, faces, sigma, share, options);
  if (options.hold_borders)
    counts.border_held = clamp_moves_across_borders(v, v_normals, border, x, kBorderMoveAcross * sigma);
  counts.unfolded = unfold(x, faces, adjacency);
  return x;
}

// Step 4b when `normal_pass`, then steps 5-7, on the output `x` of slid_and_unfolded.
Positions finish_smoothing(Positions x, const Positions& v, const Faces& faces, double sigma, bool normal_pass,
                           const NoiseAdaptiveSmoothingOptions& options, FinishCounts& counts) {
  if (normal_pass) x = face_normal_pass(x, faces);
  counts.held = hold_within_noise(x, v, options.move_radius * sigma * std::max(1.0, options.strength));
  counts.restored = restore_turned_faces_that_fit(v, faces, kRestoredFaceTilt, x);
  counts.unturned = options.unturn_wrinkles ? unturn_few_turned_faces(v, faces, kWrinkleShare, x) : 0;
  return x;
}

// The recorrupted risks of the smoothing at cut-off `mu` with each of `finishes`, on breadth-first
// patches of a large mesh. False if a copy's solve failed. `v_normals`: v's smoothed vertex normals.
bool finish_risks(const Positions& v, const Positions& v_normals, const Faces& faces, const VertexAdjacency& adjacency,
                  const BorderNeighbours& full_border, double sigma, double tangential_share, double mu,
                  double max_error,
                  const NoiseAdaptiveSmoothingOptions& options, const std::vector<SmoothingFinish>& finishes,
                  RecorruptedRisks& risks) {
  const bool sample = v.rows() > kPassSampleVertices;
  std::vector<int> kept;
  Faces sampled_faces;
  Positions sampled_v;
  VertexAdjacency sampled_adjacency;
  if (sample) {
    kept = breadth_first_patches(adjacency, kPassSampleVertices, kPassPatches);
    sampled_faces = faces_among(faces, static_cast<int>(v.rows()), kept);
    sampled_v = rows_at(v, kept);
    sampled_adjacency = vertex_adjacency(sampled_faces, static_cast<int>(kept.size()));
  }
  const Faces& f = sample ? sampled_faces : faces;
  const VertexAdjacency& a = sample ? sampled_adjacency : adjacency;
  // The mesh's own borders, not the patches' rims.
  const BorderNeighbours sampled_border =
      sample && options.hold_borders ? border_neighbours_among(full_border, kept) : BorderNeighbours{};
  const BorderNeighbours& border = sample ? sampled_border : full_border;
  // The copies' noise is sqrt(1 + a^2) times the input's: the smoothing run on them is the one
  // set for that noise, its cut-off by the noise law's scaling (mu ~ 1 / sqrt(sigma)), its cap and
  // hold by the noise. With the input's cut-off the copies are smoothed too little, which
  // favours the pass (lab: 52 of the 66 organic cases below Taubin on both numbers, against 53).
  const double copy_sigma = sigma * std::sqrt(1 + kRecorruptionScale * kRecorruptionScale);
  const double copy_mu = mu / std::sqrt(copy_sigma / sigma);
  auto run = [&](const Positions& y1, std::vector<Positions>& outputs) {
    Positions solved;
    BiharmonicLowPassReport solve;
    if (!biharmonic_low_pass(a, y1, copy_mu, options.first_order, max_error, solved, solve)) return false;
    const Positions y1_normals = smoothed_vertex_normals(y1, f, a);
    const double share = options.tangential_share ? tangential_noise_share(y1, y1_normals, a, copy_sigma) : 1.0;
    // Step 3 once each way (the finishes with and without the pass share it).
    std::optional<Positions> slid[2];
    FinishCounts counts;
    outputs.clear();
    for (const SmoothingFinish& finish : finishes) {
      std::optional<Positions>& x = slid[finish.taubin_slide];
      if (!x)
        x = slid_and_unfolded(solved, y1, y1_normals, f, a, border, copy_sigma, share, finish.taubin_slide, options, counts);
      outputs.push_back(finish_smoothing(*x, y1, f, copy_sigma, finish.normal_pass, options, counts));
    }
    return true;
  };
  // The copies' noise has the input's shape: with little tangential noise (noise along the
  // normals), isotropic copies would score the smoothing on noise the input does not have.
  const Positions& y = sample ? sampled_v : v;
  NoiseShape shape;
  shape.tangential_share = tangential_share;
  if (tangential_share < 1) shape.unit_normals = sample ? smoothed_vertex_normals(y, f, a) : v_normals;
  return recorrupted_risks(y, sigma * options.copy_noise_scale, shape, kPassDraws, kPassSeed, run, risks);
}

}  // namespace

size_t choose_finish(const std::vector<SmoothingFinish>& finishes, const std::vector<std::vector<double>>& per_draw,
                     const std::vector<double>& mean) {
  size_t best = 0, capped = finishes.size();
  for (size_t k = 0; k < finishes.size(); ++k) {
    if (mean[k] < mean[best]) best = k;
    if (!finishes[k].taubin_slide && (capped == finishes.size() || mean[k] < mean[capped])) capped = k;
  }
  if (capped == finishes.size()) return best;
  for (const std::vector<double>& draw : per_draw)
    if (draw[best] >= draw[capped]) return capped;
  return best;
}

bool noise_adaptive_smooth(const Positions& positions, const Faces& faces, const NoiseAdaptiveSmoothingOptions& options,
                           Positions& result, NoiseAdaptiveSmoothingReport& report, std::string& error,
                           const std::function<void(int, const char*)>& progress) {
  report = NoiseAdaptiveSmoothingReport{};
  StageClock clock(report.stages);
  auto step = [&](int percent, const char* what) {
    if (progress) progress(percent, what);
  };
  if (!check_triangle_mesh(positions, faces, error)) return false;
  if (!(options.strength > 0) || !std::isfinite(options.strength)) {
    error = "the strength must be a positive number";
    return false;
  }
  // The experiment fields: a negative first-order weight or a non-positive scale would make the
  // solve's matrix singular or indefinite.
  auto positive = [](double x) { return x > 0 && std::isfinite(x); };
  if (!positive(options.mu_scale) || !positive(options.selection_bias) || !positive(options.weaker_allowed) ||
      !positive(options.copy_noise_scale) || options.forced_finish < -1 || options.forced_finish > 3 ||
      !(options.tangential_cap >= 0) || !(options.first_order >= 0) || !std::isfinite(options.first_order)) {
    error = "the smoothing's filter settings are out of range (scale, bias, weaker limit and copies' noise scale positive, cap and first-order weight not negative, finish -1 to 3)";
    return false;
  }
  const int n = static_cast<int>(positions.rows());
  const double edge = mean_edge_length(positions, faces);
  if (!(edge > 0)) {
    error = "the mesh has no edge of positive length";
    return false;
  }

  double sigma = options.noise;
  if (!(sigma > 0)) {
    step(2, "Hamiltonian cycle");
    HamiltonianCycle cycle;
    if (!hamiltonian_cycle(faces, n, options.cycle, cycle, error)) return false;
    clock.done("cycle");
    step(15, "Noise estimate (finest IMF)");
    if (!estimate_noise(positions, faces, cycle, options.emd, report.noise, error)) return false;
    clock.done("noise estimate");
    sigma = report.noise.relative();
    report.sigma_used = sigma;
    if (sigma < kNoiseFree) {
      report.noise_free = true;
      result = positions;
      step(100, "Done");
      return true;
    }
    if (options.remove_scattered_spikes && report.noise.scattered_impulsive()) {
      step(20, "Impulsive noise: spike removal");
      Positions despiked = remove_spikes(positions, faces, vertex_adjacency(faces, n), report.spike_removal);
      clock.done("spike removal");
      if (report.spike_removal.sparse) {
        result.swap(despiked);
        report.spikes_removed = true;
        step(100, "Done");
        return true;
      }
      // Too dense for the removal alone: what it left smoothed as any noise (camel with three
      // tenths of its vertices moved: 5.77 degrees, 9.32 smoothed from the input; docs/quality.md
      // items 26 and 27).
      if (!filter_despiked(despiked, faces, cycle, options, report, error,
                           [&](const Positions& p, const NoiseAdaptiveSmoothingOptions& o, NoiseAdaptiveSmoothingReport& r) {
                             return noise_adaptive_smooth(p, faces, o, result, r, error, progress);
                           }))
        return false;
      const Eigen::VectorXd moves = (result - positions).rowwise().norm();
      report.max_displacement = moves.maxCoeff();
      report.rms_displacement = std::sqrt(moves.squaredNorm() / n);
      return true;
    }
  }
  report.sigma_used = sigma;
  const Eigen::RowVector3d centre = positions.colwise().mean();
  const Positions v = (positions.rowwise() - centre) / edge;  // unit mean edge
  const VertexAdjacency adjacency = vertex_adjacency(faces, n);
  // Vertex normals averaged over a few rings, for the cross-validation and step 3's share.
  const Positions v_normals = smoothed_vertex_normals(v, faces, adjacency);
  clock.done("adjacency");
  // A noise-free mesh gives sigma ~ 0: mu is then capped where the filter is the identity to
  // well under a thousandth of an edge.
  const double noise_cutoff = std::min(options.mu_scale / std::sqrt(std::max(sigma, 1e-12)), 1e3);
  report.mu = options.mu > 0 ? options.mu : noise_cutoff / std::sqrt(options.strength);
  // The noise given by the user is the truth: Stein's unbiased risk needs no floor-free estimate,
  // and unlike the cross-validation it may go weaker than the law (docs/quality.md item 18).
  // Cross-validation minimises a squared error, which large errors dominate, so on its own it
  // smooths less than the mean angle error wants on coarse detailed meshes: it may only make the
  // filter stronger than the noise level's (docs/quality.md). Its search starts a little weaker
  // than that cut-off: nearer the identity its score falls again, spuriously (0/0 in the limit).
  // Both stop at kStrongestSelected times the noise level's cut-off: simple smooth surfaces want
  // far stronger filters (docs/quality.md item 19), at the cost of their vertex distance.
  const bool by_risk = !(options.mu > 0) && options.unbiased_risk && options.noise > 0;
  if (by_risk || (!(options.mu > 0) && options.select_cutoff)) {
    const char* stage = by_risk ? "Cut-off by Stein's unbiased risk" : "Cut-off by cross-validation";
    step(20, stage);
    CutoffSelectionOptions search;
    search.mu_largest = (by_risk ? kUnbiasedRiskRange : kWeakestSearched * std::max(1.0, options.weaker_allowed)) * noise_cutoff;
    search.mu_smallest = noise_cutoff / options.strongest_selected;
    search.first_order = options.first_order;
    if (by_risk) search.noise_sigma = sigma;  // the positions are in mean edges
    CutoffSelection selection;
    if (!select_cutoff(adjacency, v, v_normals, search, selection, error,
                       [&](double done) { step(20 + static_cast<int>(10 * done), stage); }))
      return false;
    const double chosen = selection.mu / options.selection_bias;
    report.cutoff_by_risk = by_risk;
    report.cutoff_selected = !by_risk && chosen < noise_cutoff;
    report.mu = (by_risk ? chosen : std::min(chosen, options.weaker_allowed * noise_cutoff)) / std::sqrt(options.strength);
    report.selection_iterations = selection.iterations;
    report.selection_vertices = selection.sampled_vertices;
    clock.done("cut-off selection");
  }

  step(30, "Least-squares smoothing");
  const double diagonal = bounding_box_diagonal(positions);
  Positions x;
  BiharmonicLowPassReport solve;
  auto solve_at = [&](double mu) {
    return biharmonic_low_pass(adjacency, v, mu, options.first_order, kSmoothingMaxError * diagonal / edge, x, solve,
                               [&](double done) { step(30 + static_cast<int>(60 * done), "Least-squares smoothing (conjugate gradients)"); });
  };
  const bool converged = solve_at(report.mu);
  report.iterations = solve.iterations;
  report.error_bound = solve.error_bound * edge / diagonal;
  if (!converged) {
    error = "the least-squares solve did not converge (" + std::to_string(solve.iterations) + " iterations)";
    return false;
  }
  clock.done("solve");

  const double share = options.tangential_share ? tangential_noise_share(v, v_normals, adjacency, sigma) : 1.0;
  const BorderNeighbours border = options.hold_borders ? border_neighbours(faces, adjacency) : BorderNeighbours{};
  const std::vector<SmoothingFinish> finishes = allowed_finishes(options, share);
  SmoothingFinish chosen = finishes.front();
  if (finishes.size() > 1) {
    // Scored on recorrupted copies, smoothed with each finish. A copy whose solve does not
    // converge leaves the plain finish: the smoothing itself is done.
    step(92, "Finish: recorrupted risk");
    RecorruptedRisks risks;
    report.finish_risk_scored = finish_risks(v, v_normals, faces, adjacency, border, sigma, share, report.mu,
                                             kSmoothingMaxError * diagonal / edge, options, finishes, risks);
    const std::vector<double> mean = report.finish_risk_scored ? risks.mean() : std::vector<double>{};
    report.finish_risk_scored = report.finish_risk_scored && mean[0] > 0;
    if (report.finish_risk_scored) {
      const size_t best = choose_finish(finishes, risks.per_draw, mean);
      chosen = finishes[best];
      report.finish_risk_change = mean[best] / mean[0] - 1;
    }
    report.finishes_scored = static_cast<int>(finishes.size());
    clock.done("finish risk");
  }
  step(97, chosen.taubin_slide ? "Taubin's slide, unfolding and hold" : "Tangential cap, unfolding and hold");
  FinishCounts counts;
  x = finish_smoothing(slid_and_unfolded(x, v, v_normals, faces, adjacency, border, sigma, share, chosen.taubin_slide,
                                         options, counts),
                       v, faces, sigma, chosen.normal_pass, options, counts);
  clock.done("finish");
  report.face_normal_pass = chosen.normal_pass;
  report.taubin_slide = chosen.taubin_slide;
  report.border_vertices_held = counts.border_held;
  report.unfolded_vertices = counts.unfolded;
  report.tangential_share = share;
  report.held_vertices = counts.held;
  report.restored_faces = counts.restored;
  report.unturned_faces = counts.unturned;
  result = (x * edge).rowwise() + centre;
  if (!result.allFinite()) {
    error = "the solve produced non-finite positions";
    return false;
  }
  // An estimate that read no impulsive noise read the same input: no need to look again.
  if (options.keep_untouched && (options.noise > 0 || report.noise.spikes.impulsive())) {
    report.untouched_vertices_kept = keep_untouched_vertices(positions, faces, result);
    clock.done("impulsive noise check");
  }
  const Eigen::VectorXd moves = (result - positions).rowwise().norm();
  report.max_displacement = moves.maxCoeff();
  report.rms_displacement = std::sqrt(moves.squaredNorm() / n);
  step(100, "Done");
  return true;
}

}  // namespace hht
