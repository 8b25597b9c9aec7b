#include "reconstruction/recorrupted_risk.h"

#include <random>

namespace hht {

bool recorrupted_risks(const Positions& y, double sigma, int draws, std::uint32_t seed,
                       const std::function<bool(const Positions&, Positions&, Positions&)>& run, RecorruptedRisks& risks) {
  risks = RecorruptedRisks{};
  if (y.rows() == 0 || draws < 1 || !(sigma > 0)) return false;
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0, sigma);
  for (int d = 0; d < draws; ++d) {
    Positions z(y.rows(), 3);
    for (Eigen::Index i = 0; i < z.rows(); ++i)
      for (int k = 0; k < 3; ++k) z(i, k) = gaussian(generator);
    const Positions y1 = y + kRecorruptionScale * z, y2 = y - z / kRecorruptionScale;
    Positions first, second;
    if (!run(y1, first, second) || first.rows() != y.rows() || second.rows() != y.rows()) return false;
    risks.first += (first - y2).squaredNorm() / static_cast<double>(y.rows());
    risks.second += (second - y2).squaredNorm() / static_cast<double>(y.rows());
    ++risks.draws;
  }
  risks.first /= draws;
  risks.second /= draws;
  return true;
}

}  // namespace hht
