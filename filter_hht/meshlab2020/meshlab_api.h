// What the filters use of MeshLab 2020.09 (MeshFilterInterface), under the names they use
// with either MeshLab; meshlab2022/meshlab_api.h is the same for 2021.05 and later.
#pragma once

#include <common/interfaces.h>

#include <vector>

namespace hht_plugin {

using MeshLabFilter = MeshFilterInterface;  // its FilterClass and arity enumerators
using FilterArity = MeshFilterInterface::FILTER_ARITY;

inline void update_box_and_normals(MeshModel& m) { m.UpdateBoxAndNormals(); }

inline std::vector<const MeshModel*> layers(const MeshDocument& document) {
  return {document.meshList.begin(), document.meshList.end()};
}

// A choice among the document's layers, `preselected` first. 2020.09's RichMesh takes a
// mutable document (it only reads it).
inline RichMesh mesh_parameter(const QString& name, const MeshModel* preselected, const MeshDocument& document,
                               const QString& label, const QString& help) {
  return RichMesh(name, const_cast<MeshModel*>(preselected), const_cast<MeshDocument*>(&document), label, help);
}

inline MeshModel* chosen_mesh(const RichParameterList& parameters, const QString& name, MeshDocument&) {
  return parameters.getMesh(name);
}

}  // namespace hht_plugin
