// The paper's signal (sec. 4.1, after Hu, Wang & Qin 2014): G_i = <(L V)_i, n_i>, with L the
// cotangent Laplacian M^-1 C and n_i the area-weighted vertex normal. Convention: G = 2H,
// twice the mean curvature, positive where the surface is convex towards its normals
// (G = 2/r on a sphere of radius r with outward normals). The reconstruction solves for
// positions whose L V has this normal component, so the two share one definition.
#pragma once

#include "mesh/intrinsic_delaunay.h"

#include <string>

namespace hht {

struct MeanCurvature {
  Eigen::VectorXd signal;  // G, per vertex
  Positions laplacian;     // L V, per vertex (the mean-curvature normal 2H n on a smooth surface)
  Positions normals;       // n
  Eigen::VectorXd areas;   // mixed Voronoi areas (the diagonal of M)
  LaplacianTriangles triangles = LaplacianTriangles::Mesh;  // L's (the reconstruction takes the same)
  IntrinsicDelaunayReport delaunay;
};

// Fails on non-finite coordinates. Vertices of no face, or with zero area, get G = 0.
bool mean_curvature(const Positions& positions, const Faces& faces, MeanCurvature& out, std::string& error,
                    LaplacianTriangles triangles = LaplacianTriangles::Mesh);

}  // namespace hht
