// Sharp feature detection for feature-preserving processing (paper sec. 4.3, after the
// "neighbor supporting" detector of Wang et al. 2012; notes sec. 6). Steps:
//  1. Face normals are filtered first: with 30% noise the raw ones are off by ~28 degrees.
//     Guided normal filtering (Zhang et al. 2015): a joint bilateral filter over the faces
//     sharing a vertex, whose range kernel compares "guidance" normals taken from the most
//     consistent patch around each face, so creases stay sharp. Positions never move.
//  2. Crease edges: the filtered normals of their two faces differ by more than the angle;
//     mesh boundary edges always.
//  3. Neighbour support: a weaker crease edge that continues a crease along its direction
//     joins it (hysteresis), so noise does not cut lines into pieces.
//  4. Where the filter blurs a spot (a corner whose faces all touch two creases) the creases
//     stop one vertex short, closing a loop of crease edges around it: such a vertex is
//     taken back as their junction.
//  5. Thinning to one-vertex-wide chains, least salient vertices first; saliency from each
//     vertex's normal voting tensor T = sum_f w_f n_f n_f^T over its faces (Wang et al.).
//  6. Groups of a few vertices are dropped; the rest is linked (link_feature_lines), and
//     vertices where three or more lines meet are the corners. Wang et al.'s corner test on
//     the tensor's smallest eigenvalue found no corner that linking misses (fandisk, cube,
//     0-30% noise), so it is not used.
// Known limits: the filter blunts creases under ~45 degrees (see angle_degrees), and where
// long thin triangles span a narrow strip between creases it blends the neighbouring planes
// into the strip, so a short line may cut across it (fandisk: 15 of 750 line edges).
#pragma once

#include "mesh/mesh_arrays.h"

#include <functional>
#include <string>
#include <vector>

namespace hht {

enum class FeatureType : unsigned char { None, Edge, Corner };

struct SharpFeatureOptions {
  // A mesh edge is a crease when the *filtered* normals of its two faces differ by more than
  // this angle (180 degrees minus the interior dihedral angle: 0 on a plane, 90 on a cube
  // edge). 30 sits above what the filtered normals show on smooth parts (at most ~10 degrees
  // on fandisk with 30% noise, ~28 on a torus meshed at 11 degrees a step with 10% noise) and
  // below fandisk's creases (75-95; its weak ~22 degree crease comes out sharper and is found
  // too). The filter blunts moderate creases: a noise-free 40 degree fold comes out at ~29
  // and is missed, a 45 degree one at ~37. With filter_iterations = 0 (noise-free input) the
  // threshold applies to the raw normals exactly.
  double angle_degrees = 30.0;
  // Guided normal filtering passes before voting; 0 votes with the raw normals (noise-free
  // input). 3-5 suffice for 30% noise; more passes flatten smooth curved parts into facets
  // whose steps grow towards the threshold.
  int filter_iterations = 4;
  // Range width of the normal filter, on |g_i - g_j| between unit guidance normals: with 0.35
  // faces whose guidance is 30 degrees apart still mix with weight ~0.3, 60 degrees apart
  // with ~0.02. Smaller keeps moderate creases but cuts coarse curved parts into facets.
  double filter_sigma = 0.35;
  // Neighbour support: an edge whose crease angle reaches only this fraction of angle_degrees
  // is a crease too when it continues one (turning by less than 60 degrees where they meet),
  // so noise does not cut lines into pieces, while weaker creases branching off are not
  // followed.
  double support_ratio = 0.8;
  // Connected groups of feature vertices smaller than this are dropped as noise.
  int min_feature_vertices = 5;
};

// Per-vertex classification: Edge on a feature line (crease or mesh boundary), Corner where
// three or more lines meet, None elsewhere. Feature vertices form one-vertex-wide chains, and
// the types agree with link_feature_lines(positions, faces, type): its corners are the Corner
// vertices and every Edge vertex lies on one of its lines. Linear time (~1 s for 400k
// vertices). Fails, with a message, on a mesh without faces, non-finite coordinates, bad
// indices, non-manifold edges, non-orientable parts or an angle outside (0, 180).
bool detect_sharp_features(const Positions& positions, const Faces& faces, const SharpFeatureOptions& options,
                           std::vector<FeatureType>& type, std::string& error);

// The face normals the detector votes with: guided normal filtering (see above), `iterations`
// passes with range width `sigma`, or each face's own width from `face_sigma` (one per face,
// positive) where that is given. Used on its own by the denoiser's refinement. Fails like
// detect_sharp_features on broken input.
bool guided_face_normals(const Positions& positions, const Faces& faces, int iterations, double sigma,
                         Positions& normals, std::string& error, const std::vector<double>& face_sigma = {});

// Bilateral normal filtering (Zheng, Fu, Au and Tai, "Bilateral normal filtering for mesh
// denoising", TVCG 2011; the local scheme): the same passes and kernels, with the range kernel
// on the filtered normals themselves, over the faces sharing a vertex with the face, the face
// itself left out (as in the authors' code); face_sigma as there. Fails like guided_face_normals.
bool bilateral_face_normals(const Positions& positions, const Faces& faces, int iterations, double sigma,
                            Positions& normals, std::string& error, const std::vector<double>& face_sigma = {});

// `passes` single passes of guided (or, with own_normals, bilateral) normal filtering with the
// positions refitted between them: each pass filters the face normals of the current positions,
// then positions = fit(positions, filtered normals). The same as calling guided_face_normals (or
// bilateral_face_normals) with one pass and fitting, `passes` times, with the mesh's topology built
// once. Fails like guided_face_normals.
bool filter_face_normals_refitting(const Positions& positions, const Faces& faces, int passes, double sigma,
                                   bool own_normals,
                                   const std::function<Positions(const Positions&, const Positions&)>& fit,
                                   Positions& result, std::string& error, const std::vector<double>& face_sigma = {});

}  // namespace hht
