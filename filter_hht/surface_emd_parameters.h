// Parameters shared by the two surface EMD filters: the EMD stopping rules (the same names,
// defaults and help as the 1D filters), the residue the mesh is rebuilt from, and lambda.
#pragma once

#include "meshlab_api.h"
#include "filters/surface_emd_smoothing.h"

namespace hht_plugin {

// The residue k and lambda; the EMD rules are declared last (declare_emd_parameters, for experts).
void declare_surface_emd_parameters(RichParameterList& p);
// Everything but the feature options; fails with the reason on out-of-range values.
bool surface_emd_smoothing_options(const RichParameterList& p, hht::SurfaceEmdSmoothingOptions& o, QString& error);

}  // namespace hht_plugin
