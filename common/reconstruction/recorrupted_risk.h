// Procedures compared on noisy data alone, by the recorrupted-to-recorrupted risk (Pang,
// Zheng, Quan and Ji, "Recorrupted-to-Recorrupted: unsupervised deep learning for image
// denoising", CVPR 2021). For y = x + n, n ~ N(0, sigma^2) per coordinate, and z an independent
// draw of the same noise, the copies y1 = y + a z and y2 = y - z / a carry independent noise, so
// E ||f(y1) - y2||^2 = E ||f(y1) - x||^2 + a constant, for any procedure f, nonlinear steps
// included: the procedure with the smallest mean is the one nearest the clean positions (at the
// slightly higher noise of y1). With sigma estimated rather than known the copies are only nearly
// independent (docs/quality.md item 20 measures the decisions this gives); so they are if z's
// shape is not the noise's: noise along the normals wants z along the normals (item 21).
#pragma once

#include "mesh/mesh_arrays.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace hht {

constexpr double kRecorruptionScale = 0.5;  // a: y1 = y + a z, y2 = y - z / a

struct RecorruptedRisks {
  std::vector<std::vector<double>> per_draw;  // per draw, per procedure: ||f(y1) - y2||^2 / rows

  int draws() const { return static_cast<int>(per_draw.size()); }
  std::vector<double> mean() const;  // per procedure, over the draws
};

// The shape of the noise z is drawn with: sigma along each vertex's unit normal and
// sigma sqrt(tangential_share) across it; no normals: isotropic.
struct NoiseShape {
  Positions unit_normals;
  double tangential_share = 1;
};

// `run(y1, outputs)` applies each procedure to y1, one output each, as many every draw (false:
// failed, and so does this). `seed` fixes the draws: the same input gives the same answer.
bool recorrupted_risks(const Positions& y, double sigma, const NoiseShape& shape, int draws, std::uint32_t seed,
                       const std::function<bool(const Positions&, std::vector<Positions>&)>& run,
                       RecorruptedRisks& risks);

}  // namespace hht
