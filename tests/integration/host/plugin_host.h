// The staged plugin hosted in-process the way meshlabserver hosts it (QPluginLoader on
// libfilter_hht.so, initParameterSet, applyFilter on a MeshDocument), for the host tests.
#pragma once

#include <common/interfaces.h>

#include <QCoreApplication>
#include <QPluginLoader>

#include <stdexcept>

namespace hht::host {

inline MeshFilterInterface& plugin() {
  static int argc = 1;
  static char name[] = "hht_plugin_host_tests";
  static char* argv[] = {name, nullptr};
  static QCoreApplication app(argc, argv);
  static QPluginLoader loader(HHT_STAGE_DIR "/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_hht.so");
  static MeshFilterInterface* filter = qobject_cast<MeshFilterInterface*>(loader.instance());
  if (!filter) throw std::runtime_error("cannot load the staged plugin: " + loader.errorString().toStdString());
  return *filter;
}

// The plugin's action named `name` (its menu entry), or nullptr.
inline QAction* find_action(const QString& name) {
  for (QAction* a : plugin().actions())
    if (a->text() == name) return a;
  return nullptr;
}

}  // namespace hht::host
