// Parameters shared by the HHT filters (cycle seed and EMD stopping rules): declared once
// with the same names, defaults and help everywhere.
#pragma once

#include "signal/emd.h"
#include "cycle/hamiltonian_cycle.h"

#include "meshlab_api.h"

namespace hht_plugin {

void declare_cycle_and_emd_parameters(RichParameterList& p);
hht::CycleOptions cycle_options(const RichParameterList& p);
hht::EmdOptions emd_options(const RichParameterList& p);

}  // namespace hht_plugin
