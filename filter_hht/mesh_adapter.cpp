#include "mesh_adapter.h"

#include "mesh_checks.h"
#include "value_range.h"

#include <vcg/complex/algorithms/update/color.h>

namespace hht_plugin {

bool read_triangle_mesh(const CMeshO& m, hht::Positions& positions, hht::Faces& faces, QString& error) {
  hht::mesh_to_arrays(m, positions, faces);
  std::string message;
  if (!hht::check_triangle_mesh(positions, faces, message)) {
    error = QString::fromStdString("Nothing was changed: " + message + ".");
    return false;
  }
  return true;
}

std::pair<double, double> show_as_quality(MeshModel& model, const Eigen::VectorXd& values, double percent) {
  model.updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  hht::set_vertex_quality(model.cm, values);
  const auto range = hht::percentile_range(values, percent);
  vcg::tri::UpdateColor<CMeshO>::PerVertexQualityRamp(model.cm, static_cast<float>(range.first),
                                                      static_cast<float>(range.second));
  return range;
}

}  // namespace hht_plugin
