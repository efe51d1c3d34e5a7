// SPDX-License-Identifier: MIT
#include "xfem/generate/image_smoothing.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "xfem/core/error.h"

namespace xfem {
namespace {

std::vector<double> gaussian(double sigma) {
  const int r = std::max(1, static_cast<int>(std::ceil(3 * sigma)));
  std::vector<double> k(static_cast<std::size_t>(2 * r + 1));
  double sum = 0;
  for (int i = -r; i <= r; ++i) sum += k[static_cast<std::size_t>(i + r)] = std::exp(-0.5 * i * i / (sigma * sigma));
  for (double& v : k) v /= sum;
  return k;
}

// Blurs `f` along axis `a` with kernel `k` (its middle at the voxel), clamping at the edges.
void blur_axis(std::vector<float>& f, const std::array<std::int64_t, 3>& d, int a, const std::vector<double>& k) {
  const std::int64_t stride = a == 0 ? 1 : a == 1 ? d[0] : d[0] * d[1];
  const std::int64_t n = d[a], r = static_cast<std::int64_t>(k.size() / 2);
  const std::int64_t lines = d[0] * d[1] * d[2] / n;
  std::vector<float> line(static_cast<std::size_t>(n));
  for (std::int64_t l = 0; l < lines; ++l) {
    // The first voxel of line l: every index whose coordinate along a is 0.
    std::int64_t start;
    if (a == 0)
      start = l * d[0];
    else if (a == 1)
      start = (l / d[0]) * d[0] * d[1] + l % d[0];
    else
      start = l;
    for (std::int64_t i = 0; i < n; ++i) line[static_cast<std::size_t>(i)] = f[static_cast<std::size_t>(start + i * stride)];
    for (std::int64_t i = 0; i < n; ++i) {
      double s = 0;
      for (std::int64_t j = -r; j <= r; ++j)
        s += k[static_cast<std::size_t>(j + r)] * line[static_cast<std::size_t>(std::clamp(i + j, std::int64_t{0}, n - 1))];
      f[static_cast<std::size_t>(start + i * stride)] = static_cast<float>(s);
    }
  }
}

}  // namespace

std::vector<std::uint8_t> label_weights(const std::vector<std::int32_t>& labels, const std::array<std::int64_t, 3>& dims,
                                        const std::array<double, 3>& sigma) {
  for (double s : sigma)
    if (!(std::isfinite(s) && s > 0 && s <= 20))
      throw Error("smoothing: a Gaussian of " + short_number(s) + " voxels (must be positive, at most 20)");
  const std::set<std::int32_t> present(labels.begin(), labels.end());
  std::vector<std::uint8_t> weights(labels.size(), 0);
  std::vector<float> f(labels.size());
  for (std::int32_t label : present) {
    for (std::size_t i = 0; i < labels.size(); ++i) f[i] = labels[i] == label ? 255.0f : 0.0f;
    for (int a = 0; a < 3; ++a) blur_axis(f, dims, a, gaussian(sigma[static_cast<std::size_t>(a)]));
    for (std::size_t i = 0; i < labels.size(); ++i)
      weights[i] = std::max(weights[i], static_cast<std::uint8_t>(std::clamp(std::lround(f[i]), 0L, 255L)));
  }
  return weights;
}

}  // namespace xfem
