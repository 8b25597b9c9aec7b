// "HHT: Add Gaussian Noise": the paper's noise model, for making test inputs.
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "evaluation/gaussian_noise.h"

namespace hht_plugin {

namespace {

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichFloat("sigmaPercent", 10.0f, "Sigma (% of mean edge length)",
                       "Standard deviation of the displacement, in percent of the mesh's mean edge length (the paper "
                       "uses 5% for Fandisk, 10% for the cube and the torus; 0 to 1000)."));
  p.addParam(RichEnum("direction", 0,
                      QStringList{"Random direction", "Along the vertex normal", "Isotropic (each coordinate)"},
                      "Direction",
                      "Each vertex moves by a Gaussian amount along a uniformly random direction (the paper's "
                      "model), or along its area-weighted normal (the denoising literature's), or by independent "
                      "Gaussian noise on each coordinate (two thirds of it tangential). The log gives the part along "
                      "the normals, which the HHT smoothing and denoising filters read as the noise level: sigma "
                      "along the normals or on each coordinate, about sigma / 1.73 along random directions."));
  p.addParam(RichFloat("sharePercent", 100.0f, "Vertices moved (%)",
                       "The share of the vertices that move, picked at random; the others stay exactly where they "
                       "are. Below 100 this is impulsive noise, the denoising literature's other model (outliers of a "
                       "scan); the HHT smoothing and denoising filters detect it on meshes with flat parts and keep the "
                       "vertices it left alone (0 to 100)."));
  p.addParam(RichInt("seed", 1, "Random seed", "The same seed gives the same noise."));
}

bool apply(FilterRun& run) {
  MeshModel& model = *run.document.mm();
  hht::Positions positions;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;
  const double percent = run.parameters.getFloat("sigmaPercent");
  if (!check_range("sigma", percent, 0, 1000, run.error, " percent of the mean edge length")) return false;
  const double share = run.parameters.getFloat("sharePercent");
  if (!check_range("share of vertices moved", share, 0, 100, run.error, " percent")) return false;
  const int choice = run.parameters.getEnum("direction");
  const auto direction = choice == 1   ? hht::NoiseDirection::Normal
                         : choice == 2 ? hht::NoiseDirection::Isotropic
                                       : hht::NoiseDirection::Random;
  static const char* const names[] = {"random directions", "along the normals", "isotropic, each coordinate"};
  hht::Positions noisy;
  if (!move_vertices_checked(model, positions, noisy, [&](hht::Positions& out, std::string&) {
        out = hht::add_gaussian_noise(positions, faces, percent, direction,
                                      static_cast<unsigned>(run.parameters.getInt("seed")), share / 100.0);
        return true;
      }, run.error, input_map))
    return false;
  const double edge = hht::mean_edge_length(positions, faces);
  const double rms = std::sqrt((noisy - positions).rowwise().squaredNorm().mean());
  // What the smoothing and denoising filters read and take as `noisePercent`: random directions
  // put a third of the variance along the normals.
  const double along_percent = 100.0 * hht::noise_along_normals(positions, noisy, faces);
  const Eigen::Index moved = ((noisy - positions).rowwise().squaredNorm().array() > 0).count();
  run.log(QString("Gaussian noise: sigma %1% of the mean edge length %2 = %3, %4, on %5 of %6 vertices; measured RMS "
                  "displacement %7, along the vertex normals %8% of the noisy mesh's mean edge (the noise level the HHT "
                  "smoothing and denoising filters read: give this as their noisePercent)")
              .arg(percent).arg(edge).arg(percent / 100.0 * edge)
              .arg(names[static_cast<int>(direction)]).arg(moved).arg(positions.rows()).arg(rms).arg(along_percent, 0, 'f', 2));
  return true;
}

}  // namespace

FilterSpec add_noise_filter() {
  return {"HHT: Add Gaussian Noise",
          "Adds the noise model of the paper's experiments: every vertex moves by a Gaussian amount with standard "
          "deviation sigma, given in percent of the mean edge length, along a uniformly random direction, along its "
          "normal, or on each coordinate; with a share of the vertices below 100%, only that share moves (impulsive "
          "noise). The seed makes it reproducible. The log gives the part along the normals: "
          "the noise level the HHT smoothing and denoising filters read and take as noisePercent.",
          MeshLabFilter::Smoothing,
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL,
          declare,
          apply};
}

}  // namespace hht_plugin
