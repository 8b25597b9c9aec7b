#include "frequency_plot.h"

#include <QColor>
#include <QFile>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QTextStream>

#include <algorithm>

namespace hht_plugin {

namespace {

QString base_of(const QString& path) {
  const QFileInfo info(path);
  return info.dir().filePath(info.completeBaseName());
}

bool write_csv(const std::vector<std::vector<double>>& h, const QString& file, QString& error) {
  QFile out(file);
  if (!out.open(QIODevice::WriteOnly | QIODevice::Text)) {
    error = "cannot write " + file;
    return false;
  }
  QTextStream s(&out);
  const size_t bins = h.empty() ? 0 : h[0].size();
  s << "frequency_low,frequency_high";
  for (size_t k = 0; k < h.size(); ++k) s << ",imf" << (k + 1);
  s << "\n";
  for (size_t b = 0; b < bins; ++b) {
    s << QString::number(0.5 * b / bins, 'g', 8) << "," << QString::number(0.5 * (b + 1) / bins, 'g', 8);
    for (const auto& imf : h) s << "," << QString::number(imf[b], 'g', 10);
    s << "\n";
  }
  return true;
}

bool write_png(const std::vector<std::vector<double>>& h, const QString& file, QString& error) {
  const int width = 900, height = 500, left = 70, right = 150, top = 40, bottom = 50;
  QImage image(width, height, QImage::Format_RGB32);
  image.fill(Qt::white);
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  const int pw = width - left - right, ph = height - top - bottom;
  p.setPen(Qt::black);
  p.drawRect(left, top, pw, ph);
  p.drawText(QRect(0, 5, width, 30), Qt::AlignCenter, "Frequency distribution of the IMFs (amplitude-weighted)");
  p.drawText(QRect(left, height - 25, pw, 20), Qt::AlignCenter, "instantaneous frequency (cycles per sample)");
  for (int t = 0; t <= 5; ++t) {
    const int x = left + pw * t / 5;
    p.drawLine(x, top + ph, x, top + ph + 5);
    p.drawText(QRect(x - 30, top + ph + 6, 60, 15), Qt::AlignCenter, QString::number(0.1 * t, 'f', 1));
  }
  p.save();
  p.translate(20, top + ph / 2);
  p.rotate(-90);
  p.drawText(QRect(-ph / 2, -10, ph, 20), Qt::AlignCenter, "share of the IMF's amplitude");
  p.restore();
  double peak = 0;  // each IMF normalised to unit sum, all on one vertical scale
  std::vector<std::vector<double>> shares;
  for (const auto& imf : h) {
    double sum = 0;
    for (double x : imf) sum += x;
    std::vector<double> share(imf.size(), 0.0);
    for (size_t b = 0; b < imf.size(); ++b) share[b] = sum > 0 ? imf[b] / sum : 0.0;
    for (double x : share) peak = std::max(peak, x);
    shares.push_back(std::move(share));
  }
  for (size_t k = 0; k < shares.size(); ++k) {
    const QColor colour = QColor::fromHsv(static_cast<int>(300.0 * k / std::max<size_t>(1, shares.size() - 1)), 220, 200);
    p.setPen(QPen(colour, 2));
    const size_t bins = shares[k].size();
    QPointF last;
    for (size_t b = 0; b < bins; ++b) {
      const QPointF point(left + pw * (b + 0.5) / bins, top + ph - (peak > 0 ? ph * shares[k][b] / peak : 0));
      if (b > 0) p.drawLine(last, point);
      last = point;
    }
    p.drawLine(width - right + 15, top + 20 * static_cast<int>(k) + 10, width - right + 40, top + 20 * static_cast<int>(k) + 10);
    p.setPen(Qt::black);
    p.drawText(width - right + 45, top + 20 * static_cast<int>(k) + 15, QString("IMF %1").arg(k + 1));
  }
  p.end();
  if (!image.save(file, "PNG")) {
    error = "cannot write " + file;
    return false;
  }
  return true;
}

}  // namespace

bool save_frequency_distribution(const std::vector<std::vector<double>>& histogram, const QString& path,
                                 QString& written, QString& error) {
  const QString base = base_of(path);
  if (!write_csv(histogram, base + ".csv", error) || !write_png(histogram, base + ".png", error)) return false;
  written = base + ".png and " + base + ".csv";
  return true;
}

}  // namespace hht_plugin
