// Corner table (Rossignac) of a triangle mesh: the connectivity the Ring Expander walks.
// Corner c belongs to triangle c/3; next(c) and prev(c) are the other corners of that
// triangle; vertex[c] is its vertex; opposite[c] is the corner facing c across the edge
// (vertex[next(c)], vertex[prev(c)]), or -1 on a boundary edge.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hht {

using Faces = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

inline int corner_next(int c) { return c % 3 == 2 ? c - 2 : c + 1; }
inline int corner_prev(int c) { return c % 3 == 0 ? c + 2 : c - 1; }
inline int corner_triangle(int c) { return c / 3; }

struct CornerTable {
  std::vector<int> vertex;
  std::vector<int> opposite;
  int corners() const { return static_cast<int>(vertex.size()); }
};

// Builds the table of `faces` over `vertex_count` vertices. Fails, with a message that says
// what is wrong and how many times, on faces that repeat a vertex or index out of range,
// and on non-manifold edges (shared by more than two faces). Neighbouring faces whose
// orientations disagree are paired all the same; `inconsistent_edges` counts them.
bool build_corner_table(const Faces& faces, int vertex_count, CornerTable& table,
                        int& inconsistent_edges, std::string& error);

// The same, but an edge of more than two faces does not fail the build: its faces are paired two
// by two, two of one part of the surface without such edges first, then two whose orientations
// agree, then the two nearest to lying flat across it (a surface with a fin on it stays joined),
// and a face left over is left unpaired, a border; `cut_edges` counts such edges, `on_cut_edge` (if
// given) flags their vertices (one per vertex).
bool build_corner_table_cutting(const Faces& faces, const Positions& positions, CornerTable& table,
                                int& inconsistent_edges, int& cut_edges, std::string& error,
                                std::vector<char>* on_cut_edge = nullptr);

// Flips faces so that every pair of neighbours agrees on orientation, one connected
// component at a time. Fails on a non-orientable component (a Moebius strip).
bool orient_faces_coherently(Faces& faces, const CornerTable& table, std::string& error);

// Appends to `fan` the corners of c's fan (the faces around vertex[c] joined across edges at it),
// marking each in `seen` (one flag per corner): swung forward, and back from c where the fan is
// open at a boundary. Needs a coherently oriented table.
void walk_fan(const CornerTable& table, int c, std::vector<char>& seen, std::vector<int>& fan);

// Counts vertices whose incident faces form more than one fan (two cones touching at a
// tip), and vertices where two boundary loops meet, flagging them in `flags` if given (one per
// vertex). Needs a coherently oriented table.
int count_nonmanifold_vertices(const CornerTable& table, int vertex_count, std::vector<char>* flags = nullptr);

// Boundary loops, each as the vertices in the order of its faces' boundary edges.
std::vector<std::vector<int>> boundary_loops(const CornerTable& table);

// Labels each face with its connected component (across shared edges); returns the count.
int face_components(const CornerTable& table, std::vector<int>& component_of_face);

}  // namespace hht
