// synthetic_tubes.cpp -- tube, annulus and frame torus (see header).
#include "complex3/synthetic_tubes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "complex3/complex_builder.h"
#include "number/exact_sum.h"
#include "complex3/synthetic_complexes.h"

namespace grassfire {
namespace {

ExactPoint3 at(const mpq_class& x, const mpq_class& y, const mpq_class& z) { return {x, y, z}; }

// Quads between two closed rings of vertex ids (same length), as triangles.
void band(ComplexBuilder& b, const std::vector<std::uint32_t>& lo, const std::vector<std::uint32_t>& hi) {
  const std::size_t n = lo.size();
  for (std::size_t j = 0; j < n; ++j) b.quad(lo[j], lo[(j + 1) % n], hi[(j + 1) % n], hi[j]);
}

// The boundary of the square [-s, s]^2 at height z, counterclockwise from (-s, -s), with
// `per_side` points on each side (so 4 per_side points).
std::vector<ExactPoint3> square_ring(const mpq_class& s, int per_side, const mpq_class& z) {
  std::vector<ExactPoint3> ring;
  const mpq_class side = 2 * s;
  for (int i = 0; i < per_side; ++i) ring.push_back(at(-s + side * i / per_side, -s, z));
  for (int i = 0; i < per_side; ++i) ring.push_back(at(s, -s + side * i / per_side, z));
  for (int i = 0; i < per_side; ++i) ring.push_back(at(s - side * i / per_side, s, z));
  for (int i = 0; i < per_side; ++i) ring.push_back(at(-s, s - side * i / per_side, z));
  return ring;
}

// Joins two concentric square rings in one plane whose sides have p and p + 2 segments:
// per side a corner triangle at each end and quads between (the outer ring's points
// i + 1 lie beside the inner ring's points i).
void join_square_rings(ComplexBuilder& b, const std::vector<std::uint32_t>& inner, const std::vector<std::uint32_t>& outer) {
  const std::size_t p = inner.size() / 4, q = outer.size() / 4;
  for (std::size_t side = 0; side < 4; ++side) {
    std::vector<std::uint32_t> in, out;
    for (std::size_t i = 0; i <= p; ++i) in.push_back(inner[(side * p + i) % inner.size()]);
    for (std::size_t i = 0; i <= q; ++i) out.push_back(outer[(side * q + i) % outer.size()]);
    b.triangle(in[0], out[1], out[0]);
    for (std::size_t i = 0; i < p; ++i) b.quad(in[i], in[i + 1], out[i + 2], out[i + 1]);
    b.triangle(in[p], out[q], out[q - 1]);
  }
}

std::vector<std::uint32_t> ids(ComplexBuilder& b, const std::vector<ExactPoint3>& points) {
  std::vector<std::uint32_t> out;
  for (const ExactPoint3& p : points) out.push_back(b.vertex(p));
  return out;
}

}  // namespace

RawComplex tube(const TubeOptions& o) {
  if (o.sides < 3 || o.rows < 1 || o.radius < 1 || o.height < 1)
    throw std::invalid_argument("tube: sides >= 3, rows >= 1, radius >= 1, height >= 1");
  ComplexBuilder b("tube(k=" + std::to_string(o.sides) + ")");
  std::vector<std::array<mpq_class, 2>> dir;
  for (int j = 0; j < o.sides; ++j) dir.push_back(rational_unit_direction(2 * M_PI * j / o.sides));
  std::vector<std::uint32_t> previous;
  for (int m = 0; m <= o.rows; ++m) {
    std::vector<std::uint32_t> ring;
    const mpq_class z = mpq_class(o.height) * m / o.rows;
    for (const auto& d : dir) ring.push_back(b.vertex(at(o.radius * d[0], o.radius * d[1], z)));
    if (m > 0) band(b, previous, ring);
    previous = ring;
  }
  return b.take();
}

double tube_burning_time(const TubeOptions& o, double z) { return std::min(z, o.height - z); }

RawComplex square_annulus(const AnnulusOptions& o) {
  if (o.inner < 1 || o.outer <= o.inner || o.cells_per_unit < 1)
    throw std::invalid_argument("annulus: 1 <= inner < outer, cells >= 1");
  ComplexBuilder b("annulus(" + std::to_string(o.outer) + "," + std::to_string(o.inner) + ")");
  // Rings of squares from the inner to the outer boundary, 1 / g apart; ring m has
  // half-side b + m / g and 2 (b g + m) points per side (spacing 1 / g).
  const int g = o.cells_per_unit, n = (o.outer - o.inner) * g;
  std::vector<std::uint32_t> previous;
  for (int m = 0; m <= n; ++m) {
    const std::vector<std::uint32_t> ring = ids(b, square_ring(o.inner + make_rational(m, g), 2 * (o.inner * g + m), 0));
    if (m > 0) join_square_rings(b, previous, ring);
    previous = ring;
  }
  return b.take();
}

double annulus_burning_time(const AnnulusOptions& o, double x, double y) {
  const double m = std::max(std::abs(x), std::abs(y));
  return std::min(m - o.inner, o.outer - m);
}

RawComplex frame_torus(int a, int b0, int c) {
  if (b0 < 1 || a <= b0 || c < 1) throw std::invalid_argument("frame torus: 1 <= inner < outer, thickness >= 1");
  ComplexBuilder b("frame-torus(" + std::to_string(a) + "," + std::to_string(b0) + "," + std::to_string(c) + ")");
  // Outer and inner walls: bands between square rings at heights 0..c.
  for (long s : {static_cast<long>(a), static_cast<long>(b0)}) {
    std::vector<std::uint32_t> previous;
    for (int z = 0; z <= c; ++z) {
      const std::vector<std::uint32_t> ring = ids(b, square_ring(s, static_cast<int>(2 * s), z));
      if (z > 0) band(b, previous, ring);
      previous = ring;
    }
  }
  // Bottom and top: flat square rings joined between the inner and the outer square.
  for (int z : {0, c})
    for (long s = b0; s < a; ++s)
      join_square_rings(b, ids(b, square_ring(s, static_cast<int>(2 * s), z)),
                        ids(b, square_ring(s + 1, static_cast<int>(2 * s + 2), z)));
  return b.take();
}

}  // namespace grassfire
