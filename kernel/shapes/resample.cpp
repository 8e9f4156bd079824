// resample.cpp -- see resample.h.
#include "shapes/resample.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>

#include "shapes/validate_shape.h"

namespace grassfire {

namespace {

// C_0 .. C_n of the header.
std::vector<double> arc_length_prefix(const Ring& ring) {
  const std::vector<Point2>& p = ring.points;
  const std::size_t n = p.size();
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    prefix[i + 1] = prefix[i] + std::hypot(p[(i + 1) % n].x - p[i].x, p[(i + 1) % n].y - p[i].y);
  return prefix;
}

std::vector<Point2> sample_ring(const Ring& ring, std::size_t m) {
  const std::vector<Point2>& p = ring.points;
  const std::size_t n = p.size();
  const std::vector<double> prefix = arc_length_prefix(ring);
  const double length = prefix[n];
  std::vector<Point2> out;
  out.reserve(m);
  std::size_t i = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const double t = length * static_cast<double>(k) / static_cast<double>(m);
    while (i + 1 < n && prefix[i + 1] <= t) ++i;
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % n];
    // Only the last edge can be selected with C_i = C_{i+1} (an edge absorbed by rounding).
    const double edge = prefix[i + 1] - prefix[i];
    const double f = edge > 0.0 ? std::min(1.0, (t - prefix[i]) / edge) : 0.0;
    out.push_back({a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)});
  }
  return out;
}

void require_distinct(const Shape2& shape, const BoundarySamples& samples) {
  std::vector<std::tuple<double, double, std::size_t, std::size_t>> all;
  for (std::size_t r = 0; r < samples.size(); ++r)
    for (std::size_t k = 0; k < samples[r].size(); ++k) all.emplace_back(samples[r][k].x, samples[r][k].y, r, k);
  std::sort(all.begin(), all.end());
  for (std::size_t i = 1; i < all.size(); ++i) {
    const auto& [x0, y0, r0, k0] = all[i - 1];
    const auto& [x1, y1, r1, k1] = all[i];
    if (x0 != x1 || y0 != y1) continue;
    char where[96];
    std::snprintf(where, sizeof where, "(%.17g, %.17g)", x0, y0);
    throw std::runtime_error(shape.name + ": " + ring_label(r0) + ": sample " + std::to_string(k0) + " and " +
                             (r0 == r1 ? "" : ring_label(r1) + " ") + "sample " + std::to_string(k1) +
                             " coincide at " + where + " (spacing " +
                             std::to_string(ring_length(shape.rings[r0]) / static_cast<double>(samples[r0].size())) +
                             " is below the resolution of doubles here); use fewer samples");
  }
}

BoundarySamples sample_rings(const Shape2& shape, const std::vector<std::size_t>& counts) {
  BoundarySamples samples;
  for (std::size_t r = 0; r < shape.rings.size(); ++r) samples.push_back(sample_ring(shape.rings[r], counts[r]));
  require_distinct(shape, samples);
  return samples;
}

void require_shape(const Shape2& shape) {
  if (shape.rings.empty()) throw std::invalid_argument(shape.name + ": cannot resample a shape without rings");
}

// The counts of resample_by_count (see the header).
std::vector<std::size_t> counts_by_length(const std::vector<double>& lengths, std::size_t total) {
  const std::size_t rings = lengths.size();
  const double sum = std::accumulate(lengths.begin(), lengths.end(), 0.0);
  std::vector<double> share(rings);
  std::vector<std::size_t> m(rings);
  std::size_t assigned = 0;
  for (std::size_t r = 0; r < rings; ++r) {
    share[r] = static_cast<double>(total) * lengths[r] / sum;
    m[r] = std::max(kMinSamplesPerRing, static_cast<std::size_t>(std::floor(share[r])));
    assigned += m[r];
  }
  std::vector<std::size_t> order(rings);
  std::iota(order.begin(), order.end(), 0);
  auto deficit = [&](std::size_t r) { return share[r] - static_cast<double>(m[r]); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return deficit(a) > deficit(b); });
  for (std::size_t i = 0; assigned < total; i = (i + 1) % rings, ++assigned) ++m[order[i]];
  std::reverse(order.begin(), order.end());  // largest surplus first
  for (std::size_t i = 0; assigned > total; i = (i + 1) % rings)
    if (m[order[i]] > kMinSamplesPerRing) {
      --m[order[i]];
      --assigned;
    }
  return m;
}

}  // namespace

double ring_length(const Ring& ring) { return arc_length_prefix(ring).back(); }

BoundarySamples resample_by_count(const Shape2& shape, std::size_t total) {
  require_shape(shape);
  const std::size_t rings = shape.rings.size();
  if (total < kMinSamplesPerRing * rings || total > kMaxSamples)
    throw std::invalid_argument(shape.name + ": the number of samples must be between " +
                                std::to_string(kMinSamplesPerRing * rings) + " (8 per ring) and " +
                                std::to_string(kMaxSamples) + ", got " + std::to_string(total));
  std::vector<double> lengths;
  for (const Ring& r : shape.rings) lengths.push_back(ring_length(r));
  return sample_rings(shape, counts_by_length(lengths, total));
}

BoundarySamples resample_by_spacing(const Shape2& shape, double spacing) {
  require_shape(shape);
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument(shape.name + ": the sample spacing must be a positive finite number");
  std::vector<std::size_t> counts;
  double total = 0.0;
  for (const Ring& r : shape.rings) {
    const double m = std::max(static_cast<double>(kMinSamplesPerRing), std::ceil(ring_length(r) / spacing));
    total += m;
    if (total > static_cast<double>(kMaxSamples))
      throw std::invalid_argument(shape.name + ": spacing " + std::to_string(spacing) + " asks for more than " +
                                  std::to_string(kMaxSamples) + " samples");
    counts.push_back(static_cast<std::size_t>(m));
  }
  return sample_rings(shape, counts);
}

}  // namespace grassfire
