#include "surface_emd_parameters.h"

namespace hht_plugin {

void declare_surface_emd_parameters(RichParameterList& p) {
  const hht::SurfaceEmdSmoothingOptions d;
  p.addParam(RichInt("residue", d.residue, "Rebuild from residue k",
                     "The mesh is rebuilt from the k-th residue: the curvature signal minus its k finest IMFs (the "
                     "paper's Figs. 9 and 10 use 3); the final residue when there are fewer IMFs."));
  p.addParam(RichFloat("sdThreshold", float(d.emd.sd_threshold), "Sifting threshold (SD)",
                       "Sifting of an IMF stops when SD = sum (s_prev - s)^2 / sum s_prev^2 falls below this "
                       "(the paper's 0.1)."));
  p.addParam(RichInt("maxSifts", d.emd.max_sifts, "Max sifts per IMF", "Cap on the sifting iterations of one IMF."));
  p.addParam(RichInt("minExtrema", d.emd.min_extrema, "Stop below this many extrema",
                     "The decomposition stops when the residue has fewer maxima or fewer minima than this "
                     "(the paper's 15)."));
  p.addParam(RichInt("maxImfs", d.emd.max_imfs, "Max IMFs", "Cap on the number of IMFs; 0 = no cap."));
  p.addParam(RichFloat("lambda", float(d.reconstruction.lambda), "Position weight (lambda)",
                       "Weight of the original positions in the least-squares rebuild, relative to the mean edge "
                       "length (as in HHT: Spectral Filter)."));
}

bool surface_emd_smoothing_options(const RichParameterList& p, hht::SurfaceEmdSmoothingOptions& o, QString& error) {
  o.residue = p.getInt("residue");
  o.emd.sd_threshold = p.getFloat("sdThreshold");
  o.emd.max_sifts = p.getInt("maxSifts");
  o.emd.min_extrema = p.getInt("minExtrema");
  o.emd.max_imfs = p.getInt("maxImfs");
  o.reconstruction.lambda = p.getFloat("lambda");
  if (o.residue < 0 || !(o.emd.sd_threshold > 0) || o.emd.max_sifts < 1 || o.emd.min_extrema < 1 ||
      o.emd.max_imfs < 0 || !(o.reconstruction.lambda > 0)) {
    error = "Nothing was changed: residue and max IMFs must be at least 0, max sifts and min extrema at least 1, "
            "the SD threshold and lambda positive.";
    return false;
  }
  return true;
}

}  // namespace hht_plugin
