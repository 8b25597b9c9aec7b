#include "hht_parameters.h"

namespace hht_plugin {

void declare_cycle_and_emd_parameters(RichParameterList& p) {
  p.addParam(RichInt("seed", 0, "Cycle seed",
                     "Seed of the Hamiltonian cycle that orders the vertices into a 1D signal (0: first face). "
                     "Different seeds give different, equally valid cycles."));
  p.addParam(RichFloat("sdThreshold", 0.1f, "Sifting threshold (SD)",
                       "Sifting of an IMF stops when SD = sum (s_prev - s)^2 / sum s_prev^2 falls below this "
                       "(the paper's 0.1). Smaller: more sifts, narrower-band IMFs."));
  p.addParam(RichInt("maxSifts", 50, "Max sifts per IMF", "Cap on the sifting iterations of one IMF."));
  p.addParam(RichInt("minExtrema", 15, "Stop below this many extrema",
                     "The decomposition stops when the residue has fewer maxima or fewer minima than this "
                     "(the paper's 15)."));
  p.addParam(RichInt("maxImfs", 0, "Max IMFs", "Cap on the number of IMFs; 0 = no cap (the paper's default)."));
}

hht::CycleOptions cycle_options(const RichParameterList& p) {
  hht::CycleOptions o;
  o.seed = p.getInt("seed");
  return o;
}

hht::EmdOptions emd_options(const RichParameterList& p) {
  hht::EmdOptions o;
  o.sd_threshold = p.getFloat("sdThreshold");
  o.max_sifts = std::max(1, p.getInt("maxSifts"));
  o.min_extrema = std::max(1, p.getInt("minExtrema"));
  o.max_imfs = std::max(0, p.getInt("maxImfs"));
  return o;
}

}  // namespace hht_plugin
