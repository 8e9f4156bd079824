// adversarial_polygons.cpp -- see adversarial_polygons.h.
#include "shapes/adversarial_polygons.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace grassfire {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInt32 = 2147483647.0;

using Rng = std::mt19937_64;

long long uniform(Rng& rng, long long lo, long long hi) { return std::uniform_int_distribution<long long>(lo, hi)(rng); }
double real(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

Shape2 boost43(Rng& rng) {
  const double t = static_cast<double>(uniform(rng, -4, 4));
  std::vector<Point2> p = {{0, 1e7}, {7e5, t}, {7e5, 9e6}, {9.1e6, 9e6}, {9.1e6, 0}, {1e7, 1e7}};
  const int s = static_cast<int>(uniform(rng, -7, 2));
  const bool mirror = uniform(rng, 0, 1) == 1;
  const int turns = static_cast<int>(uniform(rng, 0, 3));
  const long long dx = uniform(rng, -1000, 1000) * (uniform(rng, 0, 1) ? 1 : 0);
  const long long dy = uniform(rng, -1000, 1000) * (uniform(rng, 0, 1) ? 1 : 0);
  for (Point2& q : p) {
    double x = q.x + static_cast<double>(dx), y = q.y + static_cast<double>(dy);
    if (mirror) x = -x;
    for (int k = 0; k < turns; ++k) {
      const double tmp = x;
      x = -y;
      y = tmp;
    }
    // Scale by 10^s through the decimal text, so that 10^-7 scales give the doubles nearest
    // to the decimals a file would hold.
    const double scale = std::pow(10.0, s);
    q = s >= 0 ? Point2{x * scale, y * scale} : Point2{x / std::pow(10.0, -s), y / std::pow(10.0, -s)};
  }
  return {"", {Ring{p}}};
}

Shape2 near_collinear(Rng& rng) {
  const int n = static_cast<int>(uniform(rng, 3, 60));
  const long long step = uniform(rng, 1, 1000000);
  const long long width = uniform(rng, 1, 8);
  std::vector<Point2> p;
  for (int i = 0; i <= n; ++i) p.push_back({static_cast<double>(i * step), static_cast<double>(uniform(rng, 0, 1))});
  for (int i = n; i >= 0; --i)
    p.push_back({static_cast<double>(i * step), static_cast<double>(width + 1 + uniform(rng, 0, 1))});
  return {"", {Ring{p}}};
}

Shape2 near_cocircular(Rng& rng) {
  const double radius = std::pow(10.0, real(rng, 2, 9));
  const int n = static_cast<int>(uniform(rng, 4, 80));
  std::vector<double> angle;
  for (int i = 0; i < n; ++i) angle.push_back(real(rng, 0, 2 * kPi));
  std::sort(angle.begin(), angle.end());
  Ring outer;
  for (double a : angle) outer.points.push_back({std::round(radius * std::cos(a)), std::round(radius * std::sin(a))});
  Shape2 s{"", {outer}};
  if (uniform(rng, 0, 2) == 0) {
    const double h = std::round(radius / real(rng, 4, 40));
    s.rings.push_back(Ring{{{-h, -h}, {h, -h}, {0, h}}});
  }
  return s;
}

Shape2 int32_limit(Rng& rng) {
  const double big = kInt32 - static_cast<double>(uniform(rng, 0, 3));
  const double lo = -big, hi = big;
  std::vector<Point2> p;
  // Bottom side from left to right with notches, then the other three corners.
  p.push_back({lo, lo});
  const int notches = static_cast<int>(uniform(rng, 0, 6));
  std::vector<double> at;
  for (int i = 0; i < notches; ++i) at.push_back(std::round(real(rng, lo + 10, hi - 10)));
  std::sort(at.begin(), at.end());
  double last = lo;
  for (double x : at) {
    if (x <= last + 4) continue;
    const double w = static_cast<double>(uniform(rng, 1, 3)), d = static_cast<double>(uniform(rng, 1, 3));
    p.push_back({x, lo});
    p.push_back({x, lo + d});
    p.push_back({x + w, lo + d});
    p.push_back({x + w, lo});
    last = x + w;
  }
  p.push_back({hi, lo});
  p.push_back({hi, hi});
  if (uniform(rng, 0, 1)) p.push_back({hi - 1, hi});  // an edge of length 1 at the limit
  p.push_back({lo + static_cast<double>(uniform(rng, 0, 2)), hi});
  return {"", {Ring{p}}};
}

Shape2 spikes(Rng& rng) {
  const int n = static_cast<int>(uniform(rng, 3, 40));
  const double inner = std::pow(10.0, real(rng, 1, 4)), outer = inner * std::pow(10.0, real(rng, 1, 4));
  std::vector<Point2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n, b = a + kPi / n;
    p.push_back({std::round(inner * std::cos(a)), std::round(inner * std::sin(a))});
    const double tx = std::round(outer * std::cos(b)), ty = std::round(outer * std::sin(b));
    p.push_back({tx, ty});
    // Two thirds of the tips are one unit wide: the second corner one step further
    // counter-clockwise (along the circle's tangent, rounded to the integer grid).
    if (uniform(rng, 0, 2) != 0) p.push_back({tx + std::round(-std::sin(b)), ty + std::round(std::cos(b))});
  }
  return {"", {Ring{p}}};
}

Shape2 random_star(Rng& rng) {
  const int n = static_cast<int>(uniform(rng, 3, 200));
  const double scale = std::pow(10.0, real(rng, 1, 9));
  std::vector<double> angle;
  for (int i = 0; i < n; ++i) angle.push_back(real(rng, 0, 2 * kPi));
  std::sort(angle.begin(), angle.end());
  Ring r;
  for (double a : angle) {
    const double rad = scale * real(rng, 0.05, 1.0);
    r.points.push_back({std::round(rad * std::cos(a)), std::round(rad * std::sin(a))});
  }
  return {"", {r}};
}

}  // namespace

const std::vector<std::string>& adversarial_polygon_kinds() {
  static const std::vector<std::string> kinds = {"boost43", "near-collinear", "near-cocircular",
                                                 "int32-limit", "spikes", "random-star"};
  return kinds;
}

Shape2 adversarial_polygon(const std::string& kind, std::uint64_t seed) {
  std::uint64_t h = 1469598103934665603ull;
  for (char c : kind) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  Rng rng(h ^ (seed * 0x9e3779b97f4a7c15ull));
  Shape2 s;
  if (kind == "boost43") s = boost43(rng);
  else if (kind == "near-collinear") s = near_collinear(rng);
  else if (kind == "near-cocircular") s = near_cocircular(rng);
  else if (kind == "int32-limit") s = int32_limit(rng);
  else if (kind == "spikes") s = spikes(rng);
  else if (kind == "random-star") s = random_star(rng);
  else throw std::invalid_argument("unknown adversarial polygon kind '" + kind + "'");
  s.name = kind + ":" + std::to_string(seed);
  return s;
}

}  // namespace grassfire
