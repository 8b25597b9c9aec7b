#include "filters/surface_emd_smoothing.h"

#include "mesh/mean_curvature.h"
#include "mesh/mesh_checks.h"

#include <algorithm>
#include <cmath>

namespace hht {

bool surface_emd_smoothing(const Positions& positions, const Faces& faces, const SurfaceEmdSmoothingOptions& options,
                           Positions& result, SurfaceEmdSmoothingReport& report, std::string& error) {
  report = SurfaceEmdSmoothingReport{};
  StageClock clock(report.stages);
  if (!check_triangle_mesh(positions, faces, error)) return false;
  MeanCurvature curvature;
  if (!mean_curvature(positions, faces, curvature, error)) return false;
  clock.done("signal");

  SurfaceEmdOptions emd = options.emd;
  emd.feature_vertices = nullptr;
  std::vector<unsigned char> feature_mask;
  if (options.feature_centric) {
    std::vector<FeatureType> type;
    if (!detect_sharp_features(positions, faces, options.features, type, error)) return false;
    feature_mask.resize(type.size());
    for (size_t v = 0; v < type.size(); ++v) feature_mask[v] = type[v] != FeatureType::None ? 1 : 0;
    report.feature_vertices = static_cast<int>(std::count(feature_mask.begin(), feature_mask.end(), 1));
    emd.feature_vertices = &feature_mask;
    clock.done("features");
  }

  SurfaceEmdResult decomposition;
  if (!surface_emd(positions, faces, curvature.signal, emd, decomposition, error)) return false;
  clock.done("surface EMD");
  report.imfs = static_cast<int>(decomposition.imfs.size());
  report.sifts = decomposition.sifts;
  report.emd = decomposition.report;

  // The k-th residue: the final residue plus the IMFs after the k-th.
  report.residue_used = std::min(std::max(options.residue, 0), report.imfs);
  Eigen::VectorXd filtered = decomposition.residue;
  for (int k = report.residue_used; k < report.imfs; ++k) filtered += decomposition.imfs[k];
  report.signal_change_rms =
      std::sqrt((filtered - curvature.signal).squaredNorm() / std::max<Eigen::Index>(1, filtered.size()));

  if (!reconstruct_positions(positions, faces, curvature, filtered, options.reconstruction, result,
                             report.reconstruction, error))
    return false;
  clock.done("reconstruction");
  report.max_displacement = (result - positions).rowwise().norm().maxCoeff();
  return true;
}

}  // namespace hht
