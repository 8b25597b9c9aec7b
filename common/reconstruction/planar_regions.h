// Flat parts of a denoised CAD surface made flat: regions of faces whose normals stay within a
// few degrees of their seed face's, grown across edges, are taken as planar where a quadric
// height field fitted to their vertices bends by at most max_bend_degrees over the region (a
// curved part, faceted or not by the normal filter, bends more); the faces of each planar region
// get the plane's normal as their target and the vertices are fitted to the targets (Sun et al.'s
// update, normal_vertex_update.h, run until it settles; faces of no planar region have no
// target). A crease between two planar regions comes out where their planes meet. Ours: the
// guided normal filter leaves low-frequency bumps on the flat faces of a part and rounds its
// creases a little (docs/quality.md items 36 and 37).
#pragma once

#include "mesh/mesh_arrays.h"

#include <string>

namespace hht {

struct PlanarRegionOptions {
  double seed_degrees = 3;        // a face joins its neighbour's region within this angle of the region's seed
  int min_faces = 30;             // smaller regions say too little about their shape
  double max_bend_degrees = 1;    // the fitted quadric's slope at any vertex of the region, from the plane's
  // The vertex update towards the regions' normals, in steps of `vertex_iterations` until a step
  // moves the vertices by at most `settled` times what the first step moved them, or after
  // `max_vertex_iterations` (docs/quality.md item 37: it converges slowly over a large region).
  int vertex_iterations = 20;
  double settled = 0.05;
  int max_vertex_iterations = 200;
};

struct PlanarRegionReport {
  int regions = 0;  // made flat
  int faces = 0;    // in them
  int fit_iterations = 0;  // of the vertex update
};

// Fails, leaving `result` as it was, when the faces do not form an edge-manifold mesh over the
// positions (build_corner_table's message).
bool flatten_planar_regions(const Positions& positions, const Faces& faces, const PlanarRegionOptions& options,
                            Positions& result, PlanarRegionReport& report, std::string& error);

}  // namespace hht
