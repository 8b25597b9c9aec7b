// Empirical mode decomposition of a per-vertex signal computed on the surface itself ("3D-EMD",
// Wang et al., Graphical Models 74(4) 2012; the baseline of the paper's Table 1).
//
// Rules, the same as the 1D EMD of emd.h wherever the surface allows:
//   - Extrema: a vertex is a maximum (minimum) when its value is above (below) that of every
//     one-ring neighbour, ties broken by vertex index ((s_i, i) ordered lexicographically), so
//     every component with a non-feature vertex has at least one maximum and one minimum.
//   - Envelopes: the upper (lower) envelope minimises the discrete bi-harmonic energy
//     e^T C M^-1 C e (C cotangent matrix, M mixed Voronoi areas; cotangent_laplacian.h) with
//     the maxima's (minima's) values as hard constraints: (C M^-1 C)_FF e_F = -(C M^-1 C)_FX s_X
//     on the free vertices F. Nothing is imposed at mesh boundaries (natural conditions).
//   - Sifting stops after the first sift with SD = sum (s_prev - s)^2 / sum s_prev^2 below
//     sd_threshold, or after max_sifts; the decomposition stops when the residue has fewer than
//     min_extrema maxima or minima, after max_imfs IMFs (if > 0), or when an IMF did not lower
//     the residue's number of extrema. IMFs + residue == signal to rounding.
//
// Solver (the baseline should be as fast as honestly possible): the constrained system is kept
// at full size with the constrained rows and columns replaced by their diagonal entry (and the
// right-hand side by diagonal * value), so that its sparsity pattern never changes: CHOLMOD's
// symbolic analysis (the better of AMD and METIS orderings, supernodes) is done once for the
// whole decomposition and copied to the second envelope's factor, and each envelope costs one
// numeric factorisation and one solve. The two
// envelopes of a sift are solved on two threads (threads >= 2), as the 1D EMD fits its two
// splines (emd.h); meanwhile OpenBLAS, if it is the BLAS, is held to one thread per call (its
// own threads inside both factorisations would oversubscribe the cores). Tried and dropped: conjugate gradients preconditioned with the previous
// sift's factor (the systems differ by a term of rank <= 2 x the changed extrema): on Fandisk it
// needed about as many steps as extrema changed (185-2300 for 300-1000 changes), 5-20 times the
// cost of a new factorisation.
//
// Feature-centric variant (Hu, Wang & Qin 2014, as read here): vertices flagged in
// `feature_vertices` are kept out of the envelope fitting (never extrema, not compared against
// by their neighbours, free in both envelope solves) and every IMF is zero on them, so sharp
// features stay whole in the residue.
#pragma once

#include "mesh/mesh_arrays.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hht {

struct SurfaceEmdOptions {
  double sd_threshold = 0.1;
  int max_sifts = 50;    // values below 1 act as 1
  int min_extrema = 15;  // values below 1 act as 1
  int max_imfs = 0;      // 0 = no cap
  // Optional, one flag per vertex: the feature-centric variant (see above).
  const std::vector<unsigned char>* feature_vertices = nullptr;
  int threads = 2;  // >= 2: the two envelopes of a sift are solved in parallel
};

struct SurfaceEmdReport {
  int factorizations = 0;       // numeric factorisations, two per sift
  double analysis_seconds = 0;  // the symbolic analysis, once per decomposition (copied to the other envelope)
};

struct SurfaceEmdResult {
  std::vector<Eigen::VectorXd> imfs;  // finest first
  Eigen::VectorXd residue;
  std::vector<int> sifts;  // per IMF
  SurfaceEmdReport report;
};

// Extrema by the rule above. Vertices flagged in `excluded` are neither extrema nor compared
// against; `neighbours_offset`/`neighbours` is the one-ring adjacency (CSR).
struct SurfaceExtrema {
  std::vector<int> maxima, minima;
};
void surface_extrema(const std::vector<int>& neighbours_offset, const std::vector<int>& neighbours,
                     const Eigen::VectorXd& s, const std::vector<unsigned char>* excluded, SurfaceExtrema& out);

// One-ring adjacency of the vertices, as CSR, neighbours sorted.
void one_ring_adjacency(const Faces& faces, int vertex_count, std::vector<int>& offset, std::vector<int>& neighbours);

// Decomposes `signal` (one value per vertex) on the mesh. Vertices of no face keep their value
// in the residue. Fails, with a message, on a mesh without faces, non-finite coordinates or
// signal values, face indices out of range or repeated in a face, a signal or feature mask of
// the wrong size, or a failed factorisation.
bool surface_emd(const Positions& positions, const Faces& faces, const Eigen::VectorXd& signal,
                 const SurfaceEmdOptions& options, SurfaceEmdResult& result, std::string& error);

}  // namespace hht
