#include "meshlabserver_harness.h"

#include <wrap/io_trimesh/import_ply.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace hht::test {

namespace fs = std::filesystem;

std::string resource(const std::string& name) { return std::string(HHT_RESOURCES_DIR) + "/" + name; }
std::string data_mesh(const std::string& name) { return std::string(HHT_DATA_DIR) + "/" + name + ".off"; }

std::string output_path(const std::string& file) {
  fs::create_directories(HHT_OUTPUT_DIR);
  return std::string(HHT_OUTPUT_DIR) + "/" + file;
}

ServerRun run_meshlabserver(const std::string& input, const std::string& script, const std::string& tag) {
  ServerRun run;
  run.output = output_path(tag + ".ply");
  const std::string log = output_path(tag + ".log");
  fs::remove(run.output);
  // meshlabserver reads the script's relative paths from its working directory
  const std::string command = "cd '" + std::string(HHT_OUTPUT_DIR) + "' && xvfb-run -a -s '-screen 0 800x600x24' '" +
                              std::string(HHT_STAGE_DIR) + "/bin/meshlabserver' -i '" + input + "' -o '" +
                              run.output + "' -m vq vc -s '" + script + "' > '" + log + "' 2>&1";
  const int status = std::system(command.c_str());
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  run.log = text.str();
  return run;
}

bool load_ply(const std::string& path, TriMesh& m, bool& has_quality) {
  int mask = 0;
  if (vcg::tri::io::ImporterPLY<TriMesh>::Open(m, path.c_str(), mask) != 0) return false;
  has_quality = (mask & vcg::tri::io::Mask::IOM_VERTQUALITY) != 0;
  return true;
}

std::string write_script(const std::string& tag, const std::string& body) {
  const std::string path = output_path(tag + ".mlx");
  std::ofstream(path) << "<!DOCTYPE FilterScript>\n<FilterScript>\n" << body << "</FilterScript>\n";
  return path;
}

}  // namespace hht::test
