// Runs the staged meshlabserver (under a private Xvfb) on a script and reads back what it saved.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/tri_mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace hht::test {

struct ServerRun {
  int exit_code = -1;
  std::string log;      // everything meshlabserver printed
  std::string output;   // the saved mesh, if any
};

// Which MeshLab runs a script: 2020.09's meshlabserver (staged, under Xvfb) or, in the Debian 13
// root, MeshLab 2022.02's libraries through tools/meshlabserver2022 with the 2022.02 plugin.
enum class MeshLab { V2020, V2022 };

// Runs `script` (a path) on `inputs` (layers, the last one current), saving vertex quality,
// colour and (2020.09) flags to a file named after `tag` in the running test's own folder, which
// is also the server's working directory; 2020.09 runs under a private Xvfb. The format follows
// `extension` (meshlabserver's PLY writer drops edges; its OBJ writer keeps them).
ServerRun run_script(MeshLab meshlab, const std::vector<std::string>& inputs, const std::string& script,
                     const std::string& tag, const std::string& extension = ".ply");
inline ServerRun run_meshlabserver(const std::string& input, const std::string& script, const std::string& tag) {
  return run_script(MeshLab::V2020, {input}, script, tag);
}

std::string resource(const std::string& name);   // resources/<name>
std::string data_mesh(const std::string& name);  // data/<name>.off
std::string output_dir();                          // the running test's own folder
std::string output_path(const std::string& file);  // a file in it

// Loads a PLY with vertex quality; fails the calling test when it cannot.
bool load_ply(const std::string& path, TriMesh& m, bool& has_quality);

// The vertices and edges ("l a b", as 0-based indices) of an OBJ holding a polyline.
struct ObjPolyline {
  std::vector<Eigen::RowVector3d> vertices;
  std::vector<std::pair<int, int>> edges;
};
ObjPolyline read_obj_polyline(const std::string& path);

// The mesh a successful run saved; fails the calling test when the run failed or saved nothing.
void load(const ServerRun& run, TriMesh& m);

std::string write_script(const std::string& tag, const std::string& body);  // a one-off .mlx

// The <filter> elements of shipped scripts, in order, with `overrides` (name -> value) applied
// to their parameters: a script that stays in step with resources/.
std::string chain_scripts(const std::string& tag, const std::vector<std::string>& resources,
                          const std::vector<std::pair<std::string, std::string>>& overrides = {});

// Runs each shipped script on a point cloud and (2020.09 only: 2022.02's loader removes NaN
// vertices itself) on a mesh with a NaN coordinate: each must fail with a message naming the
// problem and save nothing.
void expect_bad_input_refused(const std::vector<std::string>& scripts, const std::string& tag,
                              MeshLab meshlab = MeshLab::V2020);

double mean_dihedral_angle(const TriMesh& m);  // radians, over edges shared by two faces
double max_distance(const TriMesh& a, const TriMesh& b);  // same vertex order
double bbox_diagonal(const TriMesh& m);

}  // namespace hht::test
