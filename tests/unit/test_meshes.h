// Meshes for the unit tests: the real ones from libcgal-demo (extracted into data/ by
// scripts/setup.sh) and generated ones.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/tri_mesh.h"

#include <string>

namespace hht::test {

struct ArrayMesh {
  Positions positions;
  Faces faces;
  int vertices() const { return static_cast<int>(positions.rows()); }
};

ArrayMesh load_data_mesh(const std::string& name);  // e.g. "fandisk" -> data/fandisk.off
ArrayMesh sphere(int subdivisions, double radius = 1.0);
// A flat grid in z = 0, vertex (i, j) = j * nx + i at (i, j, 0), each square split along the same
// diagonal: an interior vertex has six neighbours, whose centroid it is.
ArrayMesh grid(int nx, int ny);
ArrayMesh torus(double major, double minor, int major_steps, int minor_steps);
ArrayMesh remove_faces(const ArrayMesh& m, int every);  // drop every `every`-th face region: holes
ArrayMesh disjoint_union(const ArrayMesh& a, const ArrayMesh& b);
// Two spheres touching at vertex 0, which both share: a non-manifold vertex (two fans of faces).
ArrayMesh touching_spheres(int subdivisions);
// A sphere with a fin: a strip of triangles standing out of it along a path of `fin_edges` of its
// edges (from vertex 0), each of them shared by three faces: non-manifold edges. The fin's faces
// come after the sphere's, its vertices (`fin_edges` + 1, each above its path vertex) after the
// sphere's too.
ArrayMesh finned_sphere(int subdivisions, int fin_edges);
ArrayMesh flip_random_edges(const ArrayMesh& m, int flips, unsigned seed);
// Each triangle cut into four at its edges' midpoints: the same surface, meshed twice as finely.
ArrayMesh midpoint_subdivision(const ArrayMesh& m);

}  // namespace hht::test
