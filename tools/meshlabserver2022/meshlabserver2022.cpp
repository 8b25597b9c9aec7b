// meshlabserver2022: runs MeshLab filter scripts (.mlx) without a window on MeshLab 2022.02's
// own library (libmeshlab-common): its plugin manager loads the installed plugins (and any
// given with -p), its IO plugins read and write the meshes, its FilterScript reads the script.
// The role meshlabserver played up to MeshLab 2020.09 (MeshLab removed it in 2021.07), with
// the same main options:
//   meshlabserver2022 -i in.ply [-i in2.ply ...] -o out.ply [-m vq vc ...] -s script.mlx [-p plugin.so ...]
#include <common/filterscript.h>
#include <common/globals.h>
#include <common/mlexception.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>

namespace {

struct SaveFlag {
  const char* name;
  int io_bit;
  int mesh_bit;
};
namespace io = vcg::tri::io;
// meshlabserver's -m flags (what to save besides positions and faces).
const SaveFlag kSaveFlags[] = {
    {"vc", io::Mask::IOM_VERTCOLOR, MeshModel::MM_VERTCOLOR},
    {"vq", io::Mask::IOM_VERTQUALITY, MeshModel::MM_VERTQUALITY},
    {"vn", io::Mask::IOM_VERTNORMAL, MeshModel::MM_VERTNORMAL},
    {"vt", io::Mask::IOM_VERTTEXCOORD, MeshModel::MM_VERTTEXCOORD},
    {"vf", io::Mask::IOM_VERTFLAGS, MeshModel::MM_VERTFLAG},
    {"fc", io::Mask::IOM_FACECOLOR, MeshModel::MM_FACECOLOR},
    {"fq", io::Mask::IOM_FACEQUALITY, MeshModel::MM_FACEQUALITY},
    {"fn", io::Mask::IOM_FACENORMAL, MeshModel::MM_FACENORMAL},
    {"ff", io::Mask::IOM_FACEFLAGS, MeshModel::MM_FACEFLAG},
    {"wt", io::Mask::IOM_WEDGTEXCOORD, MeshModel::MM_WEDGTEXCOORD},
};

struct Options {
  QStringList inputs;
  QString output;
  QStringList save_flags;
  QString script;
  QStringList plugins;
  QString plugin_dir = MESHLAB_SYSTEM_PLUGIN_DIR;
  bool list_filters = false;
};

const char* kUsage =
    "usage: meshlabserver2022 -i IN [-i IN2 ...] [-o OUT [-m FLAGS...]] [-s SCRIPT.mlx] [-p PLUGIN.so ...]\n"
    "                         [--plugin-dir DIR] [--list-filters]\n"
    "  -i IN          load a mesh as a new layer (the last one loaded is the current layer)\n"
    "  -o OUT         save the current layer after the script (format from the extension)\n"
    "  -m FLAGS       what OUT also keeps: vc vq vn vt vf fc fq fn ff wt (vertex/face colour, quality, ...)\n"
    "  -s SCRIPT      a MeshLab filter script; every filter must list all of its parameters\n"
    "  -p PLUGIN      load this plugin file (e.g. a freshly built libfilter_hht.so) instead of an\n"
    "                 installed one of the same file name\n"
    "  --plugin-dir   the installed plugins (default " MESHLAB_SYSTEM_PLUGIN_DIR ")\n"
    "  --list-filters print the name of every filter loaded and exit\n"
    "Exit status: 0 on success, 1 when a filter fails (nothing is saved), 2 on bad usage or I/O.\n";

bool parse(const QStringList& args, Options& o, QString& error) {
  for (int i = 1; i < args.size(); ++i) {
    const QString& a = args[i];
    auto value = [&](QString& into) {
      if (i + 1 >= args.size()) { error = a + " needs a value"; return false; }
      into = args[++i];
      return true;
    };
    QString v;
    if (a == "-i") { if (!value(v)) return false; o.inputs << v; }
    else if (a == "-o") { if (!value(o.output)) return false; }
    else if (a == "-s") { if (!value(o.script)) return false; }
    else if (a == "-p") { if (!value(v)) return false; o.plugins << v; }
    else if (a == "--plugin-dir") { if (!value(o.plugin_dir)) return false; }
    else if (a == "--list-filters") o.list_filters = true;
    else if (a == "-m") {
      while (i + 1 < args.size() && !args[i + 1].startsWith('-')) o.save_flags << args[++i];
    } else { error = "unknown option " + a; return false; }
  }
  for (const QString& f : o.save_flags) {
    bool known = false;
    for (const SaveFlag& s : kSaveFlags) known |= f == s.name;
    if (!known) { error = "unknown -m flag " + f; return false; }
  }
  if (!o.list_filters && o.inputs.isEmpty()) { error = "no input mesh (-i)"; return false; }
  return true;
}

void print_new_log_lines(const GLLogStream& log, int& printed) {
  const auto& lines = log.logStringList();
  for (; printed < lines.size(); ++printed) std::printf("LOG: %d %s\n", lines[printed].first, qUtf8Printable(lines[printed].second));
  std::fflush(stdout);
}

bool quiet_progress(const int, const char*) { return true; }

// The script's values over the filter's own defaults, so that nothing the script misses or
// FilterScript could not read goes unnoticed.
RichParameterList script_parameters(FilterPlugin& plugin, QAction* action, MeshDocument& document,
                                    const RichParameterList& from_script) {
  RichParameterList parameters = plugin.initParameterList(action, document);
  for (const RichParameter& p : from_script) {
    if (!parameters.hasParameter(p.name()))
      throw MLException("the script sets '" + p.name() + "', which this filter does not have");
    parameters.setValue(p.name(), p.value());
  }
  for (const RichParameter& p : parameters)
    if (!from_script.hasParameter(p.name()))
      throw MLException("the script does not give parameter '" + p.name() +
                        "' (missing, or of a type or value MeshLab could not read)");
  return parameters;
}

void apply(PluginManager& plugins, MeshDocument& document, const FilterNameParameterValuesPair& step) {
  QAction* action = plugins.filterAction(step.filterName());
  if (!action) throw MLException("no filter of this name is loaded");
  FilterPlugin* plugin = plugins.getFilterPluginFromAction(action);
  if (plugin->requiresGLContext(action))
    throw MLException("it needs an OpenGL context, which this runner does not provide");
  const RichParameterList parameters = script_parameters(*plugin, action, document, step.second);
  MeshModel* current = document.mm();
  if (current) {
    QStringList missing;
    if (!plugin->isFilterApplicable(action, *current, missing))
      throw MLException("the current mesh lacks " + missing.join(", "));
    current->updateDataMask(plugin->getRequirements(action));
  }
  plugin->setLog(&document.Log);
  unsigned int post_condition = MeshModel::MM_UNKNOWN;
  plugin->applyFilter(action, parameters, document, post_condition, quiet_progress);
  for (MeshModel& m : document.meshIterator()) vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
  // As MeshLab's window does after a filter: colouring filters switch the colour on.
  const int menu_class = plugin->getClass(action);
  if (document.mm()) {
    if (menu_class & FilterPlugin::VertexColoring) document.mm()->updateDataMask(MeshModel::MM_VERTCOLOR);
    if (menu_class & FilterPlugin::FaceColoring) document.mm()->updateDataMask(MeshModel::MM_FACECOLOR);
  }
}

void save(MeshModel& m, const QString& path, const QStringList& flags) {
  const QString format = QFileInfo(path).suffix().toLower();
  IOPlugin* writer = meshlab::pluginManagerInstance().outputMeshPlugin(format);
  if (!writer) throw MLException("no plugin writes ." + format + " files");
  int capability = 0, default_bits = 0;
  writer->exportMaskCapability(format, capability, default_bits);
  int mask = 0;
  for (const SaveFlag& s : kSaveFlags)
    if (flags.contains(s.name) && m.hasDataMask(s.mesh_bit)) mask |= s.io_bit;
  writer->save(format, path, m, mask & capability, writer->initSaveParameter(format, m), nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  // Geometry filters need no display; MeshLab's plugins still want a GUI application object.
  if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
    qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  Options options;
  QString error;
  if (!parse(app.arguments(), options, error)) {
    std::fprintf(stderr, "meshlabserver2022: %s\n%s", qUtf8Printable(error), kUsage);
    return 2;
  }

  PluginManager& plugins = meshlab::pluginManagerInstance();
  // An installed copy of a plugin given with -p must not shadow it (same filter names).
  QStringList given;
  for (const QString& file : options.plugins) given << QFileInfo(file).fileName();
  for (const QFileInfo& file : QDir(options.plugin_dir).entryInfoList({"*.so"}, QDir::Files)) {
    if (given.contains(file.fileName())) continue;
    try {
      plugins.loadPlugin(file.absoluteFilePath());
    } catch (const MLException& e) {  // the others still load: say which failed, go on
      std::fprintf(stderr, "meshlabserver2022: warning: plugin %s not loaded: %s\n", qUtf8Printable(file.fileName()),
                   e.what());
    }
  }
  for (const QString& file : options.plugins) {
    try {
      plugins.loadPlugin(QFileInfo(file).absoluteFilePath());
    } catch (const MLException& e) {
      std::fprintf(stderr, "meshlabserver2022: cannot load plugin %s: %s\n", qUtf8Printable(file), e.what());
      return 2;
    }
  }
  if (options.list_filters) {
    for (FilterPlugin* plugin : plugins.filterPluginIterator())
      for (QAction* action : plugin->actions()) std::printf("%s\n", qUtf8Printable(action->text()));
    return 0;
  }
  std::printf("Loaded %u plugins\n", plugins.size());

  MeshDocument document;
  int printed = 0;
  for (const QString& input : options.inputs) {
    try {
      meshlab::loadMeshWithStandardParameters(input, document);
    } catch (const MLException& e) {
      std::fprintf(stderr, "meshlabserver2022: cannot load %s: %s\n", qUtf8Printable(input), e.what());
      return 2;
    }
    std::printf("Mesh %s loaded: %d vertices, %d faces\n", qUtf8Printable(input), document.mm()->cm.VN(),
                document.mm()->cm.FN());
  }

  if (!options.script.isEmpty()) {
    FilterScript script;
    if (!QFileInfo::exists(options.script) || !script.open(options.script)) {
      std::fprintf(stderr, "meshlabserver2022: cannot read the filter script %s\n", qUtf8Printable(options.script));
      return 2;
    }
    for (const FilterNameParameterValuesPair& step : script) {
      std::printf("Applying filter %s\n", qUtf8Printable(step.filterName()));
      try {
        apply(plugins, document, step);
      } catch (const MLException& e) {
        print_new_log_lines(document.Log, printed);
        std::printf("%s failed: %s\n", qUtf8Printable(step.filterName()), e.what());
        return 1;
      } catch (const std::exception& e) {
        print_new_log_lines(document.Log, printed);
        std::printf("%s failed: unexpected error: %s\n", qUtf8Printable(step.filterName()), e.what());
        return 1;
      }
      print_new_log_lines(document.Log, printed);
    }
  }

  if (!options.output.isEmpty()) {
    try {
      save(*document.mm(), options.output, options.save_flags);
    } catch (const MLException& e) {
      std::fprintf(stderr, "meshlabserver2022: cannot save %s: %s\n", qUtf8Printable(options.output), e.what());
      return 2;
    }
    std::printf("Mesh saved to %s\n", qUtf8Printable(options.output));
  }
  return 0;
}
