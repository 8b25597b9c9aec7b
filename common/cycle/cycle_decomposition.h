// The Hilbert-Huang transform of a per-vertex signal read along a Hamiltonian cycle: each
// component's cycle is one periodic 1D signal, decomposed by EMD into IMFs and a residue, and
// each IMF's Hilbert spectrum (instantaneous amplitude, phase, frequency) is computed. Results
// map back to vertices through cycle_signal.h.
#pragma once

#include "cycle/cycle_signal.h"
#include "signal/emd.h"
#include "signal/hilbert_spectrum.h"
#include "signal/spectral_filter.h"

#include <string>

namespace hht {

struct CycleDecomposition {
  std::vector<EmdResult> emd;                         // one per cycle segment
  std::vector<std::vector<HilbertSpectrum>> spectra;  // per segment, per IMF (finest first)
  int imf_count() const;                              // the most IMFs of any segment
};

struct ImfSummary {
  int sifts = 0;                 // summed over segments
  double mean_frequency = 0;     // amplitude-weighted, cycles per sample
  double energy_share = 0;       // sum of squares over that of all IMFs plus the residue
};

// Decomposes `signal` (one value per vertex). Fails on non-finite values.
bool decompose_along_cycle(const HamiltonianCycle& cycle, const Eigen::VectorXd& signal, const EmdOptions& options,
                           CycleDecomposition& out, std::string& error);

// Spectra of every segment's IMFs (the EMD must be done); FFTW plans reused per length.
void compute_spectra(CycleDecomposition& d);

std::vector<ImfSummary> summarize_imfs(const CycleDecomposition& d);  // index 0 = finest IMF

// The paper's Fig. 3: per IMF, amplitude-weighted histogram of instantaneous frequency over
// [0, 0.5] in `bins` bins, summed over segments.
std::vector<std::vector<double>> frequency_distribution(const CycleDecomposition& d, int bins);

enum class CycleQuantity { Imf, Amplitude, Frequency, Phase, Residue };

// One quantity of IMF `imf` (0 = finest) per vertex; 0 where a segment has fewer IMFs, the
// one-ring mean on vertices off the cycle.
Eigen::VectorXd quantity_on_vertices(const HamiltonianCycle& cycle, const CycleDecomposition& d, CycleQuantity what,
                                     int imf, const Faces& faces);

// The paper's eq. 14 per segment, mapped to vertices: sum_i phi(omega_i) IMF_i + residue,
// phi = gain on `band`, 1 elsewhere. Vertices off the cycle change by the one-ring mean of
// their neighbours' change (so gain 1 changes nothing anywhere).
Eigen::VectorXd filtered_on_vertices(const HamiltonianCycle& cycle, const CycleDecomposition& d,
                                     const FrequencyBand& band, double gain, const Faces& faces,
                                     const Eigen::VectorXd& signal);

// The residue plus the k coarsest IMFs of each segment (the paper's Fig. 5 series).
Eigen::VectorXd coarsest_on_vertices(const HamiltonianCycle& cycle, const CycleDecomposition& d, int k,
                                     const Faces& faces, const Eigen::VectorXd& signal);

}  // namespace hht
