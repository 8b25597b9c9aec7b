// Denoising quality against a ground truth with the same connectivity (algorithms.md sec. 8):
// `result` and `reference` are two positions of the same vertices, `faces` their triangles.
//
// Degenerate faces: a face of (numerically) zero area in the reference has no true normal and
// is left out of E_a; one degenerate only in the result has lost its orientation and counts
// 90 degrees, the mean angle between a fixed and a random direction. For distances a
// degenerate reference face is the segment (or point) it collapsed to.
//
// Vertices of no face are not part of either surface: they are left out of the means and get
// 0 in the per-vertex values (so identical meshes always give 0). With no faces, everything
// is 0. Mismatched sizes or face indices out of range throw std::invalid_argument.
#pragma once

#include "mesh/mesh_arrays.h"

namespace hht {

// E_a: mean over faces of the angle (degrees) between the result's and the reference's face
// normals. Normals follow the faces' winding, so a flipped face counts 180 degrees.
double mean_face_normal_error_degrees(const Positions& result, const Positions& reference, const Faces& faces);

// Faces turned over: the result's normal more than 90 degrees from the reference's, counted
// over the faces not folded in the reference (pointing against the sum of their corners'
// unnormalised area-weighted normals there): scripts/evaluate_quality.py's count.
int flipped_faces(const Positions& result, const Positions& reference, const Faces& faces);

// E_v: mean over the result's vertices of the distance to the reference surface (the closest
// point on any reference triangle, not the corresponding vertex), divided by the diagonal of
// the reference surface's bounding box (undivided if that diagonal is 0).
double mean_distance_to_reference(const Positions& result, const Positions& reference, const Faces& faces);

// Per vertex, for colour maps: the absolute distance to the reference surface.
Eigen::VectorXd vertex_distance_to_reference(const Positions& result, const Positions& reference,
                                             const Faces& faces);

// Per vertex, for colour maps: the mean E_a of the faces around it.
Eigen::VectorXd vertex_normal_error_degrees(const Positions& result, const Positions& reference,
                                            const Faces& faces);

}  // namespace hht
