// The bridge between a VCG mesh (MeshLab's CMeshO, or hht::TriMesh) and the plain arrays
// the algorithms take: positions (n x 3, double) and faces (m x 3, vertex indices).
// Deleted vertices and faces are skipped; indices are compact in the order of m.vert.
#pragma once

#include "mesh/corner_table.h"

#include <vcg/complex/complex.h>

#include <Eigen/Core>

namespace hht {


template <class MeshType>
void mesh_to_arrays(const MeshType& m, Positions& positions, Faces& faces) {
  std::vector<int> index(m.vert.size(), -1);
  int n = 0;
  for (size_t i = 0; i < m.vert.size(); ++i)
    if (!m.vert[i].IsD()) index[i] = n++;
  positions.resize(n, 3);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    if (index[i] < 0) continue;
    for (int k = 0; k < 3; ++k) positions(index[i], k) = m.vert[i].cP()[k];
  }
  faces.resize(m.fn, 3);
  int f = 0;
  for (const auto& face : m.face) {
    if (face.IsD()) continue;
    for (int k = 0; k < 3; ++k) faces(f, k) = index[vcg::tri::Index(m, face.cV(k))];
    ++f;
  }
  faces.conservativeResize(f, 3);
}

// Writes one value per (non-deleted) vertex, in mesh_to_arrays order, into vertex quality.
template <class MeshType, class Values>
void set_vertex_quality(MeshType& m, const Values& values) {
  size_t n = 0;
  for (auto& v : m.vert)
    if (!v.IsD()) v.Q() = static_cast<typename MeshType::VertexType::QualityType>(values[n++]);
}

template <class MeshType>
void set_vertex_positions(MeshType& m, const Positions& positions) {
  Eigen::Index n = 0;
  for (auto& v : m.vert) {
    if (v.IsD()) continue;
    for (int k = 0; k < 3; ++k)
      v.P()[k] = static_cast<typename MeshType::ScalarType>(positions(n, k));
    ++n;
  }
}

}  // namespace hht
