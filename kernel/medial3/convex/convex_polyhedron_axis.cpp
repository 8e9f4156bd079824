// convex_polyhedron_axis.cpp -- see convex_polyhedron_axis.h.
#include "medial3/convex/convex_polyhedron_axis.h"

#include <algorithm>
#include <optional>
#include <set>
#include <stdexcept>

#include "medial3/convex/polytope_cells.h"
#include "complex3/complex_builder.h"
#include "geometry3/exact_predicates3.h"

namespace grassfire {

namespace {

enum : std::uint64_t { kFacet = 1, kBisector = 2 };  // kBox = 0 (polytope_cells.h)

std::uint64_t label(std::uint64_t kind, std::uint64_t i, std::uint64_t j = 0) { return (kind << 56) | (i << 28) | j; }
std::uint64_t kind_of(std::uint64_t l) { return l >> 56; }
std::uint32_t first_of(std::uint64_t l) { return static_cast<std::uint32_t>((l >> 28) & 0xFFFFFFF); }
std::uint32_t second_of(std::uint64_t l) { return static_cast<std::uint32_t>(l & 0xFFFFFFF); }

std::optional<mpq_class> rational_sqrt(const mpq_class& q) {
  if (sgn(q) < 0) return std::nullopt;
  mpz_class n = q.get_num(), d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
  mpz_sqrt(n.get_mpz_t(), n.get_mpz_t());
  mpz_sqrt(d.get_mpz_t(), d.get_mpz_t());
  return make_rational(n, d);
}

// The distance functions g_i = (e_i - u_i . x) / sqrt(s) of the polyhedron actually used.
struct Normalized {
  std::vector<ExactPoint3> u;
  std::vector<mpq_class> e;
  mpq_class s = 1;
  bool exact = true;
  double bound = 0;
};

// Exact mode: every |n_i|^2 = s q_i^2 with s = |n_0|^2; u_i = n_i / q_i, e_i = d_i / q_i.
std::optional<Normalized> normalize_exactly(const std::vector<HalfSpace>& planes) {
  Normalized out;
  out.s = planes[0].a * planes[0].a + planes[0].b * planes[0].b + planes[0].c * planes[0].c;
  for (const HalfSpace& h : planes) {
    const auto q = rational_sqrt((h.a * h.a + h.b * h.b + h.c * h.c) / out.s);
    if (!q) return std::nullopt;
    out.u.push_back({h.a / *q, h.b / *q, h.c / *q});
    out.e.push_back(h.d / *q);
  }
  return out;
}

mpq_class dyadic(mpfr_srcptr x, long bits) {
  mpfr_t t;
  mpfr_init2(t, mpfr_get_prec(x) + 8);
  mpfr_mul_2si(t, x, bits, MPFR_RNDN);
  mpfr_rint(t, t, MPFR_RNDN);
  mpz_class n;
  mpfr_get_z(n.get_mpz_t(), t, MPFR_RNDN);
  mpfr_clear(t);
  return make_rational(n, mpz_class(1) << static_cast<unsigned long>(bits));
}

// A rational unit vector near n / |n| (inverse stereographic projection of a dyadic
// point), and a certified upper bound on its distance to n / |n|.
ExactPoint3 rational_unit_near(const ExactPoint3& n, long bits, double* delta) {
  const long prec = 2 * bits + 64;
  const mpq_class m = dot(n, n);
  mpfr_t len, c[3], p, q, one;
  mpfr_inits2(prec, len, c[0], c[1], c[2], p, q, one, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(len, m.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(len, len, MPFR_RNDN);
  const mpq_class* nc[3] = {&n.x, &n.y, &n.z};
  for (int k = 0; k < 3; ++k) {
    mpfr_set_q(c[k], nc[k]->get_mpq_t(), MPFR_RNDN);
    mpfr_div(c[k], c[k], len, MPFR_RNDN);
  }
  const bool north = mpfr_sgn(c[2]) < 0;  // project from the pole farther from the point
  mpfr_set_ui(one, 1, MPFR_RNDN);
  if (north) mpfr_sub(one, one, c[2], MPFR_RNDN); else mpfr_add(one, one, c[2], MPFR_RNDN);
  mpfr_div(p, c[0], one, MPFR_RNDN);
  mpfr_div(q, c[1], one, MPFR_RNDN);
  const mpq_class P = dyadic(p, bits), Q = dyadic(q, bits);
  const mpq_class r2 = P * P + Q * Q, den = 1 + r2;
  ExactPoint3 u{2 * P / den, 2 * Q / den, mpq_class(north ? mpq_class(r2 - 1) : mpq_class(1 - r2)) / den};
  // |u - n/|n||^2 = 2 - 2 (u . n) / |n|, bounded above with directed rounding.
  const mpq_class un = dot(u, n);
  mpfr_set_q(len, m.get_mpq_t(), MPFR_RNDU);
  mpfr_sqrt(len, len, MPFR_RNDU);
  mpfr_set_q(p, un.get_mpq_t(), MPFR_RNDD);
  mpfr_div(p, p, len, MPFR_RNDD);
  mpfr_mul_2ui(p, p, 1, MPFR_RNDD);
  mpfr_ui_sub(p, 2, p, MPFR_RNDU);
  if (mpfr_sgn(p) < 0) mpfr_set_ui(p, 0, MPFR_RNDU);
  mpfr_sqrt(p, p, MPFR_RNDU);
  *delta = mpfr_get_d(p, MPFR_RNDU);
  mpfr_clears(len, c[0], c[1], c[2], p, q, one, static_cast<mpfr_ptr>(nullptr));
  return u;
}

double sqrt_up(const mpq_class& q) { return round_up(std::sqrt(enclose(q).hi)); }

// Approximate mode: planes with rational |n_i| stay exact (s = 1); the others turn about
// the centroid of their facet of P to a nearby rational unit normal.
Normalized normalize_approximately(const std::vector<HalfSpace>& planes, const std::vector<ExactPoint3>& centroid,
                                   long bits, std::vector<double>* deltas) {
  Normalized out;
  out.exact = false;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const HalfSpace& h = planes[i];
    const ExactPoint3 n{h.a, h.b, h.c};
    double delta = 0;
    if (const auto len = rational_sqrt(dot(n, n))) {
      out.u.push_back({h.a / *len, h.b / *len, h.c / *len});
      out.e.push_back(h.d / *len);
    } else {
      out.u.push_back(rational_unit_near(n, bits, &delta));
      out.e.push_back(dot(out.u.back(), centroid[i]));
    }
    deltas->push_back(delta);
  }
  return out;
}

mpq_class distance_numerator(const Normalized& g, std::size_t i, const ExactPoint3& x) { return g.e[i] - dot(g.u[i], x); }

std::vector<CellPlane> facet_planes(const Normalized& g) {
  std::vector<CellPlane> out;
  for (std::size_t i = 0; i < g.u.size(); ++i)
    out.push_back(rational_plane(g.u[i].x, g.u[i].y, g.u[i].z, -g.e[i], label(kFacet, i)));
  return out;
}

// C_i: the box clipped by facet i and by g_i <= g_j, i.e. (u_j - u_i) . x + e_i - e_j <= 0.
PolytopeCell facet_cell(const Normalized& g, std::size_t i, const std::vector<std::size_t>& order,
                        const ExactPoint3& lo, const ExactPoint3& hi, ClipStats* stats) {
  std::vector<CellPlane> cuts{facet_planes(g)[i]};
  for (std::size_t j : order) {
    if (j == i) continue;
    const ExactPoint3 d = g.u[j] - g.u[i];
    cuts.push_back(rational_plane(d.x, d.y, d.z, g.e[i] - g.e[j], label(kBisector, i, j)));
  }
  PolytopeCell cell = clip_box(lo, hi, cuts);
  stats->merge(cell.stats);
  if (cell.touches_box) throw std::logic_error("convex axis: a facet cell reaches the bounding box");
  return cell;
}

// Facets j in order of adjacency to facet i in P (sharing a vertex first): the cell
// shrinks to its final size after a few clips, so the remaining ones are sign tests only.
std::vector<std::size_t> clip_order(const PolytopeCell& p, std::size_t i, std::size_t m) {
  std::set<std::size_t> near;
  std::set<std::uint32_t> own;
  for (const auto& f : p.faces)
    if (first_of(f.label) == i) own.insert(f.vertices.begin(), f.vertices.end());
  for (const auto& f : p.faces)
    for (std::uint32_t v : f.vertices)
      if (own.count(v)) near.insert(first_of(f.label));
  std::vector<std::size_t> order(near.begin(), near.end());
  for (std::size_t j = 0; j < m; ++j)
    if (!near.count(j)) order.push_back(j);
  return order;
}

}  // namespace

ConvexAxis convex_polyhedron_axis(const ConvexPolyhedron& input, const ConvexAxisOptions& options) {
  if (input.planes.size() < 4) throw std::invalid_argument(input.source + ": fewer than 4 half-spaces cannot bound a polyhedron");
  ConvexAxis out;
  // The polyhedron from the planes as given: its facets, bounds and centroids.
  std::vector<CellPlane> given;
  for (std::size_t i = 0; i < input.planes.size(); ++i) {
    const HalfSpace& h = input.planes[i];
    given.push_back(rational_plane(h.a, h.b, h.c, -h.d, label(kFacet, i)));
  }
  PolytopeCell p0 = polytope_from_planes(given, input.source);
  std::vector<HalfSpace> facets;
  std::vector<ExactPoint3> centroid;
  for (auto& f : p0.faces) {
    facets.push_back(input.planes[first_of(f.label)]);
    centroid.push_back(polygon_centroid(p0, f));
    // From here on facets are numbered in this order (g->u, clip_order): relabel, or a
    // redundant input plane shifts the numbers past the end of g->u.
    f.label = label(kFacet, facets.size() - 1);
  }
  out.redundant_planes = input.planes.size() - facets.size();
  std::vector<double> deltas;
  std::optional<Normalized> g = normalize_exactly(facets);
  if (!g) g = normalize_approximately(facets, centroid, options.approximation_bits, &deltas);
  PolytopeCell p = g->exact ? std::move(p0) : polytope_from_planes(facet_planes(*g), input.source);
  if (!g->exact) {
    // Keep only the rotated planes that are facets of P' (a tiny facet may vanish).
    Normalized kept;
    kept.exact = false;
    for (auto& f : p.faces) {
      const std::uint32_t i = first_of(f.label);
      double radius = 0;
      for (const ExactPoint3& v : p.points) radius = std::max(radius, sqrt_up(squared_distance(v, centroid[i])));
      kept.bound = std::max(kept.bound, round_up(deltas[i] * radius));
      f.label = label(kFacet, kept.u.size());
      kept.u.push_back(g->u[i]);
      kept.e.push_back(g->e[i]);
    }
    g = kept;
  }
  out.exact = g->exact;
  out.distance_bound = g->bound;
  out.volume = polytope_volume(p);
  ExactPoint3 lo = p.points[0], hi = p.points[0];
  for (const ExactPoint3& v : p.points) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  lo = lo - ExactPoint3{1, 1, 1};
  hi = hi + ExactPoint3{1, 1, 1};
  const std::size_t m = g->u.size();
  ComplexBuilder builder(input.source + " (convex medial axis)");
  for (std::size_t i = 0; i < m; ++i) {
    const PolytopeCell cell = facet_cell(*g, i, clip_order(p, i, m), lo, hi, &out.stats);
    out.cell_volume_sum += polytope_volume(cell);
    for (const auto& f : cell.faces) {
      if (kind_of(f.label) != kBisector || second_of(f.label) < i) continue;
      ++out.polygons;
      std::vector<std::uint32_t> ids;
      for (std::uint32_t v : f.vertices) {
        const ExactPoint3& x = cell.points[v];
        mpq_class h = distance_numerator(*g, 0, x);
        for (std::size_t k = 1; k < m; ++k) h = std::min(h, distance_numerator(*g, k, x));
        ids.push_back(builder.vertex(x, h * h / g->s));
      }
      for (std::size_t k = 1; k + 1 < ids.size(); ++k) builder.triangle(ids[0], ids[k], ids[k + 1]);
    }
  }
  out.complex = builder.take();
  out.u = g->u;
  out.e = g->e;
  out.s = g->s;
  return out;
}

DefinitionCheck check_convex_axis(const ConvexAxis& axis) {
  DefinitionCheck c;
  const std::size_t m = axis.u.size();
  auto check_point = [&](const ExactPoint3& x, const mpq_class* r2, const std::string& what) {
    ++c.points;
    mpq_class best;
    std::size_t attained = 0;
    bool inside = true;
    for (std::size_t k = 0; k < m; ++k) {
      const mpq_class h = axis.e[k] - dot(axis.u[k], x);
      inside &= sgn(h) >= 0;
      if (k == 0 || h < best) {
        best = h;
        attained = 1;
      } else if (h == best) {
        ++attained;
      }
    }
    std::string problem;
    if (!inside) problem = "outside the polyhedron";
    else if (attained < 2) problem = "only one nearest facet";
    else if (r2 && *r2 != best * best / axis.s) problem = "R^2 differs from the distance to the boundary";
    if (problem.empty()) return;
    if (c.failures++ == 0) c.first_failure = what + ": " + problem;
  };
  const RawComplex& raw = axis.complex;
  for (std::size_t v = 0; v < raw.vertices.size(); ++v)
    check_point(raw.vertices[v], &raw.radius_squared[v], "vertex " + std::to_string(v));
  for (std::size_t t = 0; t < raw.triangles.size(); ++t) {
    const auto& tri = raw.triangles[t];
    const ExactPoint3 centre = make_rational(1, 3) * (raw.vertices[tri[0]] + raw.vertices[tri[1]] + raw.vertices[tri[2]]);
    check_point(centre, nullptr, "centroid of triangle " + std::to_string(t));
  }
  return c;
}

}  // namespace grassfire
