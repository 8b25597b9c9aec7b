// Saves the frequency distribution of the IMFs (the paper's Fig. 3) as a PNG plot and a CSV
// table: one curve / column per IMF, amplitude-weighted, over instantaneous frequency.
#pragma once

#include <QString>

#include <vector>

namespace hht_plugin {

// `histogram[k][b]`: IMF k (0 = finest), bin b of equal bins over [0, 0.5] cycles per sample.
// Writes <base>.png and <base>.csv (base = path without its extension); false with a message on error.
bool save_frequency_distribution(const std::vector<std::vector<double>>& histogram, const QString& path,
                                 QString& written, QString& error);

}  // namespace hht_plugin
