#include "filter_hht_plugin.h"

#include <exception>

FilterHhtPlugin::FilterHhtPlugin() : filters_(hht_plugin::all_filters()) {
  for (int id = 0; id < static_cast<int>(filters_.size()); ++id) typeList.push_back(id);
  for (ActionIDType id : types()) actionList.push_back(new QAction(filterName(id), this));
}

QString FilterHhtPlugin::pluginName() const { return "FilterHHT"; }

QString FilterHhtPlugin::filterName(ActionIDType filter) const { return filters_.at(filter).name; }

QString FilterHhtPlugin::filterInfo(ActionIDType filter) const { return filters_.at(filter).info; }

FilterPlugin::FilterClass FilterHhtPlugin::getClass(const QAction* action) const {
  return filters_.at(ID(action)).menu_class;
}

FilterPlugin::FilterArity FilterHhtPlugin::filterArity(const QAction* action) const {
  return filters_.at(ID(action)).arity;
}

int FilterHhtPlugin::getPreConditions(const QAction*) const { return MeshModel::MM_NONE; }

int FilterHhtPlugin::postCondition(const QAction* action) const { return filters_.at(ID(action)).post_condition; }

RichParameterList FilterHhtPlugin::initParameterList(const QAction* action, const MeshDocument& document) {
  RichParameterList parameters;
  filters_.at(ID(action)).declare_parameters(document, parameters);
  return parameters;
}

std::map<std::string, QVariant> FilterHhtPlugin::applyFilter(const QAction* action, const RichParameterList& parameters,
                                                             MeshDocument& document, unsigned int& postConditionMask,
                                                             vcg::CallBackPos* progress) {
  const hht_plugin::FilterSpec& filter = filters_.at(ID(action));
  QString error;
  hht_plugin::FilterRun run{document, parameters, progress, [this](const QString& line) { log(line.toStdString()); },
                            error};
  bool ok = false;
  try {
    ok = filter.apply(run);
  } catch (const std::bad_alloc&) {
    error = "Out of memory: the mesh is too large for the memory available.";
  } catch (const std::exception& e) {
    error = QString("Unexpected error: ") + e.what();
  }
  // MeshLab shows the exception's text (the window in a dialog, the runner as "<filter> failed: ...").
  if (!ok) throw MLException(error);
  postConditionMask = filter.post_condition;
  return {};
}
