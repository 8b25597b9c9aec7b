#include "filter_hht_plugin.h"

#include <exception>

FilterHhtPlugin::FilterHhtPlugin() : filters_(hht_plugin::all_filters()) {
  for (int id = 0; id < static_cast<int>(filters_.size()); ++id) typeList << id;
  for (FilterIDType id : types()) actionList << new QAction(filterName(id), this);
}

QString FilterHhtPlugin::pluginName() const { return "FilterHHT"; }

QString FilterHhtPlugin::filterName(FilterIDType filter) const { return filters_.at(filter).name; }

QString FilterHhtPlugin::filterInfo(FilterIDType filter) const { return filters_.at(filter).info; }

MeshFilterInterface::FilterClass FilterHhtPlugin::getClass(QAction* action) {
  return filters_.at(ID(action)).menu_class;
}

MeshFilterInterface::FILTER_ARITY FilterHhtPlugin::filterArity(QAction* action) const {
  return filters_.at(ID(action)).arity;
}

int FilterHhtPlugin::getPreConditions(QAction*) const { return MeshModel::MM_NONE; }

int FilterHhtPlugin::postCondition(QAction* action) const { return filters_.at(ID(action)).post_condition; }

void FilterHhtPlugin::initParameterSet(QAction* action, MeshDocument& document, RichParameterList& parameters) {
  filters_.at(ID(action)).declare_parameters(document, parameters);
}

bool FilterHhtPlugin::applyFilter(QAction* action, MeshDocument& document, const RichParameterList& parameters,
                                  vcg::CallBackPos* progress) {
  hht_plugin::FilterRun run{document, parameters, progress,
                            [this](const QString& line) { Log(qUtf8Printable(line)); }, errorMessage};
  // An exception escaping a filter kills MeshLab 2020.09: turn it into an error message.
  bool ok = false;
  try {
    ok = filters_.at(ID(action)).apply(run);
  } catch (const std::bad_alloc&) {
    errorMessage = "Out of memory: the mesh is too large for the memory available.";
  } catch (const std::exception& e) {
    errorMessage = QString("Unexpected error: ") + e.what();
  }
  // meshlabserver shows the log but not errorMessage: put the reason in both.
  if (!ok) Log(qUtf8Printable(filterName(ID(action)) + " failed: " + errorMessage));
  return ok;
}
