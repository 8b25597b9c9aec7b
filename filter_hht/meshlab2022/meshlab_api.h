// What the filters use of MeshLab 2021.05 and later (FilterPlugin), under the names they use
// with either MeshLab; meshlab2020/meshlab_api.h is the same for 2020.09.
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

#include <vector>

namespace hht_plugin {

using MeshLabFilter = FilterPlugin;  // its FilterClass and arity enumerators
using FilterArity = FilterPlugin::FilterArity;

inline void update_box_and_normals(MeshModel& m) { m.updateBoxAndNormals(); }

inline std::vector<const MeshModel*> layers(const MeshDocument& document) {
  std::vector<const MeshModel*> all;
  for (const MeshModel& m : document.meshIterator()) all.push_back(&m);
  return all;
}

// A choice among the document's layers, `preselected` first (layers are named by id here).
inline RichMesh mesh_parameter(const QString& name, const MeshModel* preselected, const MeshDocument& document,
                               const QString& label, const QString& help) {
  return RichMesh(name, preselected ? preselected->id() : 0, &document, label, help);
}

inline MeshModel* chosen_mesh(const RichParameterList& parameters, const QString& name, MeshDocument& document) {
  return document.getMesh(parameters.getMeshId(name));
}

}  // namespace hht_plugin
