// Hinge heights: across every interior edge (a, b) shared by faces (a, b, c) and (b, a, d), the
// height of d over the plane of (a, b, c), divided by the standard deviation that unit noise
// normal to the surface gives it. To first order only the normal offsets z count, and the
// height is z_d - (alpha z_a + beta z_b + gamma z_c), with (alpha, beta, gamma) the barycentric
// coordinates of d's foot in (a, b, c); so the divisor is sqrt(1 + alpha^2 + beta^2 + gamma^2).
//
// Why: on a CAD export many hinges are exactly flat (inside planar faces, along a cylinder's
// rulings) and noise never is. A low quantile of |hinge height| therefore bounds the noise
// from above: a surface only adds to it (|N(s, sigma^2)| is stochastically larger than
// |N(0, sigma^2)|), and it is about 0 on a noise-free mesh with flat parts, where the one-ring
// heights of signal/noise_estimate.h still read its coarse triangulation as 7-14% noise.
#pragma once

#include "mesh/mesh_arrays.h"
#include "mesh/vertex_adjacency.h"

#include <functional>
#include <vector>

namespace hht {

// The hinge of an interior edge (a, b): the faces (a, b, c) and (a, b, d), and d's height as above.
struct Hinge {
  int a, b, c, d;
  double height;
};

// Calls visit once per interior edge of two faces (boundary and non-manifold edges, edges of
// zero-area faces, and a face against its own duplicate are left out); heights in the length
// unit of `positions`, signed. `adjacency` is vertex_adjacency() of the same faces.
void for_each_hinge(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency,
                    const std::function<void(const Hinge&)>& visit);

// The heights of for_each_hinge, in its order.
std::vector<double> hinge_heights(const Positions& positions, const Faces& faces, const VertexAdjacency& adjacency);

}  // namespace hht
