#include "surface_emd_parameters.h"

#include "hht_parameters.h"
#include "mesh_adapter.h"

namespace hht_plugin {

void declare_surface_emd_parameters(RichParameterList& p) {
  const hht::SurfaceEmdSmoothingOptions d;
  p.addParam(RichInt("residue", d.residue, "Rebuild from residue k",
                     QString("The mesh is rebuilt from the k-th residue: the curvature signal minus its k finest IMFs "
                             "(the paper's Figs. 9 and 10 use 3); the final residue when there are fewer IMFs (0 to "
                             "%1).").arg(kMaxImfsCap)));
  p.addParam(RichFloat("lambda", float(d.reconstruction.lambda), "Position weight (lambda)",
                       "Weight of the original positions in the least-squares rebuild, relative to the mean edge "
                       "length (as in HHT: Spectral Filter; 0.0001 to 10000)."));
}

bool surface_emd_smoothing_options(const RichParameterList& p, hht::SurfaceEmdSmoothingOptions& o, QString& error) {
  o.residue = p.getInt("residue");
  o.emd.sd_threshold = p.getFloat("sdThreshold");
  o.emd.max_sifts = p.getInt("maxSifts");
  o.emd.min_extrema = p.getInt("minExtrema");
  o.emd.max_imfs = p.getInt("maxImfs");
  o.reconstruction.lambda = p.getFloat("lambda");
  return check_range("residue", o.residue, 0, kMaxImfsCap, error) && check_emd_parameters(p, error) &&
         check_lambda(o.reconstruction.lambda, error);
}

}  // namespace hht_plugin
