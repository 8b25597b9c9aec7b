// Small helpers for the benchmarks: loading a mesh file (its faces oriented as the plugin orients
// them) and reading the process's memory.
#pragma once

#include "mesh/coherent_orientation.h"
#include "mesh/mesh_arrays.h"
#include "mesh/tri_mesh.h"

#include <wrap/io_trimesh/import.h>

#include <chrono>
#include <fstream>
#include <string>

namespace hht::bench {

inline bool load_mesh(const std::string& path, Positions& positions, Faces& faces) {
  TriMesh m;
  int mask = 0;
  if (vcg::tri::io::Importer<TriMesh>::Open(m, path.c_str(), mask) != 0) return false;
  mesh_to_arrays(m, positions, faces);
  orient_as_most_faces(faces, static_cast<int>(positions.rows()));  // as the plugin reads a mesh (mesh_adapter.h)
  return true;
}

// Resident and peak resident memory of this process, in MB (/proc/self/status).
inline double memory_mb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == std::string(field) + ":") {
      double kb = 0;
      status >> kb;
      return kb / 1024.0;
    }
  }
  return 0;
}

// Resets the peak (VmHWM) to the current resident size, so that the next peak measures one step.
inline void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5"; }

template <class F>
double seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace hht::bench
