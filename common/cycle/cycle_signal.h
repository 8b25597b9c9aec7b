// Moving per-vertex values onto the Hamiltonian cycle and back: the 1D signals of the
// pipeline are the values read in cycle order, one periodic signal per component's cycle.
#pragma once

#include "cycle/hamiltonian_cycle.h"

#include <Eigen/Core>

#include <vector>

namespace hht {

// One signal per cycle segment (connected component), in cycle order.
std::vector<std::vector<double>> signals_along_cycle(const HamiltonianCycle& cycle, const Eigen::VectorXd& values);

// The inverse: vertex values from one signal per segment (`segments`). A vertex off the cycle takes the
// mean of its one-ring neighbours that are on it (the paper's rule for isolated vertices), or
// `off_cycle` when none is.
Eigen::VectorXd values_on_vertices(const HamiltonianCycle& cycle, const std::vector<std::vector<double>>& segments,
                                   const Faces& faces, const Eigen::VectorXd& off_cycle);

}  // namespace hht
