// filter_hht for MeshLab 2020.09 (MeshFilterInterface): the plugin class, which only
// dispatches over the filter table (../filter_spec.h). Empirical Mode Decomposition and
// Hilbert spectra on triangle meshes, after "Efficient EMD and Hilbert spectra computation for
// 3D geometry processing and analysis via space-filling curve" (The Visual Computer, 2015).
#pragma once

#include "filter_spec.h"

#include <vector>

class FilterHhtPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  FilterHhtPlugin();

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  FILTER_ARITY filterArity(QAction* action) const override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  void initParameterSet(QAction* action, MeshDocument& document, RichParameterList& parameters) override;
  bool applyFilter(QAction* action, MeshDocument& document, const RichParameterList& parameters,
                   vcg::CallBackPos* progress) override;

 private:
  std::vector<hht_plugin::FilterSpec> filters_;
};
