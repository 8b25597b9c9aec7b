#pragma once
// Empirical Mode Decomposition (Huang et al. 1998) of a 1D signal: the signal is split into
// intrinsic mode functions (IMFs), finest first, and a residue, with
//   signal == sum of IMFs + residue   (to rounding: the residue is updated as r_k = r_{k-1} - h_k).
//
// Sifting one IMF: s_0 = r_{k-1}; s_i = s_{i-1} - (upper + lower envelope) / 2, the envelopes
// being cubic splines through the maxima and through the minima of s_{i-1}.
//   - Periodic signals (a Hamiltonian cycle): extrema are found cyclically (the last sample is
//     compared with the first) and the envelopes are periodic splines, so there are no ends.
//   - Open signals (a path): the ends are not extrema; 2 extrema of each kind are mirrored
//     beyond each end (as Rilling's emd.m and PyEMD's nbsym = 2 do), about the extremum
//     nearest to the end, or about the end sample when the signal there lies beyond the first
//     extremum of the other kind (the end sample then becomes a knot too) or when mirroring
//     about the extremum would not reach past the end; the envelopes are not-a-knot splines.
//   - A flat run of equal samples counts as one extremum, at its middle (the left one of the
//     two middle samples for an even length).
//
// Stopping the sifting of one IMF (the IMF is the last s_i):
//   - after the first sift i with SD = sum_t (s_{i-1}(t) - s_i(t))^2 / sum_t s_{i-1}(t)^2
//     below sd_threshold (the ratio-of-sums form of Huang's SD: the pointwise form divides by
//     near-zero samples and grows with the length), or
//   - after max_sifts sifts, or
//   - before a sift, when s_i has no maximum or no minimum left, so that no envelope exists.
// Stopping the decomposition, checked on the residue before each new IMF:
//   - the residue has fewer than min_extrema maxima or fewer than min_extrema minima (the
//     paper's rule, 15), or
//   - max_imfs IMFs have been extracted (when max_imfs > 0), or
//   - the last IMF left the residue with no fewer extrema (maxima + minima) than it had before,
//     a guard that makes the decomposition always terminate.

#include <vector>

namespace hht {

enum class SignalBoundary { Periodic, Open };  // Periodic: a Hamiltonian cycle's signal; Open: a path

struct EmdOptions {
  SignalBoundary boundary = SignalBoundary::Periodic;
  double sd_threshold = 0.1;  // sifting stops when SD (above) < this
  int max_sifts = 50;         // cap on sifts per IMF; values below 1 act as 1
  int min_extrema = 15;       // no new IMF once the residue has fewer maxima or minima than this;
                              // values below 1 act as 1
  int max_imfs = 0;           // 0 = no cap (the paper's default)
  // Optional, size n: samples flagged non-zero are never taken as extrema, neither for the
  // envelopes nor for the stopping rule (feature vertices, paper sec. 4.3).
  const std::vector<unsigned char>* never_extremum = nullptr;
  // With threads >= 2, signals of at least 65536 samples fit the upper and the lower envelope of
  // each sift on two threads (about 15-20% faster; shorter signals gain nothing). The result
  // does not depend on it.
  int threads = 2;
};

enum class EmdStatus {
  Ok,
  NonFiniteInput,  // the signal holds a NaN or an infinity: nothing was decomposed
};

struct EmdResult {
  std::vector<std::vector<double>> imfs;  // finest first
  std::vector<double> residue;            // empty only when status != Ok
  std::vector<int> sifts;                 // sifts used per IMF
  EmdStatus status = EmdStatus::Ok;
};

// Decomposes the signal. Any length works, including 0: a signal with too few extrema (empty,
// constant, shorter than about 2 * min_extrema samples) gives no IMF and residue == signal.
// A NaN or infinite sample gives status NonFiniteInput with no IMF and an empty residue.
// Throws std::invalid_argument if never_extremum is given with a size other than the signal's.
EmdResult emd(const std::vector<double>& signal, const EmdOptions& options = {});

// Local extrema as sample indices, increasing, by the rules above (flat runs count once, at
// their middle; cyclic search for Periodic; never the end samples for Open; flagged samples
// skipped). `out`'s capacity is reused.
struct Extrema {
  std::vector<int> maxima, minima;
};
void find_extrema(const std::vector<double>& s, SignalBoundary boundary,
                  const std::vector<unsigned char>* never_extremum, Extrema& out);

struct ExtremaCount {
  int maxima;
  int minima;
};
ExtremaCount count_extrema(const std::vector<double>& s, SignalBoundary boundary,
                           const std::vector<unsigned char>* never_extremum = nullptr);

}  // namespace hht
