#include "signal/spectral_filter.h"

#include <algorithm>
#include <stdexcept>

namespace hht {

std::vector<double> filter_by_frequency(const EmdResult& emd,
                                        const std::vector<HilbertSpectrum>& spectra,
                                        const FrequencyBand& band, double gain) {
  if (spectra.size() != emd.imfs.size()) {
    throw std::invalid_argument("filter_by_frequency: need one spectrum per IMF");
  }
  const size_t n = emd.residue.size();
  std::vector<double> out = emd.residue;
  // Coarsest first, in the same order as keep_coarsest.
  for (size_t i = emd.imfs.size(); i-- > 0;) {
    const std::vector<double>& imf = emd.imfs[i];
    const std::vector<double>& omega = spectra[i].frequency;
    if (imf.size() != n || omega.size() != n) {
      throw std::invalid_argument("filter_by_frequency: IMF, spectrum and residue lengths differ");
    }
    for (size_t t = 0; t < n; ++t) {
      const bool in_band = band.low <= omega[t] && omega[t] <= band.high;
      out[t] += (in_band != band.outside) ? gain * imf[t] : imf[t];
    }
  }
  return out;
}

std::vector<double> keep_coarsest(const EmdResult& emd, int k) {
  if (k < 0) throw std::invalid_argument("keep_coarsest: k must not be negative");
  const size_t count = emd.imfs.size();
  const size_t kept = std::min(static_cast<size_t>(k), count);
  std::vector<double> out = emd.residue;
  for (size_t i = count; i-- > count - kept;) {
    const std::vector<double>& imf = emd.imfs[i];
    if (imf.size() != out.size()) {
      throw std::invalid_argument("keep_coarsest: IMF and residue lengths differ");
    }
    for (size_t t = 0; t < out.size(); ++t) out[t] += imf[t];
  }
  return out;
}

}  // namespace hht
