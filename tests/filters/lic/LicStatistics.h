#pragma once
// Statistics of LIC images used as acceptance measures: Pearson correlation of pixel pairs and
// difference percentiles.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "filters/lic/LineIntegralConvolution.h"

namespace fluidviz::testing {

struct PairSums {
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  long n = 0;
  void add(double a, double b) {
    sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b, ++n;
  }
  double correlation() const {
    const double ma = sa / n, mb = sb / n;
    const double cov = sab / n - ma * mb;
    return cov / std::sqrt((saa / n - ma * ma) * (sbb / n - mb * mb));
  }
};

inline double pixel(const lic::LicImage& img, int i, int j) {
  return img.texture.values[static_cast<std::size_t>(j) * img.width() + i];
}

/// Correlation between pixel (i, j) and pixel (i + di, j + dj) over the pixels with
/// margin <= i, i + di < width - margin (same for j).
inline double offsetCorrelation(const lic::LicImage& img, int di, int dj, int margin) {
  PairSums s;
  for (int j = margin; j < img.height() - margin; ++j)
    for (int i = margin; i < img.width() - margin; ++i) {
      const int i2 = i + di, j2 = j + dj;
      if (i2 < margin || j2 < margin || i2 >= img.width() - margin || j2 >= img.height() - margin)
        continue;
      s.add(pixel(img, i, j), pixel(img, i2, j2));
    }
  return s.correlation();
}

struct Differences {
  double meanAbs = 0, p99 = 0, max = 0;
};
inline Differences differences(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t p = 0; p < a.size(); ++p) d[p] = std::abs(a[p] - b[p]);
  Differences r;
  for (double x : d) r.meanAbs += x;
  r.meanAbs /= d.size();
  std::sort(d.begin(), d.end());
  r.p99 = d[static_cast<std::size_t>(0.99 * (d.size() - 1))];
  r.max = d.back();
  return r;
}

inline double standardDeviation(const std::vector<double>& a) {
  double s = 0, s2 = 0;
  for (double x : a) s += x, s2 += x * x;
  const double m = s / a.size();
  return std::sqrt(std::max(0.0, s2 / a.size() - m * m));
}

}  // namespace fluidviz::testing
