// builtin_shapes.cpp -- see builtin_shapes.h.
#include "shapes/builtin_shapes.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "shapes/validate_shape.h"

namespace grassfire {

namespace {

Ring ring(std::vector<Point2> points) { return Ring{std::move(points)}; }

// Fig. 1.2a: the medial axis is a segment with four branches to the corners.
Shape2 rectangle() { return {"", {ring({{0, 0}, {10, 0}, {10, 4}, {0, 4}})}}; }

// Fig. 1.2b: a very small bump on a long side adds a long medial axis branch.
Shape2 rectangle_bump() {
  return {"", {ring({{0, 0}, {10, 0}, {10, 4}, {5.25, 4}, {5, 4.25}, {4.75, 4}, {0, 4}})}};
}

// Fig. 3.2 / 3.3 left: an animal-like body with a tail, two legs and a neck with a head.
Shape2 branches() {
  return {"", {ring({{2, 4},      {3, 4},     {2.6, 1},   {3.4, 1},   {3.8, 4},   {6.2, 4},
                     {6.4, 1},    {7.2, 1},   {7, 4},     {8, 4.4},   {9.4, 7},   {9.8, 7.8},
                     {9, 7.6},    {7.6, 6},   {3, 6},     {1, 7.6},   {0.4, 7.2}, {2, 5}})}};
}

// Fig. 3.3 right: an irregular shape with one interior hole (its medial axis has a loop).
Shape2 hole() {
  return {"",
          {ring({{1, 1}, {6, 0.5}, {9, 2}, {9.5, 6}, {7, 9}, {3, 9.5}, {0.5, 6}}),
           ring({{3.5, 3.5}, {4, 6.5}, {6.5, 6}, {6, 3.5}})}};
}

// Fig. 3.6: a big rectangle (blunt corners), a thin rectangle attached to it (a sharp
// protrusion) and a small bump (boundary noise).
Shape2 blunt_sharp() {
  return {"", {ring({{0, 0}, {6, 0}, {6, 1.6}, {9, 1.6}, {9, 2.4}, {6, 2.4}, {6, 4}, {3.2, 4}, {3, 4.25},
                     {2.8, 4}, {0, 4}})}};
}

// SplitMix64 (Steele, Lea, Flood 2014): a fixed, platform-independent pseudo-random stream.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  // Uniform in [-1, 1).
  double symmetric() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1p-52 - 1.0;
  }

 private:
  std::uint64_t state_;
};

// Fig. 3.4: a body with five limbs of different lengths (Gaussian bumps of the radius in
// five directions) and 6% radial noise at each of 400 vertices.
Shape2 noisy() {
  struct Limb {
    double angle, length, width;
  };
  const Limb limbs[] = {{0.0, 3.0, 0.16}, {1.25, 1.8, 0.2}, {2.4, 2.0, 0.18}, {3.5, 2.8, 0.15}, {5.0, 2.2, 0.2}};
  const double pi = std::acos(-1.0);
  const int n = 400;
  SplitMix64 noise(20110801);
  Ring r;
  for (int i = 0; i < n; ++i) {
    const double theta = 2 * pi * i / n;
    double radius = 1.4;
    for (const Limb& l : limbs) {
      const double d = std::remainder(theta - l.angle, 2 * pi) / l.width;
      radius += l.length * std::exp(-d * d);
    }
    radius *= 1.0 + 0.06 * noise.symmetric();
    // Elongated horizontally; rounded to 3 decimals (nice, reproducible numbers).
    const double x = std::round((5.0 + 1.15 * radius * std::cos(theta)) * 1000) / 1000;
    const double y = std::round((5.0 + 0.8 * radius * std::sin(theta)) * 1000) / 1000;
    r.points.push_back({x, y});
  }
  return {"", {r}};
}

struct Entry {
  BuiltinShapeInfo info;
  Shape2 (*make)();
};

const std::vector<Entry>& entries() {
  static const std::vector<Entry> list = {
      {{"rectangle", "a 10 x 4 rectangle (Fig. 1.2a)"}, rectangle},
      {{"rectangle-bump", "the rectangle with a small bump on a long side (Fig. 1.2b)"}, rectangle_bump},
      {{"branches", "a simply connected elongated body with four limbs (Fig. 3.2, Fig. 3.3 left)"}, branches},
      {{"hole", "an irregular shape with one interior hole (Fig. 3.3 right)"}, hole},
      {{"noisy", "a five-limbed body with heavy pseudo-random boundary noise, fixed seed (Fig. 3.4)"}, noisy},
      {{"blunt-sharp", "a big rectangle with a thin rectangle attached and a small bump (Fig. 3.6)"}, blunt_sharp},
  };
  return list;
}

}  // namespace

const std::vector<BuiltinShapeInfo>& builtin_shape_list() {
  static const std::vector<BuiltinShapeInfo> list = [] {
    std::vector<BuiltinShapeInfo> l;
    for (const Entry& e : entries()) l.push_back(e.info);
    return l;
  }();
  return list;
}

bool is_builtin_shape(const std::string& name) {
  for (const Entry& e : entries())
    if (e.info.name == name) return true;
  return false;
}

std::string builtin_shape_names() {
  std::string names;
  for (const Entry& e : entries()) names += (names.empty() ? "" : ", ") + e.info.name;
  return names;
}

Shape2 builtin_shape(const std::string& name) {
  for (const Entry& e : entries())
    if (e.info.name == name) {
      Shape2 s = e.make();
      s.name = name;
      validate_shape(s, "built-in shape '" + name + "'");
      return s;
    }
  throw std::invalid_argument("unknown built-in shape '" + name + "'; the built-in shapes are: " +
                              builtin_shape_names());
}

}  // namespace grassfire
