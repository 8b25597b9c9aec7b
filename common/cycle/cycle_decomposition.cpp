#include "cycle/cycle_decomposition.h"

#include <algorithm>
#include <map>
#include <memory>

namespace hht {

int CycleDecomposition::imf_count() const {
  size_t most = 0;
  for (const auto& e : emd) most = std::max(most, e.imfs.size());
  return static_cast<int>(most);
}

bool decompose_along_cycle(const HamiltonianCycle& cycle, const Eigen::VectorXd& signal, const EmdOptions& options,
                           CycleDecomposition& out, std::string& error) {
  if (!signal.allFinite()) {
    error = "the signal has NaN or infinite values";
    return false;
  }
  out = CycleDecomposition{};
  for (const auto& s : signals_along_cycle(cycle, signal)) out.emd.push_back(emd(s, options));
  return true;
}

void compute_spectra(CycleDecomposition& d) {
  std::map<size_t, std::unique_ptr<HilbertTransformer>> transformers;  // one per segment length
  d.spectra.clear();
  for (const auto& e : d.emd) {
    std::vector<HilbertSpectrum> spectra;
    if (!e.imfs.empty()) {
      auto& t = transformers[e.residue.size()];
      if (!t) t = std::make_unique<HilbertTransformer>(static_cast<int>(e.residue.size()));
      for (const auto& imf : e.imfs) spectra.push_back(t->spectrum(imf, SignalBoundary::Periodic));
    }
    d.spectra.push_back(std::move(spectra));
  }
}

std::vector<ImfSummary> summarize_imfs(const CycleDecomposition& d) {
  std::vector<ImfSummary> out(d.imf_count());
  std::vector<double> weight(out.size(), 0.0);
  double total = 0;
  for (size_t s = 0; s < d.emd.size(); ++s) {
    const auto& e = d.emd[s];
    total += energy(e.residue);
    for (size_t k = 0; k < e.imfs.size(); ++k) {
      const double ek = energy(e.imfs[k]);
      total += ek;
      out[k].energy_share += ek;
      out[k].sifts += e.sifts[k];
      if (s < d.spectra.size() && k < d.spectra[s].size()) {
        double a = 0;
        for (double x : d.spectra[s][k].amplitude) a += x;
        out[k].mean_frequency += a * mean_frequency(d.spectra[s][k]);
        weight[k] += a;
      }
    }
  }
  for (size_t k = 0; k < out.size(); ++k) {
    out[k].energy_share = total > 0 ? out[k].energy_share / total : 0.0;
    out[k].mean_frequency = weight[k] > 0 ? out[k].mean_frequency / weight[k] : 0.0;
  }
  return out;
}

std::vector<std::vector<double>> frequency_distribution(const CycleDecomposition& d, int bins) {
  std::vector<std::vector<double>> total(d.imf_count(), std::vector<double>(std::max(1, bins), 0.0));
  for (const auto& spectra : d.spectra) {
    const auto h = frequency_histogram(spectra, std::max(1, bins));
    for (size_t k = 0; k < h.size(); ++k)
      for (size_t b = 0; b < h[k].size(); ++b) total[k][b] += h[k][b];
  }
  return total;
}

Eigen::VectorXd quantity_on_vertices(const HamiltonianCycle& cycle, const CycleDecomposition& d, CycleQuantity what,
                                     int imf, const Faces& faces) {
  std::vector<std::vector<double>> per_segment;
  for (size_t s = 0; s < d.emd.size(); ++s) {
    const auto& e = d.emd[s];
    const bool has = imf >= 0 && imf < static_cast<int>(e.imfs.size());
    switch (what) {
      case CycleQuantity::Residue: per_segment.push_back(e.residue); break;
      case CycleQuantity::Imf: per_segment.push_back(has ? e.imfs[imf] : std::vector<double>(e.residue.size(), 0.0)); break;
      default: {
        if (!has || s >= d.spectra.size()) {
          per_segment.emplace_back(e.residue.size(), 0.0);
          break;
        }
        const HilbertSpectrum& h = d.spectra[s][imf];
        per_segment.push_back(what == CycleQuantity::Amplitude ? h.amplitude
                              : what == CycleQuantity::Frequency ? h.frequency
                                                                 : h.phase);
      }
    }
  }
  return values_on_vertices(cycle, per_segment, faces, Eigen::VectorXd::Zero(cycle.position.size()));
}

namespace {

// Vertices off the cycle take the one-ring mean of the change, not of the values, so that an
// unchanged signal stays unchanged everywhere.
Eigen::VectorXd apply_change(const HamiltonianCycle& cycle, std::vector<std::vector<double>> modified,
                             const Faces& faces, const Eigen::VectorXd& signal) {
  const auto original = signals_along_cycle(cycle, signal);
  for (size_t s = 0; s < modified.size(); ++s)
    for (size_t j = 0; j < modified[s].size(); ++j) modified[s][j] -= original[s][j];
  return signal + values_on_vertices(cycle, modified, faces, Eigen::VectorXd::Zero(signal.size()));
}

}  // namespace

Eigen::VectorXd filtered_on_vertices(const HamiltonianCycle& cycle, const CycleDecomposition& d,
                                     const FrequencyBand& band, double gain, const Faces& faces,
                                     const Eigen::VectorXd& signal) {
  std::vector<std::vector<double>> per_segment;
  for (size_t s = 0; s < d.emd.size(); ++s) per_segment.push_back(filter_by_frequency(d.emd[s], d.spectra[s], band, gain));
  return apply_change(cycle, std::move(per_segment), faces, signal);
}

Eigen::VectorXd coarsest_on_vertices(const HamiltonianCycle& cycle, const CycleDecomposition& d, int k,
                                     const Faces& faces, const Eigen::VectorXd& signal) {
  std::vector<std::vector<double>> per_segment;
  for (const auto& e : d.emd) per_segment.push_back(keep_coarsest(e, k));
  return apply_change(cycle, std::move(per_segment), faces, signal);
}

}  // namespace hht
