#pragma once
// Hilbert spectra of IMFs (paper sec. 3.3): instantaneous amplitude, phase and frequency from the
// analytic signal z = x + i H[x], computed by FFT.
//
// Analytic signal: X = FFT(x); DC (and Nyquist for even n) kept with weight 1, positive
// frequencies doubled, negative ones zeroed; z = IFFT. Computed as z = x + i H[x] with
// H[x] = IFFT(-i sgn(k) X[k]) by a real-to-complex and a complex-to-real FFT, so Re z == x
// exactly. The FFT sees x as one period of a periodic signal: exact for a Hamiltonian cycle's
// signal; for an open path the ends carry the usual end effect of the jump between the last
// and the first sample.
//
// Per sample t:  amplitude a = |z|,  phase theta = arg z in (-pi, pi],
//   frequency omega[t] = arg(z[t+1] conj(z[t])) / (2 pi)   in cycles per sample,
// with t+1 taken modulo n (Periodic); for Open signals omega[n-1] = omega[n-2]. It is computed
// as the phase step theta[t+1] - theta[t] wrapped into (-pi, pi], the same number without a
// second atan2 per sample.
// Near-zero amplitude rule: where a[t] < 1e-3 * RMS(a) of that IMF, or where omega[t] < 0, the
// phase is meaningless and omega[t] is set to the IMF's amplitude-weighted mean frequency
// over the remaining samples (0 if none remain); every omega lies in [0, 0.5].

#include <complex>
#include <memory>
#include <vector>

#include "signal/emd.h"

namespace hht {

struct HilbertSpectrum {
  std::vector<double> amplitude, phase, frequency;  // frequency in cycles per sample, in [0, 0.5]
};

// FFTW plans and buffers for one signal length n, created once and reused for every IMF.
// Plans are made with FFTW_ESTIMATE (cheap, deterministic). Constructing and destroying
// transformers is serialised by a mutex private to this file; other FFTW planners in the process
// are not covered by it. One transformer must not be used by two threads at once; separate
// transformers may run concurrently.
class HilbertTransformer {
 public:
  explicit HilbertTransformer(int n);  // throws std::invalid_argument if n < 1
  ~HilbertTransformer();
  HilbertTransformer(const HilbertTransformer&) = delete;
  HilbertTransformer& operator=(const HilbertTransformer&) = delete;

  int size() const;
  // z = x + i H[x]; x must have size() samples (else std::invalid_argument). z is resized.
  void analytic_signal(const std::vector<double>& x, std::vector<std::complex<double>>& z);
  // Amplitude, phase and frequency of one IMF, by the rules above.
  HilbertSpectrum spectrum(const std::vector<double>& imf, SignalBoundary boundary);

  // FFTW plans created by all transformers so far (diagnostics: plans are reused, not remade).
  static long plans_created();

 private:
  struct Plans;
  // Runs both transforms; the result, n H[x], lives in the transformer's buffer.
  const double* hilbert_transform_times_n(const std::vector<double>& x);
  std::unique_ptr<Plans> plans_;
};

// Spectra of all IMFs (IMFs of unequal lengths: std::invalid_argument). Up to `threads` threads
// (at most one per IMF) each make one transformer and take every threads-th IMF; the result does
// not depend on the number of threads.
std::vector<HilbertSpectrum> hilbert_spectra(const std::vector<std::vector<double>>& imfs,
                                             SignalBoundary boundary, int threads = 2);

// Amplitude-weighted mean instantaneous frequency, sum a omega / sum a (0 for a zero IMF).
double mean_frequency(const HilbertSpectrum& spectrum);

// Sum of squares of the samples.
double energy(const std::vector<double>& imf);

// Frequency distribution (paper Fig. 3): per IMF, the sum of the instantaneous amplitudes of the
// samples whose frequency falls in each of `bins` equal bins over [0, 0.5] (0.5 goes in the
// last bin). Not normalised. Throws std::invalid_argument if bins < 1.
std::vector<std::vector<double>> frequency_histogram(const std::vector<HilbertSpectrum>& spectra,
                                                     int bins);

}  // namespace hht
