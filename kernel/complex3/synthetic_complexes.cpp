// synthetic_complexes.cpp -- hand-made complexes with known burning times (see header).
#include "complex3/synthetic_complexes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>

#include "complex3/complex_builder.h"
#include "complex3/synthetic_tubes.h"
#include "number/exact_sum.h"

namespace grassfire {
namespace {

const double kSqrt2 = std::sqrt(2.0);

ExactPoint3 point(const mpq_class& x, const mpq_class& y, const mpq_class& z) { return {x, y, z}; }

// A grid of (nu + 1) x (nv + 1) vertices given by `at`, split into triangles; returns ids.
std::vector<std::vector<std::uint32_t>> grid(ComplexBuilder& b, int nu, int nv,
                                             const std::function<ExactPoint3(int, int)>& at) {
  std::vector<std::vector<std::uint32_t>> id(nu + 1, std::vector<std::uint32_t>(nv + 1));
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) id[i][j] = b.vertex(at(i, j));
  // Split every cell along its (i, j)-(i+1, j+1) diagonal (on the board this makes the
  // line y = x a chain of triangle edges, so N is part of the triangulation).
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) b.quad(id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]);
  return id;
}

void never_along(ComplexBuilder& b, const std::vector<std::uint32_t>& chain) {
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) b.rule(chain[i], chain[i + 1], IgnitionRule::Never);
}

}  // namespace

std::array<mpq_class, 2> rational_unit_direction(double theta) {
  theta = std::remainder(theta, 2 * M_PI);  // (-pi, pi]
  const bool flip = std::abs(theta) > M_PI / 2;
  if (flip) theta = std::remainder(theta + M_PI, 2 * M_PI);
  const mpq_class t = make_rational(std::lround(std::tan(theta / 2) * 64), 64);
  const mpq_class den = 1 + t * t;
  std::array<mpq_class, 2> d = {mpq_class((1 - t * t) / den), mpq_class(2 * t / den)};
  if (flip) d = {mpq_class(-d[0]), mpq_class(-d[1])};
  return d;
}

RawComplex board_fin(const BoardFinOptions& o) {
  if (o.extent < 3 || o.cells_per_unit < 1) throw std::invalid_argument("board_fin: extent >= 3, cells >= 1");
  ComplexBuilder b("board-fin(E=" + std::to_string(o.extent) + ",g=" + std::to_string(o.cells_per_unit) + ")");
  const int g = o.cells_per_unit, n = o.extent * g;
  auto coord = [&](int i) { return make_rational(i, g); };
  const auto board = grid(b, 2 * n, n, [&](int i, int j) { return point(coord(i - n), coord(j), 0); });
  const auto fin = grid(b, n - g, n, [&](int i, int j) { return point(coord(i + g), coord(i + g), coord(j)); });
  // Truncation borders: x = -E, x = E, y = E on the board; z = E and s = E on the fin.
  std::vector<std::uint32_t> left, right, top, fin_top, fin_end;
  for (int j = 0; j <= n; ++j) left.push_back(board[0][j]), right.push_back(board[2 * n][j]);
  for (int i = 0; i <= 2 * n; ++i) top.push_back(board[i][n]);
  for (int i = 0; i <= n - g; ++i) fin_top.push_back(fin[i][n]);
  for (int j = 0; j <= n; ++j) fin_end.push_back(fin[n - g][j]);
  for (const auto* chain : {&left, &right, &top, &fin_top, &fin_end}) never_along(b, *chain);
  return b.take();
}

std::array<double, 3> board_fin_kink() { return {2 + kSqrt2, 2 + kSqrt2, 0.0}; }

// Derivation (a = 1, zero radius): B ignites the board at 0, so y bounds BT on the board
// and equals it wherever fire from B arrives first. On N at distance t = sqrt2 (s - 1)
// from c the fin's front arrives at t, the back side's at s, the front side's last; N
// burns at the second arrival max(s, t) (the kink is where they are equal, s = 2 + sqrt2).
// Beyond k, BT on N grows at unit rate along N, so the fire N sends into the front side is
// the circle 2 + sqrt2 + |p - k|; it is below y exactly where x > 2 + sqrt2 (the two are
// equal on the vertical ray above k). On the back side y is always the smaller.
double board_fin_burning_time(const std::array<double, 3>& p) {
  const double x = p[0], y = p[1], z = p[2];
  if (z > 0) return kSqrt2 * (x - 1);
  if (x == y && x >= 1) return std::max(x, kSqrt2 * (x - 1));
  const auto k = board_fin_kink();
  if (y > x && x > k[0]) return k[0] + std::hypot(x - k[0], y - k[1]);
  return y;
}

RawComplex board_cylinder(const BoardCylinderOptions& o) {
  if (o.sides < 3 || o.rings < 1 || o.rows < 1 || !(o.radius > 0) || !(o.half_width > 2 * o.radius))
    throw std::invalid_argument("board_cylinder: sides >= 3, rings, rows >= 1, 0 < radius < half_width / 2");
  ComplexBuilder b("board-cylinder(k=" + std::to_string(o.sides) + ")");
  const mpq_class r = make_rational(std::lround(o.radius * 8), 8);
  const mpq_class L = make_rational(std::lround(o.half_width * 8), 8);
  const mpq_class height = o.height > 0 ? make_rational(std::lround(o.height * 8), 8) : mpq_class(2 * r);
  const int k = o.sides;
  std::vector<std::array<mpq_class, 2>> dir;
  for (int j = 0; j < k; ++j) dir.push_back(rational_unit_direction(2 * M_PI * j / k));
  // Rings of the board at radii r, ..., 0.8 L (scaled copies of the k-gon), then the square.
  const mpq_class outer = L * make_rational(4, 5);
  std::vector<std::vector<std::uint32_t>> ring(o.rings + 1, std::vector<std::uint32_t>(k));
  for (int m = 0; m <= o.rings; ++m) {
    const mpq_class rho = r + (outer - r) * make_rational(m, o.rings);
    for (int j = 0; j < k; ++j) ring[m][j] = b.vertex(point(rho * dir[j][0], rho * dir[j][1], 0));
  }
  const std::uint32_t centre = b.vertex(point(0, 0, 0));
  for (int j = 0; j < k; ++j) b.triangle(centre, ring[0][j], ring[0][(j + 1) % k]);
  for (int m = 0; m < o.rings; ++m)
    for (int j = 0; j < k; ++j) b.quad(ring[m][j], ring[m + 1][j], ring[m + 1][(j + 1) % k], ring[m][(j + 1) % k]);
  // The square: the k directions pushed out to it, and its corners, fanned from the last ring.
  auto on_square = [&](const std::array<mpq_class, 2>& d) {
    const mpq_class m = std::max(abs(d[0]), abs(d[1]));
    return point(L * d[0] / m, L * d[1] / m, 0);
  };
  for (int j = 0; j < k; ++j) {
    const auto& d0 = dir[j];
    const auto& d1 = dir[(j + 1) % k];
    std::vector<std::uint32_t> chain = {b.vertex(on_square(d0))};
    for (const auto& corner : std::vector<std::array<int, 2>>{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) {
      // The corner lies strictly between the two directions (counterclockwise).
      const mpq_class c0 = d0[0] * corner[1] - d0[1] * corner[0];
      const mpq_class c1 = corner[0] * d1[1] - corner[1] * d1[0];
      if (sgn(c0) > 0 && sgn(c1) > 0) chain.push_back(b.vertex(point(L * corner[0], L * corner[1], 0)));
    }
    chain.push_back(b.vertex(on_square(d1)));
    const std::uint32_t inner0 = ring[o.rings][j], inner1 = ring[o.rings][(j + 1) % k];
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      b.triangle(inner0, chain[i], chain[i + 1]);
      const ExactPoint3 &p = b.raw().vertices[chain[i]], &q = b.raw().vertices[chain[i + 1]];
      if (o.near_side_only && !(p.y == -L && q.y == -L)) b.rule(chain[i], chain[i + 1], IgnitionRule::Never);
    }
    b.triangle(inner0, chain.back(), inner1);
  }
  // The prism's side.
  std::vector<std::vector<std::uint32_t>> side(o.rows + 1, std::vector<std::uint32_t>(k));
  for (int m = 0; m <= o.rows; ++m)
    for (int j = 0; j < k; ++j) side[m][j] = b.vertex(point(r * dir[j][0], r * dir[j][1], height * make_rational(m, o.rows)));
  for (int m = 0; m < o.rows; ++m)
    for (int j = 0; j < k; ++j) b.quad(side[m][j], side[m][(j + 1) % k], side[m + 1][(j + 1) % k], side[m + 1][j]);
  return b.take();
}

RawComplex book(const BookOptions& o) {
  const int k = o.pages;
  if (k < 1 || o.height < 0 || o.cells_per_unit < 1 || (!o.widths.empty() && static_cast<int>(o.widths.size()) != k))
    throw std::invalid_argument("book: pages >= 1, height >= 1, cells >= 1, one width per page");
  ComplexBuilder b("book(k=" + std::to_string(k) + ")");
  const int g = o.cells_per_unit, nz = book_height(o) * g;
  for (int j = 0; j < k; ++j) {
    const long w = o.widths.empty() ? 2 : o.widths[j];
    if (w < 1) throw std::invalid_argument("book: widths >= 1");
    const auto d = rational_unit_direction(2 * M_PI * j / k);
    const int nu = static_cast<int>(w) * g;
    const auto id = grid(b, nu, nz, [&](int i, int m) {
      const mpq_class u = make_rational(i, g);
      return point(u * d[0], u * d[1], make_rational(m, g));
    });
    (void)id;
  }
  return b.take();
}

int book_height(const BookOptions& o) {
  if (o.height > 0) return o.height;
  const long w = o.widths.empty() ? 2 : *std::max_element(o.widths.begin(), o.widths.end());
  return static_cast<int>(2 * w + 2);
}

double book_burning_time(const BookOptions& o, int page, double u, double z) {
  std::vector<long> w = o.widths.empty() ? std::vector<long>(o.pages, 2) : o.widths;
  const double wj = static_cast<double>(w.at(page));
  std::sort(w.begin(), w.end());
  const double spine = o.pages == 1 ? 0.0 : static_cast<double>(w[o.pages - 2]);
  const double s = book_height(o);
  if (u == 0) return std::min({spine, z, s - z});  // on the spine itself
  return std::min({wj - u, spine + u, z, s - z});
}

BookOptions y_junction_options(int cells_per_unit) {
  BookOptions o;
  o.pages = 3;
  o.widths = {2, 3, 4};
  o.height = 10;
  o.cells_per_unit = cells_per_unit;
  return o;
}

RawComplex y_junction(int cells_per_unit) {
  RawComplex r = book(y_junction_options(cells_per_unit));
  r.source = "y-junction";
  return r;
}

RawComplex tetrahedron_surface() {
  ComplexBuilder b("tetrahedron");
  const std::uint32_t o = b.vertex(point(0, 0, 0)), x = b.vertex(point(1, 0, 0)), y = b.vertex(point(0, 1, 0)),
                      z = b.vertex(point(0, 0, 1));
  b.triangle(o, y, x);
  b.triangle(o, x, z);
  b.triangle(o, z, y);
  b.triangle(x, y, z);
  return b.take();
}

RawComplex octahedron_surface() {
  ComplexBuilder b("octahedron");
  std::uint32_t v[6];
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s) {
      mpq_class c[3] = {0, 0, 0};
      c[a] = s == 0 ? 1 : -1;
      v[2 * a + s] = b.vertex(point(c[0], c[1], c[2]));
    }
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) b.triangle(v[sx], v[2 + sy], v[4 + sz]);
  return b.take();
}

RawComplex pinched_double_cone(int sides) {
  if (sides < 3) throw std::invalid_argument("pinched_double_cone: sides >= 3");
  ComplexBuilder b("double-cone(k=" + std::to_string(sides) + ")");
  const std::uint32_t apex = b.vertex(point(0, 0, 0));
  for (int up : {1, -1}) {
    std::vector<std::uint32_t> rim;
    for (int j = 0; j < sides; ++j) {
      const auto d = rational_unit_direction(2 * M_PI * j / sides);
      rim.push_back(b.vertex(point(d[0], d[1], up)));
    }
    for (int j = 0; j < sides; ++j) b.triangle(apex, rim[j], rim[(j + 1) % sides]);
  }
  return b.take();
}

RawComplex tetrahedron_with_flap() {
  ComplexBuilder b("tetrahedron-flap");
  RawComplex tet = tetrahedron_surface();
  for (const auto& t : tet.triangles)
    b.triangle(b.vertex(tet.vertices[t[0]]), b.vertex(tet.vertices[t[1]]), b.vertex(tet.vertices[t[2]]));
  b.quad(b.vertex(point(0, 0, 0)), b.vertex(point(0, -1, 0)), b.vertex(point(1, -1, 0)), b.vertex(point(1, 0, 0)));
  RawComplex r = b.take();
  return r;
}

RawComplex box_medial_axis(long a, long b, long c, int n) {
  if (!(a >= b && b > c && c > 0) || n < 1) throw std::invalid_argument("box_medial_axis: a >= b > c > 0, n >= 1");
  ComplexBuilder bld("box-medial-axis(" + std::to_string(a) + "," + std::to_string(b) + "," + std::to_string(c) + ")");
  struct Corner {
    ExactPoint3 p;
    mpq_class r;
  };
  auto P = [&](int sx, int sy) { return Corner{point(sx * (a - c), sy * (b - c), 0), c}; };
  auto Q = [&](int sx, int sy, int sz) { return Corner{point(sx * a, sy * b, sz * c), 0}; };
  auto at = [&](const Corner& p, const Corner& q, const Corner& r, const Corner& s, int i, int j) {
    // Bilinear point of the planar quad p q r s at (i/n, j/n), with R interpolated the same
    // way (R is affine on the quad, so this is R there).
    const mpq_class u = make_rational(i, n), v = make_rational(j, n);
    const mpq_class wp = (1 - u) * (1 - v), wq = u * (1 - v), wr = u * v, ws = (1 - u) * v;
    const ExactPoint3 x = wp * p.p + wq * q.p + wr * r.p + ws * s.p;
    const mpq_class rad = wp * p.r + wq * q.r + wr * r.r + ws * s.r;
    return bld.vertex(x, rad * rad);
  };
  auto quad = [&](const Corner& p, const Corner& q, const Corner& r, const Corner& s) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        bld.quad(at(p, q, r, s, i, j), at(p, q, r, s, i + 1, j), at(p, q, r, s, i + 1, j + 1), at(p, q, r, s, i, j + 1));
  };
  auto tri = [&](const Corner& p, const Corner& q, const Corner& r) {
    // A triangle is the quad p q r r degenerated at r: use barycentric rows instead.
    auto bary = [&](int i, int j) {
      const mpq_class u = make_rational(i, n), v = make_rational(j, n), w = 1 - u - v;
      return bld.vertex(w * p.p + u * q.p + v * r.p, (w * p.r + u * q.r + v * r.r) * (w * p.r + u * q.r + v * r.r));
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        bld.triangle(bary(i, j), bary(i + 1, j), bary(i, j + 1));
        if (i + j + 2 <= n) bld.triangle(bary(i + 1, j), bary(i + 1, j + 1), bary(i, j + 1));
      }
  };
  quad(P(-1, -1), P(1, -1), P(1, 1), P(-1, 1));
  for (int sz : {1, -1}) {
    for (int sy : {1, -1}) quad(Q(-1, sy, sz), Q(1, sy, sz), P(1, sy), P(-1, sy));
    for (int sx : {1, -1}) quad(Q(sx, -1, sz), Q(sx, 1, sz), P(sx, 1), P(sx, -1));
  }
  for (int sx : {1, -1})
    for (int sy : {1, -1}) tri(Q(sx, sy, 1), Q(sx, sy, -1), P(sx, sy));
  return bld.take();
}

double box_medial_axis_burning_time(double a, double b, double c, const std::array<double, 3>& p) {
  const double x = std::abs(p[0]), y = std::abs(p[1]), z = std::abs(p[2]);
  if (z == 0 && x <= a - c && y <= b - c) return kSqrt2 * c + std::min(a - c - x, b - c - y);
  return kSqrt2 * std::min({a - x, b - y, c - z});
}

RawComplex random_planar_fan(std::uint32_t seed) {
  std::mt19937 rng(seed);
  ComplexBuilder b("planar sheet " + std::to_string(seed));
  const std::uint32_t centre = b.vertex({0, 0, 0}, 4);
  const int k = 5 + static_cast<int>(seed % 6);
  std::uniform_int_distribution<int> radius(6, 12), rr(0, 3);
  const mpq_class rho = radius(rng);
  std::vector<std::uint32_t> rim;
  for (int j = 0; j < k; ++j) {
    const auto d = rational_unit_direction(2 * M_PI * j / k);
    const mpq_class r = rr(rng);
    rim.push_back(b.vertex({rho * d[0], rho * d[1], 0}, r * r));
  }
  for (int j = 0; j < k; ++j) b.triangle(centre, rim[j], rim[(j + 1) % k]);
  b.rule(rim[0], rim[1], IgnitionRule::Never);
  return b.take();
}

std::vector<std::string> synthetic_complex_names() {
  return {"board-fin", "board-cylinder", "book:K", "y-junction", "tetrahedron", "octahedron", "double-cone",
          "tetrahedron-flap", "box:A:B:C", "tube", "annulus", "torus"};
}

RawComplex synthetic_complex(const std::string& name) {
  if (name == "board-fin") return board_fin();
  if (name == "board-cylinder") return board_cylinder();
  if (name == "y-junction") return y_junction();
  if (name == "tetrahedron") return tetrahedron_surface();
  if (name == "octahedron") return octahedron_surface();
  if (name == "double-cone") return pinched_double_cone();
  if (name == "tetrahedron-flap") return tetrahedron_with_flap();
  if (name == "tube") return tube();
  if (name == "annulus") return square_annulus();
  if (name == "torus") return frame_torus();
  if (name.rfind("book:", 0) == 0) {
    BookOptions o;
    try {
      o.pages = std::stoi(name.substr(5));
    } catch (const std::exception&) {
      throw std::invalid_argument("synthetic complex '" + name + "': K in book:K must be an integer");
    }
    if (o.pages < 1 || o.pages > 64) throw std::invalid_argument("synthetic complex '" + name + "': 1 <= K <= 64");
    return book(o);
  }
  if (name.rfind("box:", 0) == 0) {
    long d[3];
    std::size_t pos = 4;
    for (int i = 0; i < 3; ++i) {
      const std::size_t end = name.find(':', pos);
      try {
        d[i] = std::stol(name.substr(pos, end == std::string::npos ? std::string::npos : end - pos));
      } catch (const std::exception&) {
        throw std::invalid_argument("synthetic complex '" + name + "': expected box:A:B:C with integers A >= B > C > 0");
      }
      pos = end == std::string::npos ? name.size() : end + 1;
    }
    return box_medial_axis(d[0], d[1], d[2]);
  }
  std::string list;
  for (const auto& n : synthetic_complex_names()) list += (list.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown synthetic complex '" + name + "' (known: " + list + ")");
}

}  // namespace grassfire
