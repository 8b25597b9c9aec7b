// filter_hht for MeshLab 2021.05 and later (FilterPlugin; tested with 2022.02): the plugin
// class, which only dispatches over the filter table (../filter_spec.h).
#pragma once

#include "filter_spec.h"

#include <map>
#include <string>
#include <vector>

class FilterHhtPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  FilterHhtPlugin();

  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  int getPreConditions(const QAction* action) const override;
  int postCondition(const QAction* action) const override;
  RichParameterList initParameterList(const QAction* action, const MeshDocument& document) override;
  std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& parameters,
                                              MeshDocument& document, unsigned int& postConditionMask,
                                              vcg::CallBackPos* progress) override;

 private:
  std::vector<hht_plugin::FilterSpec> filters_;
};
