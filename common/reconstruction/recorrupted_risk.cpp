#include "reconstruction/recorrupted_risk.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

namespace hht {

bool recorrupted_risks(const Positions& y, double sigma, const NoiseShape& shape, int draws, std::uint32_t seed,
                       const std::function<bool(const Positions&, std::vector<Positions>&)>& run,
                       RecorruptedRisks& risks) {
  risks = RecorruptedRisks{};
  if (y.rows() == 0 || draws < 1 || !(sigma > 0)) return false;
  const bool shaped = shape.unit_normals.rows() == y.rows() && shape.tangential_share < 1;
  const double across = std::sqrt(std::max(0.0, shape.tangential_share));
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0, sigma);
  for (int d = 0; d < draws; ++d) {
    Positions z(y.rows(), 3);
    for (Eigen::Index i = 0; i < z.rows(); ++i)
      for (int k = 0; k < 3; ++k) z(i, k) = gaussian(generator);
    if (shaped)
      for (Eigen::Index i = 0; i < z.rows(); ++i) {
        const Eigen::RowVector3d normal = shape.unit_normals.row(i), along = z.row(i).dot(normal) * normal;
        z.row(i) = along + across * (z.row(i) - along);
      }
    const Positions y1 = y + kRecorruptionScale * z, y2 = y - z / kRecorruptionScale;
    std::vector<Positions> outputs;
    if (!run(y1, outputs) || outputs.empty() || (d > 0 && outputs.size() != risks.per_draw[0].size())) return false;
    std::vector<double> draw(outputs.size());
    for (size_t p = 0; p < outputs.size(); ++p) {
      if (outputs[p].rows() != y.rows()) return false;
      draw[p] = (outputs[p] - y2).squaredNorm() / static_cast<double>(y.rows());
    }
    risks.per_draw.push_back(std::move(draw));
  }
  return true;
}

std::vector<double> RecorruptedRisks::mean() const {
  std::vector<double> sum(per_draw.empty() ? 0 : per_draw[0].size(), 0.0);
  for (const std::vector<double>& draw : per_draw)
    for (size_t p = 0; p < sum.size(); ++p) sum[p] += draw[p] / static_cast<double>(per_draw.size());
  return sum;
}

}  // namespace hht
