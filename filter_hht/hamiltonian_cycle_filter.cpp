// "HHT: Hamiltonian Cycle": the space-filling curve that turns the surface into a 1D signal.
#include "filter_spec.h"
#include "mesh_adapter.h"

#include "cycle/hamiltonian_cycle.h"

#include <vcg/complex/algorithms/update/color.h>
#include <vcg/complex/allocate.h>

namespace hht_plugin {

namespace {

constexpr int kMaxTries = 100;

void declare(const MeshDocument&, RichParameterList& p) {
  p.addParam(RichInt("seed", 0, "Seed",
                     "Where the ring starts growing: 0 takes each component's first face, any other "
                     "value a random face drawn from this seed. Different seeds give different cycles."));
  p.addParam(RichInt("tries", 1, "Seeds to try",
                     "Grow the ring from this many seeds per component and keep the cycle that leaves the "
                     "fewest isolated vertices (1 to 100). Each try costs one more linear pass."));
  p.addParam(RichBool("repair", true, "Attach isolated vertices",
                      "Attach vertices the ring missed by a local move (drop an ear of the region, take two "
                      "triangles). Vertices still missed are logged and get quality -1."));
  p.addParam(RichBool("addCycleLayer", false, "Add the cycle as a new layer",
                      "Add a layer holding the cycle as an edge polyline (one closed loop per connected "
                      "component), to look at over the mesh."));
}

void add_cycle_layer(MeshDocument& document, const hht::Positions& positions, const hht::HamiltonianCycle& cycle,
                     const QString& label) {
  MeshModel* layer = document.addNewMesh("", label, false);
  CMeshO& m = layer->cm;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, cycle.order.size());
  for (int index : cycle.order)
    (vi++)->P() = CMeshO::CoordType(static_cast<CMeshO::ScalarType>(positions(index, 0)),
                                   static_cast<CMeshO::ScalarType>(positions(index, 1)),
                                   static_cast<CMeshO::ScalarType>(positions(index, 2)));
  vcg::tri::Allocator<CMeshO>::AddEdges(m, cycle.order.size());
  for (size_t s = 0; s + 1 < cycle.segment_begin.size(); ++s) {
    const int b = cycle.segment_begin[s], e = cycle.segment_begin[s + 1];
    for (int i = b; i < e; ++i) {
      auto& edge = m.edge[i];
      edge.V(0) = &m.vert[i];
      edge.V(1) = &m.vert[i + 1 < e ? i + 1 : b];
    }
  }
  update_box_and_normals(*layer);
}

bool apply(FilterRun& run) {
  Stopwatch clock;
  MeshModel& model = *run.document.mm();
  hht::Positions positions;
  hht::Faces faces;
  hht::InputMap input_map;  // where each mesh vertex went (merged seams, split fans)
  if (!read_mesh_to_filter(model.cm, positions, faces, run.error, run.log, input_map)) return false;

  run.report(10, "Growing the ring");
  hht::CycleOptions options;
  options.seed = run.parameters.getInt("seed");
  options.tries = run.parameters.getInt("tries");
  if (!check_range("tries", options.tries, 1, kMaxTries, run.error, " (each try is one more pass over the mesh)"))
    return false;
  options.repair = run.parameters.getBool("repair");
  hht::HamiltonianCycle cycle;
  std::string message;
  if (!hht::hamiltonian_cycle(faces, static_cast<int>(positions.rows()), options, cycle, message)) {
    run.error = nothing_changed(message);
    return false;
  }
  const double cycle_seconds = clock.lap();

  run.report(80, "Writing the cycle order into vertex quality");
  Eigen::VectorXd order_value(positions.rows());
  for (Eigen::Index v = 0; v < order_value.size(); ++v) order_value[v] = cycle.position[v];
  model.updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  // Each mesh vertex takes its row's place on the cycle (a split vertex one copy's, as any result).
  hht::set_vertex_quality(model.cm, hht::to_input_vertices(order_value, input_map));
  vcg::tri::UpdateColor<CMeshO>::PerVertexQualityRamp(model.cm, 0.f, std::max(1.f, float(cycle.order.size()) - 1));
  for (auto& v : model.cm.vert)
    if (!v.IsD() && v.Q() < 0) v.C() = vcg::Color4b::Black;  // not on the cycle
  if (run.parameters.getBool("addCycleLayer"))
    add_cycle_layer(run.document, positions, cycle, "Hamiltonian cycle of " + model.label());

  const double n = static_cast<double>(positions.rows());
  run.log(QString("Hamiltonian cycle: %1 vertices, %2 on the cycle (%3%), %4 isolated (%5 attached by repair), "
                  "%6 unreferenced")
              .arg(positions.rows()).arg(cycle.order.size()).arg(100.0 * cycle.order.size() / n, 0, 'f', 3)
              .arg(cycle.isolated).arg(cycle.repaired).arg(cycle.unreferenced));
  if (cycle.components > 1)
    run.log(QString("  %1 connected components: one cycle each, concatenated in quality order")
                .arg(cycle.components));
  if (cycle.holes > 0)
    run.log(QString("  %1 boundary loops closed by a dummy vertex each (the mesh is unchanged)").arg(cycle.holes));
  if (cycle.inconsistent_edges > 0)
    run.log(QString("  %1 edges join faces of opposite orientation; the cycle was built on a coherently "
                    "oriented copy").arg(cycle.inconsistent_edges));
  run.log(QString("  quality = position along the cycle (0..%1), -1 and black when not on it; %2 s")
              .arg(cycle.order.size() - 1).arg(cycle_seconds + clock.seconds(), 0, 'f', 3));
  return true;
}

}  // namespace

FilterSpec hamiltonian_cycle_filter() {
  return {"HHT: Hamiltonian Cycle",
          "Builds a Hamiltonian cycle through the mesh vertices with the <i>Ring Expander</i> of Gurung, Luffel, "
          "Lindstrom and Rossignac (<b>LR: compact connectivity representation for triangle meshes</b>, ACM TOG "
          "30(4), 2011), the space-filling curve that turns the surface into a 1D signal (HHT pipeline, step 1).<br>"
          "Vertex quality receives each vertex's position along the cycle (0..k-1; -1 for a vertex the cycle misses) "
          "and the mesh is coloured by it. Consecutive vertices on the cycle are always joined by a mesh edge. "
          "Holes are closed by a dummy vertex per boundary loop (the mesh itself is not changed); each connected "
          "component gets its own cycle. Non-manifold meshes are refused with a message.",
          MeshLabFilter::FilterClass(MeshLabFilter::Quality | MeshLabFilter::VertexColoring),
          MeshLabFilter::SINGLE_MESH,
          MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR,
          declare,
          apply};
}

}  // namespace hht_plugin
