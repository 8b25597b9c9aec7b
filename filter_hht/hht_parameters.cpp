#include "hht_parameters.h"

#include "mesh_adapter.h"

namespace hht_plugin {

void declare_cycle_and_emd_parameters(RichParameterList& p) {
  p.addParam(RichInt("seed", 0, "Cycle seed",
                     expert("Seed of the Hamiltonian cycle that orders the vertices into a 1D signal (0: first face; "
                            "any integer). Different seeds give different, equally valid cycles.")));
  declare_emd_parameters(p);
}

void declare_emd_parameters(RichParameterList& p) {
  const hht::EmdOptions d;
  p.addParam(RichFloat("sdThreshold", float(d.sd_threshold), "Sifting threshold (SD)",
                       expert(QString("Sifting of an IMF stops when SD = sum (s_prev - s)^2 / sum s_prev^2 falls below "
                                      "this (the paper's 0.1; %1 to %2). Smaller: more sifts, narrower-band IMFs.")
                                  .arg(kMinSdThreshold).arg(kMaxSdThreshold))));
  p.addParam(RichInt("maxSifts", d.max_sifts, "Max sifts per IMF",
                     expert(QString("Cap on the sifting iterations of one IMF (1 to %1).").arg(kMaxSiftsCap))));
  p.addParam(RichInt("minExtrema", d.min_extrema, "Stop below this many extrema",
                     expert(QString("The decomposition stops when the residue has fewer maxima or fewer minima than "
                                    "this (the paper's 15; 1 to %1).").arg(kMaxExtremaCap))));
  p.addParam(RichInt("maxImfs", d.max_imfs, "Max IMFs",
                     expert(QString("Cap on the number of IMFs; 0 = no cap (the paper's default; 0 to %1).")
                                .arg(kMaxImfsCap))));
}

hht::CycleOptions cycle_options(const RichParameterList& p) {
  hht::CycleOptions o;
  o.seed = p.getInt("seed");
  return o;
}

hht::EmdOptions emd_options(const RichParameterList& p) {
  hht::EmdOptions o;
  o.sd_threshold = p.getFloat("sdThreshold");
  o.max_sifts = p.getInt("maxSifts");
  o.min_extrema = p.getInt("minExtrema");
  o.max_imfs = p.getInt("maxImfs");
  return o;
}

bool check_emd_parameters(const RichParameterList& p, QString& error) {
  return check_range("the sifting threshold sdThreshold", p.getFloat("sdThreshold"), kMinSdThreshold, kMaxSdThreshold,
                     error) &&
         check_range("maxSifts", p.getInt("maxSifts"), 1, kMaxSiftsCap, error, " (it bounds the work per IMF)") &&
         check_range("minExtrema", p.getInt("minExtrema"), 1, kMaxExtremaCap, error) &&
         check_range("maxImfs", p.getInt("maxImfs"), 0, kMaxImfsCap, error);
}

bool check_lambda(double lambda, QString& error) {
  return check_range("lambda", lambda, kMinLambda, kMaxLambda, error,
                     " mean edge lengths (smaller leaves the solve without a hold on the positions)");
}

}  // namespace hht_plugin
