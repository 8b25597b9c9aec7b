// Parameters shared by the HHT filters (cycle seed and EMD stopping rules): declared once
// with the same names, defaults, ranges and help everywhere.
#pragma once

#include "signal/emd.h"
#include "cycle/hamiltonian_cycle.h"

#include "meshlab_api.h"

namespace hht_plugin {

// The ranges the EMD parameters are checked against: the caps bound the work (sifts per IMF,
// IMFs), the SD threshold's range holds every value the EMD literature uses.
constexpr double kMinSdThreshold = 1e-6, kMaxSdThreshold = 1;
constexpr int kMaxSiftsCap = 1000, kMaxExtremaCap = 1000, kMaxImfsCap = 100;
// The Laplacian rebuild's lambda, in mean edge lengths: below, the solve loses its hold on the
// positions (lambda 1e-12 moved Fandisk's vertices by 1e5); above, it gives the input back.
constexpr double kMinLambda = 1e-4, kMaxLambda = 1e4;

// Help text prefix of the parameters only an expert should change.
inline QString expert(const QString& help) { return "For experts. " + help; }

void declare_cycle_and_emd_parameters(RichParameterList& p);  // the cycle's seed, then the EMD's
void declare_emd_parameters(RichParameterList& p);
hht::CycleOptions cycle_options(const RichParameterList& p);
hht::EmdOptions emd_options(const RichParameterList& p);
// Refuses EMD parameters outside their ranges, with a message naming the parameter.
bool check_emd_parameters(const RichParameterList& p, QString& error);
bool check_lambda(double lambda, QString& error);

}  // namespace hht_plugin
