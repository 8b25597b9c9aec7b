#include "meshlabserver_harness.h"

#include <gtest/gtest.h>
#include <wrap/io_trimesh/import_ply.h>

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace hht::test {

namespace fs = std::filesystem;

std::string resource(const std::string& name) { return std::string(HHT_RESOURCES_DIR) + "/" + name; }
std::string data_mesh(const std::string& name) { return std::string(HHT_DATA_DIR) + "/" + name + ".off"; }

std::string output_dir() {
  // one folder per test: ctest -j runs tests in parallel, and scripts write relative paths
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = test ? std::string(test->test_suite_name()) + "." + test->name() : "no_test";
  for (char& c : name)
    if (c == '/') c = '_';
  const std::string dir = std::string(HHT_OUTPUT_DIR) + "/" + name;
  fs::create_directories(dir);
  return dir;
}

std::string output_path(const std::string& file) { return output_dir() + "/" + file; }

namespace {

// One Xvfb per test process for 2020.09's meshlabserver. The server picks a free display number
// itself (-displayfd), so parallel tests cannot race for one as xvfb-run -a's check-then-start can.
class VirtualDisplay {
 public:
  static const std::string& name() {
    static VirtualDisplay display;
    return display.name_;
  }
  ~VirtualDisplay() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }

 private:
  VirtualDisplay() {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      prctl(PR_SET_PDEATHSIG, SIGTERM);  // never outlive the test
      close(fds[0]);
      freopen("/dev/null", "w", stderr);
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "800x600x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    char c;
    while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (!number.empty()) name_ = ":" + number;
  }
  pid_t pid_ = -1;
  std::string name_;
};

#ifdef HHT_MESHLAB2022_BUILD
// The project as the Debian 13 root sees it (in_debian13.sh mounts it at HHT_PROJECT_INSIDE).
std::string inside_root(const std::string& path) {
  const std::string project = HHT_SOURCE_DIR;
  if (path.compare(0, project.size(), project) != 0) {
    ADD_FAILURE() << path << " is outside the project folder, which is all the Debian 13 root sees";
    return path;
  }
  return HHT_PROJECT_INSIDE + path.substr(project.size());
}
#endif

std::string server_command(MeshLab meshlab, const std::vector<std::string>& inputs, const std::string& output,
                           const std::string& script) {
  std::string args;
  if (meshlab == MeshLab::V2020) {
    const std::string& display = VirtualDisplay::name();
    if (display.empty()) {
      ADD_FAILURE() << "Xvfb did not start";
      return "false";
    }
    for (const auto& input : inputs) args += " -i '" + input + "'";
    return "DISPLAY=" + display + " '" + std::string(HHT_STAGE_DIR) + "/bin/meshlabserver'" + args + " -o '" + output +
           "' -m vq vc vf -s '" + script + "'";
  }
#ifdef HHT_MESHLAB2022_BUILD
  for (const auto& input : inputs) args += " -i '" + inside_root(input) + "'";
  const std::string build = inside_root(HHT_MESHLAB2022_BUILD);
  return "'" + std::string(HHT_SOURCE_DIR) + "/scripts/in_debian13.sh' sh -c \"cd '" + inside_root(output_dir()) +
         "' && '" + build + "/tools/meshlabserver2022' -p '" + build + "/filter_hht/libfilter_hht.so'" + args +
         " -o '" + inside_root(output) + "' -m vq vc -s '" + inside_root(script) + "'\"";
#else
  ADD_FAILURE() << "this build does not test MeshLab 2022.02 (configure with -DHHT_TEST_MESHLAB2022=ON)";
  return "false";
#endif
}

}  // namespace

ServerRun run_script(MeshLab meshlab, const std::vector<std::string>& inputs, const std::string& script,
                     const std::string& tag, const std::string& extension) {
  ServerRun run;
  run.output = output_path(tag + extension);
  const std::string log = output_path(tag + ".log");
  fs::remove(run.output);
  // the servers read the script's relative paths from their working directory
  const std::string command = "cd '" + output_dir() + "' && " +
                              server_command(meshlab, inputs, run.output, script) + " > '" + log + "' 2>&1";
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

ObjPolyline read_obj_polyline(const std::string& path) {
  ObjPolyline out;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "v") {
      Eigen::RowVector3d p;
      fields >> p[0] >> p[1] >> p[2];
      out.vertices.push_back(p);
    } else if (kind == "l") {
      int a = 0, b = 0;
      fields >> a >> b;
      out.edges.push_back({a - 1, b - 1});  // OBJ counts from 1
    }
  }
  return out;
}

void load(const ServerRun& run, TriMesh& m) {
  bool has_quality = false;
  ASSERT_EQ(run.exit_code, 0) << run.log;
  ASSERT_TRUE(load_ply(run.output, m, has_quality)) << run.output;
}

std::string write_script(const std::string& tag, const std::string& body) {
  const std::string path = output_path(tag + ".mlx");
  std::ofstream(path) << "<!DOCTYPE FilterScript>\n<FilterScript>\n" << body << "</FilterScript>\n";
  return path;
}

std::string chain_scripts(const std::string& tag, const std::vector<std::string>& resources,
                          const std::vector<std::pair<std::string, std::string>>& overrides) {
  std::string body;
  for (const auto& name : resources) {
    std::ifstream in(resource(name));
    std::stringstream text;
    text << in.rdbuf();
    const std::string xml = text.str();
    const size_t begin = xml.find("<filter"), end = xml.rfind("</filter>");
    body += xml.substr(begin, end + 9 - begin) + "\n";
  }
  for (const auto& [name, value] : overrides) {
    const std::regex param("(name=\"" + name + "\" value=\")[^\"]*\"");
    body = std::regex_replace(body, param, "$01" + value + "\"");  // $01: value may start with a digit
  }
  return write_script(tag, body);
}

void expect_bad_input_refused(const std::vector<std::string>& scripts, const std::string& tag, MeshLab meshlab) {
  const std::string cloud = output_path(tag + "_cloud.off");
  std::ofstream(cloud) << "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string nan = output_path(tag + "_nan.off");
  std::ofstream(nan) << "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  std::vector<std::pair<std::string, std::string>> cases{{cloud, "no faces"}, {nan, "NaN"}};
  // MeshLab 2022.02's loader deletes NaN vertices (and their faces) before any filter runs.
  if (meshlab == MeshLab::V2022) cases.pop_back();
  for (const auto& script : scripts)
    for (const auto& [input, message] : cases) {
      const ServerRun run = run_script(meshlab, {input}, resource(script), tag);
      EXPECT_NE(run.exit_code, 0) << script;
      EXPECT_NE(run.log.find("failed: Nothing was changed"), std::string::npos) << script << "\n" << run.log;
      EXPECT_NE(run.log.find(message), std::string::npos) << script << "\n" << run.log;
      EXPECT_FALSE(fs::exists(run.output)) << script;
    }
}

double mean_dihedral_angle(const TriMesh& m) {
  Positions p;
  Faces f;
  mesh_to_arrays(m, p, f);
  std::map<std::pair<int, int>, Eigen::RowVector3d> first;
  double sum = 0;
  int count = 0;
  for (Eigen::Index i = 0; i < f.rows(); ++i) {
    const Eigen::RowVector3d a = p.row(f(i, 0));
    const Eigen::RowVector3d n = (p.row(f(i, 1)) - a).cross(p.row(f(i, 2)) - a).normalized();
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> e{std::min(f(i, k), f(i, (k + 1) % 3)), std::max(f(i, k), f(i, (k + 1) % 3))};
      auto it = first.find(e);
      if (it == first.end()) {
        first.emplace(e, n);
      } else {
        sum += std::acos(std::clamp(n.dot(it->second), -1.0, 1.0));
        ++count;
      }
    }
  }
  return count ? sum / count : 0.0;
}

double max_distance(const TriMesh& a, const TriMesh& b) {
  double d = 0;
  for (size_t i = 0; i < a.vert.size() && i < b.vert.size(); ++i) d = std::max(d, double((a.vert[i].cP() - b.vert[i].cP()).Norm()));
  return d;
}

double bbox_diagonal(const TriMesh& m) {
  vcg::Box3d box;
  for (const auto& v : m.vert) box.Add(v.cP());
  return box.Diag();
}

}  // namespace hht::test
