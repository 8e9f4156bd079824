// perturbation.cpp -- see perturbation.h.
#include "apps2d/perturbation.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps2d/alignment.h"
#include "shapes/validate_shape.h"

namespace grassfire {

namespace {

constexpr std::size_t kMaxPoints = 10000000;

// SplitMix64 (Steele, Lea, Flood 2014): one 64-bit draw per call, deterministic.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Uniform in [-1, 1] for point k of draw (seed, attempt).
double unit_noise(std::uint64_t seed, int attempt, std::uint64_t k) {
  const std::uint64_t h = splitmix64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(attempt)) ^ k);
  return 2.0 * (static_cast<double>(h >> 11) * 0x1.0p-53) - 1.0;
}

Point2 unit_normal(const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  return {dy / len, -dx / len};  // right of a->b: outward for a counter-clockwise ring
}

struct Densified {
  std::vector<Point2> points, normals;
};

Densified densify(const Ring& r, double spacing) {
  Densified d;
  const std::size_t n = r.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 &prev = r.points[(i + n - 1) % n], &p = r.points[i], &q = r.points[(i + 1) % n];
    const Point2 n0 = unit_normal(prev, p), n1 = unit_normal(p, q);
    const double sx = n0.x + n1.x, sy = n0.y + n1.y, s = std::hypot(sx, sy);
    // s = 0 only for a spike turning back by 180 degrees, which validation rejects.
    d.points.push_back(p);
    d.normals.push_back(s > 0 ? Point2{sx / s, sy / s} : n1);
    const auto k = static_cast<std::size_t>(std::ceil(std::hypot(q.x - p.x, q.y - p.y) / spacing));
    for (std::size_t j = 1; j < k; ++j) {
      const double t = static_cast<double>(j) / static_cast<double>(k);
      d.points.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
      d.normals.push_back(n1);
    }
    if (d.points.size() > kMaxPoints) throw std::invalid_argument("perturb_boundary: more than 10^7 points");
  }
  return d;
}

double round_to(double x, double scale) { return std::round(x * scale) / scale; }

}  // namespace

const char* to_string(PerturbationKind k) { return k == PerturbationKind::Uniform ? "uniform" : "one-sided"; }

PerturbedShape perturb_boundary(const Shape2& shape, const PerturbationOptions& o) {
  const double rounding = std::pow(10.0, -o.decimal_digits), scale = std::pow(10.0, o.decimal_digits);
  if (!(o.amplitude > 2 * rounding) || !std::isfinite(o.amplitude))
    throw std::invalid_argument("perturb_boundary: the amplitude must be finite and above 2 * 10^-digits");
  if (!(o.spacing > 0) || !std::isfinite(o.spacing))
    throw std::invalid_argument("perturb_boundary: the spacing must be positive and finite");
  if (o.decimal_digits < 0 || o.decimal_digits > 9 || o.max_attempts < 1)
    throw std::invalid_argument("perturb_boundary: decimal_digits must be in [0, 9] and max_attempts >= 1");
  std::vector<Densified> rings;
  for (const Ring& r : shape.rings) rings.push_back(densify(r, o.spacing));
  const Point2 c = bounding_box_centre(shape);
  const double noise = o.amplitude - rounding;
  for (int attempt = 0; attempt < o.max_attempts; ++attempt) {
    PerturbedShape out;
    out.shape.name = shape.name + " (" + to_string(o.kind) + " perturbation)";
    std::uint64_t k = 0;
    for (const Densified& d : rings) {
      Ring r;
      for (std::size_t i = 0; i < d.points.size(); ++i, ++k) {
        const Point2& p = d.points[i];
        const bool moved =
            o.kind == PerturbationKind::Uniform || (p.x - c.x) * o.direction.x + (p.y - c.y) * o.direction.y > 0;
        const double u = moved ? noise * unit_noise(o.seed, attempt, k) : 0.0;
        r.points.push_back({round_to(p.x + u * d.normals[i].x, scale), round_to(p.y + u * d.normals[i].y, scale)});
        out.perturbed_points += moved;
      }
      out.points += d.points.size();
      out.shape.rings.push_back(std::move(r));
    }
    try {
      validate_shape(out.shape, out.shape.name);
    } catch (const InvalidShapeError&) {
      continue;  // the noise folded the boundary: draw again (perturbation.h, step 4)
    }
    out.attempts = attempt + 1;
    return out;
  }
  throw std::runtime_error(shape.name + ": no valid perturbation of amplitude " + std::to_string(o.amplitude) +
                           " with seed " + std::to_string(o.seed) + " in " + std::to_string(o.max_attempts) +
                           " attempts");
}

}  // namespace grassfire
