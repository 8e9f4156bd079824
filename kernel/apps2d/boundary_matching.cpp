// boundary_matching.cpp -- see boundary_matching.h.
#include "apps2d/boundary_matching.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "apps2d/axis_correspondence.h"
#include "burn2/boundary_eccentricity.h"
#include "burn2/closest_points.h"
#include "pipeline/edf2d.h"
#include "shapes/resample.h"

namespace grassfire {

BoundarySignature boundary_samples(const Shape2& shape, std::size_t samples) {
  if (shape.rings.empty()) throw std::invalid_argument("boundary_samples: the shape '" + shape.name + "' is empty");
  const Shape2 outer{shape.name, {shape.rings[0]}};
  BoundarySignature s;
  s.points = resample_by_count(outer, samples).front();
  return s;
}

std::vector<double> curvature_signature(const std::vector<Point2>& c) {
  const std::size_t n = c.size();
  if (n < 3) throw std::invalid_argument("curvature_signature: fewer than 3 points");
  std::vector<double> k(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 &p = c[(i + n - 1) % n], &q = c[i], &r = c[(i + 1) % n];
    const double ax = q.x - p.x, ay = q.y - p.y, bx = r.x - q.x, by = r.y - q.y;
    const double turn = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
    k[i] = turn / (0.5 * (std::hypot(ax, ay) + std::hypot(bx, by)));
  }
  return k;
}

std::vector<double> local_feature_size(const std::vector<Point2>& points, const MedialGraph& axis) {
  double extent = 0;
  for (const MedialEdge& e : axis.edges()) extent = std::max(extent, e.length.mid());
  const AxisLocator locator(axis, std::max(extent / 64, 1e-12));
  std::vector<double> lfs;
  lfs.reserve(points.size());
  for (const Point2& p : points) lfs.push_back(locator.nearest(p).distance);
  return lfs;
}

BoundarySignature eccentricity_signature(const Shape2& shape, std::size_t samples, std::size_t refine) {
  if (shape.rings.size() != 1)
    throw std::invalid_argument("eccentricity_signature: '" + shape.name +
                                "' has holes; boundary eccentricity is defined for simply connected shapes (3.5.3)");
  if (samples < kMinSamplesPerRing || refine < 1)
    throw std::invalid_argument("eccentricity_signature: at least 8 samples and refine >= 1 are needed");
  Edf2dOptions o;
  o.samples = samples * refine;
  const Edf2dResult r = compute_edf2d(shape, o);
  const AxisEccentricity e = distance_to_ema(*r.graph, *r.burning);
  const ClosestPoints cp = closest_points(*r.graph, &shape, &r.samples);
  const BoundaryEccentricity be = boundary_eccentricity(*r.graph, *r.burning, e, cp);
  BoundarySignature sig;
  std::vector<bool> known;
  for (std::size_t i = 0; i < samples; ++i) {
    sig.points.push_back(r.samples[0][i * refine]);
    const Interval v = be.value[0][i * refine];
    known.push_back(!v.is_infinite());
    sig.values.push_back(v.is_infinite() ? 0.0 : v.mid());
  }
  if (std::find(known.begin(), known.end(), true) == known.end())
    throw std::runtime_error("eccentricity_signature: no boundary sample of '" + shape.name + "' has a medial point");
  for (std::size_t i = 0; i < samples; ++i) {
    if (known[i]) continue;
    for (std::size_t d = 1;; ++d) {  // the nearest known sample, forwards first
      if (known[(i + d) % samples]) {
        sig.values[i] = sig.values[(i + d) % samples];
        break;
      }
      if (known[(i + samples - d) % samples]) {
        sig.values[i] = sig.values[(i + samples - d) % samples];
        break;
      }
    }
    ++sig.filled;
  }
  return sig;
}

std::vector<std::uint32_t> signature_maxima(const std::vector<double>& v, std::size_t window) {
  const std::size_t n = v.size();
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < n; ++i) {
    bool top = true;
    for (std::size_t d = 1; d <= window && d < n && top; ++d) {
      const double before = v[(i + n - d) % n], after = v[(i + d) % n];
      top = v[i] >= after && v[i] > before;  // a plateau counts once, at its first sample
    }
    if (top) out.push_back(static_cast<std::uint32_t>(i));
  }
  return out;
}

namespace {

std::vector<double> normalised(const std::vector<double>& v, bool normalise, const char* which) {
  if (v.empty()) throw std::invalid_argument(std::string("match_signatures: signature ") + which + " is empty");
  double mx = 0;
  for (double x : v) {
    if (!std::isfinite(x)) throw std::invalid_argument(std::string("match_signatures: signature ") + which +
                                                       " has a value that is not finite");
    mx = std::max(mx, std::abs(x));
  }
  if (!normalise) return v;
  if (!(mx > 0)) throw std::invalid_argument(std::string("match_signatures: signature ") + which +
                                             " is zero everywhere and cannot be normalised");
  std::vector<double> out(v);
  for (double& x : out) x /= mx;
  return out;
}

enum Step : std::uint8_t { kDiagonal, kAdvanceA, kAdvanceB };

// Best path for one offset: cost table over (i, j) with b indexed by (o + j) mod m.
BoundaryMatch best_path(const std::vector<double>& a, const std::vector<double>& b, std::uint32_t o, double stretch,
                        std::vector<double>& cost, std::vector<std::uint8_t>& from) {
  const std::size_t n = a.size(), m = b.size();
  auto at = [m](std::size_t i, std::size_t j) { return i * m + j; };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const double here = std::abs(a[i] - b[(o + j) % m]);
      if (i == 0 && j == 0) {
        cost[0] = here;
        continue;
      }
      // Ties prefer the diagonal, then advancing a (the order of the comparisons).
      double best = std::numeric_limits<double>::infinity();
      std::uint8_t step = kDiagonal;
      if (i > 0 && j > 0) best = cost[at(i - 1, j - 1)];
      if (i > 0 && cost[at(i - 1, j)] + stretch < best) best = cost[at(i - 1, j)] + stretch, step = kAdvanceA;
      if (j > 0 && cost[at(i, j - 1)] + stretch < best) best = cost[at(i, j - 1)] + stretch, step = kAdvanceB;
      cost[at(i, j)] = best + here;
      from[at(i, j)] = step;
    }
  BoundaryMatch r;
  r.offset = o;
  r.cost = cost[at(n - 1, m - 1)];
  std::size_t i = n - 1, j = m - 1;
  while (true) {
    r.path.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((o + j) % m)});
    if (i == 0 && j == 0) break;
    const std::uint8_t s = from[at(i, j)];
    r.stretch_steps += s != kDiagonal;
    if (s != kAdvanceB) --i;
    if (s != kAdvanceA) --j;
  }
  std::reverse(r.path.begin(), r.path.end());
  return r;
}

}  // namespace

BoundaryMatch match_signatures(const std::vector<double>& a_in, const std::vector<double>& b_in,
                               const MatchOptions& options) {
  const std::vector<double> a = normalised(a_in, options.normalise, "a"), b = normalised(b_in, options.normalise, "b");
  std::vector<double> cost(a.size() * b.size());
  std::vector<std::uint8_t> from(a.size() * b.size());
  BoundaryMatch best;
  best.cost = std::numeric_limits<double>::infinity();
  for (std::uint32_t o = 0; o < b.size(); ++o) {
    BoundaryMatch r = best_path(a, b, o, options.stretch, cost, from);
    if (r.cost < best.cost) best = std::move(r);  // strict: ties keep the smallest offset
  }
  return best;
}

namespace {

// The smallest cost over every monotone path from (i, j) to (n-1, m-1), by plain recursion
// (no table: the definition the DP is checked against; only costs and offsets compare).
double enumerate(const std::vector<double>& a, const std::vector<double>& b, std::uint32_t o, double stretch,
                 std::size_t i, std::size_t j) {
  const std::size_t n = a.size(), m = b.size();
  const double here = std::abs(a[i] - b[(o + j) % m]);
  if (i == n - 1 && j == m - 1) return here;
  double best = std::numeric_limits<double>::infinity();
  if (i + 1 < n && j + 1 < m) best = std::min(best, enumerate(a, b, o, stretch, i + 1, j + 1));
  if (i + 1 < n) best = std::min(best, stretch + enumerate(a, b, o, stretch, i + 1, j));
  if (j + 1 < m) best = std::min(best, stretch + enumerate(a, b, o, stretch, i, j + 1));
  return here + best;
}

}  // namespace

BoundaryMatch match_signatures_reference(const std::vector<double>& a_in, const std::vector<double>& b_in,
                                         const MatchOptions& options) {
  const std::vector<double> a = normalised(a_in, options.normalise, "a"), b = normalised(b_in, options.normalise, "b");
  if (a.size() > 8 || b.size() > 8) throw std::invalid_argument("match_signatures_reference: at most 8 samples each");
  BoundaryMatch best;
  best.cost = std::numeric_limits<double>::infinity();
  for (std::uint32_t o = 0; o < b.size(); ++o) {
    const double c = enumerate(a, b, o, options.stretch, 0, 0);
    if (c < best.cost) best.cost = c, best.offset = o;
  }
  return best;
}

std::vector<std::uint32_t> correspondence_of(const BoundaryMatch& m, std::size_t n) {
  std::vector<std::uint32_t> out(n, 0);
  std::vector<bool> seen(n, false);
  for (const auto& [i, j] : m.path)
    if (i < n && !seen[i]) out[i] = j, seen[i] = true;
  return out;
}

}  // namespace grassfire
