#include "filter_spec.h"

namespace hht_plugin {

std::vector<FilterSpec> all_filters() {
  return {hamiltonian_cycle_filter(), curvature_signal_filter(), hilbert_spectra_filter(), spectral_filter_filter(),
          add_noise_filter(),         denoise_filter(),          compare_filter(),         bilateral_filter(),
          adaptive_smooth_filter(),   guided_denoise_filter(),   surface_emd_filter(),     feature_centric_emd_filter(),
          nonlocal_means_filter()};
}

}  // namespace hht_plugin
