// What each filter of the plugin declares: its name, description, menu class, parameters
// and the function that applies it, in terms that hold for either MeshLab (meshlab_api.h).
// The plugin class (meshlab2020/ or meshlab2022/) only dispatches over these.
#pragma once

#include "meshlab_api.h"

#include <functional>
#include <vector>

namespace hht_plugin {

struct FilterRun {
  MeshDocument& document;
  const RichParameterList& parameters;
  vcg::CallBackPos* progress;
  std::function<void(const QString&)> log;
  QString& error;  // set before returning false; the mesh must then be as it was

  void report(int percent, const char* stage) const {
    if (progress) progress(percent, stage);
  }
};

struct FilterSpec {
  QString name;
  QString info;
  MeshLabFilter::FilterClass menu_class;
  FilterArity arity;
  int post_condition;  // MeshModel::MM_* bits the filter changes
  std::function<void(const MeshDocument&, RichParameterList&)> declare_parameters;
  std::function<bool(FilterRun&)> apply;
};

// Every filter of the plugin, in menu order (filter_spec.cpp).
std::vector<FilterSpec> all_filters();

// One per filter, each in its own file.
FilterSpec hamiltonian_cycle_filter();
FilterSpec curvature_signal_filter();
FilterSpec hilbert_spectra_filter();
FilterSpec spectral_filter_filter();
FilterSpec add_noise_filter();
FilterSpec denoise_filter();
FilterSpec compare_filter();
FilterSpec bilateral_filter();
FilterSpec adaptive_smooth_filter();
FilterSpec guided_denoise_filter();
FilterSpec surface_emd_filter();
FilterSpec feature_centric_emd_filter();
FilterSpec nonlocal_means_filter();

}  // namespace hht_plugin
