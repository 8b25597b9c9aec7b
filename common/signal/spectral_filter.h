#pragma once
// Hilbert-spectrum filtering of an EMD (paper sec. 4.2, eq. 12-14):
//   G~(t) = sum_i phi(omega_i(t)) a_i(t) cos(theta_i(t)) + r(t)
//         = sum_i phi(omega_i(t)) imf_i(t) + r(t),
// since a_i cos(theta_i) is the real part of the analytic signal, i.e. the IMF itself. So a gain
// of 1 returns the signal exactly (to rounding), and no amplitude or phase is resynthesised.
//
// Common filters (omega in cycles per sample, the residue always kept):
//   low-pass (smoothing)   FrequencyBand{cutoff, 0.5},        gain 0
//   high-pass              FrequencyBand{0, cutoff},          gain 0
//   band-pass              FrequencyBand{low, high, true},    gain 0
//   band-stop              FrequencyBand{low, high},          gain 0
//   enhancement            FrequencyBand{cutoff, 0.5},        gain > 1

#include <vector>

#include "signal/emd.h"
#include "signal/hilbert_spectrum.h"

namespace hht {

// Selects low <= omega <= high, or the complement when outside.
struct FrequencyBand {
  double low = 0.0, high = 0.5;
  bool outside = false;
};

// phi(omega) = gain where the band selects omega, 1 elsewhere: gain 0 removes the band, 1 leaves
// it, > 1 enhances it. spectra[i] must be the spectrum of emd.imfs[i] (same count and lengths,
// else std::invalid_argument).
std::vector<double> filter_by_frequency(const EmdResult& emd,
                                        const std::vector<HilbertSpectrum>& spectra,
                                        const FrequencyBand& band, double gain);

// Residue plus the k coarsest IMFs (the paper's Fig. 5 coarse-to-fine series): k = 0 gives the
// residue, k >= number of IMFs the whole signal. Throws std::invalid_argument if k < 0.
std::vector<double> keep_coarsest(const EmdResult& emd, int k);

}  // namespace hht
