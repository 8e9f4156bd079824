// inner_voronoi.cpp -- see inner_voronoi.h. The CGAL translation unit of the mesh axis.
#include "medial3/mesh/inner_voronoi.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <memory>
#include <stdexcept>

#include "medial3/mesh/mesh_checks.h"
#include "geometry3/exact_predicates3.h"
#include "support/cpu_clock.h"
#include "support/union_find.h"
#include "number/exact_sum.h"

namespace grassfire {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, K>;
using Dt = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
using P3 = std::array<double, 3>;

constexpr std::uint32_t kNone = UINT32_MAX;


std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

bool disjoint(const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
  for (int k = 0; k < 3; ++k)
    if (a[k].hi < b[k].lo || b[k].hi < a[k].lo) return true;
  return false;
}

// The per-run state: the triangulation, its cells and the classification.
class Extractor {
 public:
  Extractor(InnerVoronoi* out, const SolidLocator& solid) : out_(out), solid_(solid) {}

  void run() {
    double t = cpu_seconds();
    triangulate();
    out_->delaunay_seconds = cpu_seconds_since(t);
    t = cpu_seconds();
    number_cells();
    merge_cospherical();
    classify();
    estimate_feature_size();
    out_->classify_seconds = cpu_seconds_since(t);
    t = cpu_seconds();
    extract_polygons();
    extract_segments();
    collapse_sample_cells();
    out_->extract_seconds = cpu_seconds_since(t);
  }

 private:
  void triangulate() {
    std::vector<std::pair<K::Point_3, std::uint32_t>> pts;
    pts.reserve(out_->samples.lattice.size());
    for (std::uint32_t i = 0; i < out_->samples.lattice.size(); ++i) {
      const P3 p = out_->samples.point(i);
      pts.push_back({K::Point_3(p[0], p[1], p[2]), i});
    }
    dt_.insert(pts.begin(), pts.end());
  }

  std::array<std::uint32_t, 4> corners(Dt::Cell_handle c) const {
    return {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
  }

  void number_cells() {
    if (dt_.dimension() < 3) return;
    for (auto c = dt_.finite_cells_begin(); c != dt_.finite_cells_end(); ++c) {
      c->info() = static_cast<std::uint32_t>(cells_.size());
      cells_.push_back(c);
      centre_.push_back(lattice_circumcentre(out_->samples, corners(c)));
      box_.push_back(enclose(out_->samples, centre_.back()));
    }
    for (auto c = dt_.all_cells_begin(); c != dt_.all_cells_end(); ++c)
      if (dt_.is_infinite(c)) c->info() = kNone;
    out_->tetrahedra = cells_.size();
  }

  // Adjacent tetrahedra with one circumsphere belong to one Delaunay cell; a cell's
  // tetrahedra are joined through its interior facets, so adjacency finds all of them.
  void merge_cospherical() {
    classes_ = std::make_unique<UnionFind>(cells_.size());
    for (std::uint32_t i = 0; i < cells_.size(); ++i)
      for (int k = 0; k < 4; ++k) {
        const Dt::Cell_handle n = cells_[i]->neighbor(k);
        if (n->info() == kNone || n->info() < i || disjoint(box_[i], box_[n->info()])) continue;
        const K::Point_3& opposite = n->vertex(n->index(cells_[i]))->point();
        if (dt_.side_of_sphere(cells_[i], opposite) == CGAL::ON_BOUNDARY) {
          classes_->unite(i, n->info());
          ++out_->cospherical_pairs;
        }
      }
  }

  void classify() {
    vertex_of_.assign(cells_.size(), kNone);
    for (std::uint32_t i = 0; i < cells_.size(); ++i) {
      if (classes_->find(i) != i) continue;
      ++out_->cells;
      const LatticeCentre& c = centre_[i];
      const int where = solid_.locate(box_[i], [&] { return exact_point(out_->samples, c); });
      if (where == 0) ++out_->cells_on_boundary;
      if (where <= 0) continue;
      vertex_of_[i] = static_cast<std::uint32_t>(out_->vertices.size());
      out_->vertices.push_back({centre_[i], box_[i]});
    }
    for (std::uint32_t i = 0; i < cells_.size(); ++i) vertex_of_[i] = vertex_of_[classes_->find(i)];
  }

  // The poles of a sample (Amenta-Bern): the farthest Voronoi vertices of its cell inside
  // and outside the solid; the nearer of the two estimates the local feature size (the
  // cell is unbounded outside for samples on the convex hull: that pole is at infinity).
  void estimate_feature_size() {
    const std::size_t n = out_->samples.lattice.size();
    std::vector<double> inner(n, 0), outer(n, 0);
    out_->inner_pole.assign(n, UINT32_MAX);
    for (auto c = dt_.all_cells_begin(); c != dt_.all_cells_end(); ++c) {
      const bool finite = c->info() != kNone;
      const bool inside = finite && vertex_of(c) != kNone;
      double r2 = INFINITY;
      if (finite) {
        const LatticeCentre& lc = centre_[c->info()];
        double num = 0;
        for (int k = 0; k < 3; ++k) num += static_cast<double>(lc.num[k]) * static_cast<double>(lc.num[k]);
        r2 = out_->samples.grid * out_->samples.grid * num / (static_cast<double>(lc.den) * static_cast<double>(lc.den));
      }
      for (int k = 0; k < 4; ++k) {
        if (dt_.is_infinite(c->vertex(k))) continue;
        const std::uint32_t i = c->vertex(k)->info();
        double& pole = (inside ? inner : outer)[i];
        if (inside && r2 > pole) out_->inner_pole[i] = vertex_of(c);
        pole = std::max(pole, r2);
      }
    }
    out_->pole_distance.resize(n);
    out_->inner_pole_distance.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      out_->inner_pole_distance[i] = std::sqrt(inner[i]);
      const double r2 = inner[i] == 0 ? outer[i] : outer[i] == 0 ? inner[i] : std::min(inner[i], outer[i]);
      out_->pole_distance[i] = std::sqrt(r2);
    }
  }

  // The Voronoi vertex of a tetrahedron, or kNone when it is infinite or not inside.
  std::uint32_t vertex_of(Dt::Cell_handle c) const { return c->info() == kNone ? kNone : vertex_of_[c->info()]; }

  // Around an interior edge pq the cells of D_in come in runs of tetrahedra; each change
  // of cell is a side of the polygon, dual to the facet (p, q, r) the two tetrahedra share.
  // An edge is taken from the tetrahedron of least index around it; the walk stops at an
  // outer tetrahedron (the edge is not interior) or at one of smaller index.
  void extract_polygons() {
    std::vector<std::uint32_t> around, apex;
    for (std::uint32_t i = 0; i < cells_.size(); ++i) {
      if (vertex_of_[i] == kNone) continue;
      for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 4; ++b) {
          around.clear();
          apex.clear();
          if (walk_around(cells_[i], a, b, &around, &apex)) add_polygon(cells_[i], a, b, around, apex);
        }
    }
  }

  bool walk_around(Dt::Cell_handle first, int a, int b, std::vector<std::uint32_t>* around, std::vector<std::uint32_t>* apex) const {
    const Dt::Vertex_handle vp = first->vertex(a), vq = first->vertex(b);
    const std::uint32_t self = first->info();
    auto start = dt_.incident_cells(first, a, b), c = start;
    do {
      if (c->info() == kNone || c->info() < self) return false;
      const std::uint32_t v = vertex_of_[c->info()];
      if (v == kNone) return false;
      around->push_back(v);
      // The facet shared with the next cell is opposite to the vertex of c that the next
      // cell lacks; the apex is the remaining vertex of c.
      auto next = c;
      ++next;
      const int i = c->index(vp), j = c->index(vq);
      const int k = (i + 1) % 4 == j ? (i + 2) % 4 : (i + 1) % 4;
      const int l = 6 - i - j - k;
      apex->push_back(c->neighbor(k) == next ? c->vertex(l)->info() : c->vertex(k)->info());
      ++c;
    } while (c != start);
    return around->size() >= 3;
  }

  void add_polygon(Dt::Cell_handle c, int a, int b, const std::vector<std::uint32_t>& around,
                   const std::vector<std::uint32_t>& apex) {
    PolygonRings& rings = out_->polygons;
    const std::size_t first = rings.vertex.size();
    for (std::size_t m = 0; m < around.size(); ++m)
      if (around[m] != around[(m + 1) % around.size()]) {
        rings.vertex.push_back(around[m]);
        out_->apex.push_back(apex[m]);
      }
    if (rings.vertex.size() - first < 3) {  // pq is a diagonal of a Delaunay cell or 2-face
      rings.vertex.resize(first);
      out_->apex.resize(first);
      return;
    }
    rings.close();
    out_->pq.push_back({c->vertex(a)->info(), c->vertex(b)->info()});
  }

  // Each Voronoi edge is a polygon side (both orders of its ends), sorted for lookups.
  std::vector<std::uint64_t> polygon_sides() const {
    const PolygonRings& rings = out_->polygons;
    std::vector<std::uint64_t> sides;
    sides.reserve(rings.vertex.size());
    for (std::size_t i = 0; i < rings.size(); ++i)
      for (std::uint32_t k = 0; k < rings.ring_size(i); ++k) {
        const auto [a, b] = rings.side(i, k);
        sides.push_back(pair_key(a, b));
      }
    std::sort(sides.begin(), sides.end());
    return sides;
  }

  // Voronoi edges between two cells of D_in that no polygon has; each once (the first
  // facet found among those of one Delaunay 2-face).
  void extract_segments() {
    const std::vector<std::uint64_t> sides = polygon_sides();
    std::vector<std::pair<std::uint64_t, InnerVoronoi::Segment>> found;
    for (std::uint32_t i = 0; i < cells_.size(); ++i) {
      const std::uint32_t a = vertex_of_[i];
      if (a == kNone) continue;
      for (int f = 0; f < 4; ++f) {
        const Dt::Cell_handle n = cells_[i]->neighbor(f);
        const std::uint32_t b = vertex_of(n);
        if (b == kNone || b == a || n->info() < i) continue;
        const std::uint64_t key = pair_key(a, b);
        if (std::binary_search(sides.begin(), sides.end(), key)) continue;
        InnerVoronoi::Segment s;
        s.v = {std::min(a, b), std::max(a, b)};
        for (int k = 0, m = 0; k < 4; ++k)
          if (k != f) s.triangle[m++] = cells_[i]->vertex(k)->info();
        found.push_back({key, s});
      }
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < found.size(); ++i)
      if (i == 0 || found[i].first != found[i - 1].first) out_->segments.push_back(found[i].second);
  }

  // A sample all of whose Delaunay cells are in D_in is an interior vertex of D_in: its
  // dual block is its whole Voronoi cell (a 3-cell of the dual complex, whose boundary
  // polygons are all in V_in). It happens in narrow grooves, where the other wall's
  // samples cut the cell off from the outside. Each such 3-cell is collapsed through one
  // boundary polygon shared with a sample that is not interior (or whose cell is already
  // gone): the 2-complex keeps the homotopy type of the dual complex.
  void collapse_sample_cells() {
    const std::size_t n = out_->samples.lattice.size();
    std::vector<bool> open(n, false);  // the sample has no 3-cell (any more)
    for (auto c = dt_.all_cells_begin(); c != dt_.all_cells_end(); ++c)
      if (vertex_of(c) == kNone)
        for (int k = 0; k < 4; ++k)
          if (!dt_.is_infinite(c->vertex(k))) open[c->vertex(k)->info()] = true;
    // The polygons of each interior sample, by increasing id (a counting sort: linear).
    std::vector<std::uint32_t> first(n + 1, 0);
    for (const auto& pq : out_->pq)
      for (std::uint32_t s : pq)
        if (!open[s]) ++first[s + 1];
    for (std::size_t s = 0; s < n; ++s) first[s + 1] += first[s];
    if (first[n] == 0) return;
    std::vector<std::uint32_t> faces(first[n]), fill(first.begin(), first.end() - 1);
    for (std::uint32_t i = 0; i < out_->pq.size(); ++i)
      for (std::uint32_t s : out_->pq[i])
        if (!open[s]) faces[fill[s]++] = i;
    std::vector<std::uint32_t> pending;
    for (std::uint32_t s = 0; s < n; ++s)
      if (!open[s]) pending.push_back(s);
    out_->interior_samples = pending.size();
    std::vector<bool> dropped(out_->pq.size(), false);
    while (!pending.empty()) {
      std::vector<std::uint32_t> later;
      for (std::uint32_t s : pending) {
        std::uint32_t k = first[s];
        for (; k < first[s + 1]; ++k) {
          const auto& pq = out_->pq[faces[k]];
          if (!dropped[faces[k]] && open[pq[0] == s ? pq[1] : pq[0]]) break;
        }
        if (k == first[s + 1]) {
          later.push_back(s);
          continue;
        }
        dropped[faces[k]] = true;
        open[s] = true;
      }
      if (later.size() == pending.size()) throw std::logic_error("inner_voronoi: sample cells cannot be collapsed");
      pending.swap(later);
    }
    drop_polygons(dropped);
  }

  void drop_polygons(const std::vector<bool>& dropped) {
    PolygonRings kept;
    std::vector<std::uint32_t> apex;
    std::vector<std::array<std::uint32_t, 2>> pq;
    const PolygonRings& rings = out_->polygons;
    for (std::size_t i = 0; i < rings.size(); ++i) {
      if (dropped[i]) continue;
      kept.vertex.insert(kept.vertex.end(), rings.ring(i), rings.ring(i) + rings.ring_size(i));
      apex.insert(apex.end(), out_->apex.begin() + rings.offset[i], out_->apex.begin() + rings.offset[i + 1]);
      kept.close();
      pq.push_back(out_->pq[i]);
    }
    out_->polygons = std::move(kept);
    out_->apex = std::move(apex);
    out_->pq = std::move(pq);
  }

  InnerVoronoi* out_;
  const SolidLocator& solid_;
  Dt dt_;
  std::vector<Dt::Cell_handle> cells_;
  std::vector<LatticeCentre> centre_;
  std::vector<std::array<Interval, 3>> box_;
  std::unique_ptr<UnionFind> classes_;
  std::vector<std::uint32_t> vertex_of_;  // per class representative
};

}  // namespace

mpz_class to_mpz(__int128 x) {
  const bool negative = x < 0;
  const unsigned __int128 m = negative ? -static_cast<unsigned __int128>(x) : static_cast<unsigned __int128>(x);
  mpz_class z(static_cast<unsigned long>(m >> 64));
  z <<= 64;
  z += static_cast<unsigned long>(m & ~0ul);
  if (negative) z = -z;
  return z;
}

mpq_class to_mpq(__int128 x) { return mpq_class(to_mpz(x)); }

// Bounds (differences |d| <= 2^27): cross products < 2^55, |d|^2 < 2^56, det < 2^84,
// N_k < 3 * 2^56 * 2^55 < 2^113.
LatticeCentre lattice_circumcentre(const SurfaceSamples& s, const std::array<std::uint32_t, 4>& t) {
  using I = __int128;
  std::array<std::array<I, 3>, 3> d;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t x = s.lattice[t[i + 1]][k] - s.lattice[t[0]][k];
      if (x > (1ll << 27) || x < -(1ll << 27)) throw std::invalid_argument("inner_voronoi: samples too far apart for the lattice");
      d[i][k] = x;
    }
  auto cross = [](const std::array<I, 3>& u, const std::array<I, 3>& v) {
    return std::array<I, 3>{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  auto dot = [](const std::array<I, 3>& u, const std::array<I, 3>& v) -> I { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const std::array<I, 3> bc = cross(d[1], d[2]), ca = cross(d[2], d[0]), ab = cross(d[0], d[1]);
  LatticeCentre c;
  c.tetrahedron = t;
  c.den = 2 * dot(d[0], bc);
  if (c.den == 0) throw std::logic_error("inner_voronoi: a Delaunay tetrahedron is flat");
  const I na = dot(d[0], d[0]), nb = dot(d[1], d[1]), nc = dot(d[2], d[2]);
  for (int k = 0; k < 3; ++k) c.num[k] = na * bc[k] + nb * ca[k] + nc * ab[k];
  return c;
}

namespace {
// An enclosure of a 128-bit integer: its nearest double, widened outwards.
Interval enclose_int(__int128 x) {
  const double d = static_cast<double>(x);
  return {round_down(d), round_up(d)};
}
}  // namespace

std::array<Interval, 3> enclose(const SurfaceSamples& s, const LatticeCentre& c) {
  const Interval den = enclose_int(c.den);
  std::array<Interval, 3> out;
  for (int k = 0; k < 3; ++k)
    out[k] = Interval(s.grid) * (Interval(static_cast<double>(s.lattice[c.tetrahedron[0]][k])) + enclose_int(c.num[k]) / den);
  return out;
}

namespace {
// q * 2^e for the power of two g = 2^e.
void scale_by_grid(mpq_class& q, double g, int times = 1) {
  const long e = static_cast<long>(std::ilogb(g)) * times;
  if (e >= 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
  else mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
}
}  // namespace

namespace {
void set_int128(mpz_ptr z, __int128 x) {
  const unsigned __int128 m = x < 0 ? -static_cast<unsigned __int128>(x) : static_cast<unsigned __int128>(x);
  mpz_set_ui(z, static_cast<unsigned long>(m >> 64));
  mpz_mul_2exp(z, z, 64);
  mpz_add_ui(z, z, static_cast<unsigned long>(m & ~0ul));
  if (x < 0) mpz_neg(z, z);
}

// num / den in lowest terms into q (den > 0 given), with one gcd.
void set_quotient(mpq_ptr q, mpz_ptr num, mpz_ptr den, mpz_ptr gcd) {
  mpz_gcd(gcd, num, den);
  mpz_divexact(mpq_numref(q), num, gcd);
  mpz_divexact(mpq_denref(q), den, gcd);
}
}  // namespace

// x_k = g (n_k D + N_k) / D and R^2 = g^2 |N|^2 / D^2: one gcd each, temporaries reused.
ExactPoint3 exact_point(const SurfaceSamples& s, const LatticeCentre& c, mpq_class* radius_squared) {
  static thread_local struct Temps {
    mpz_t den, num, gcd, n2, t;
    Temps() { mpz_inits(den, num, gcd, n2, t, nullptr); }
    ~Temps() { mpz_clears(den, num, gcd, n2, t, nullptr); }
  } z;
  set_int128(z.den, c.den < 0 ? -c.den : c.den);
  const int flip = c.den < 0 ? -1 : 1;
  std::array<mpq_class, 3> x;
  for (int k = 0; k < 3; ++k) {
    set_int128(z.num, flip * c.num[k]);
    mpz_set_si(z.t, static_cast<long>(s.lattice[c.tetrahedron[0]][k]));
    mpz_addmul(z.num, z.t, z.den);
    set_quotient(x[k].get_mpq_t(), z.num, z.den, z.gcd);
    scale_by_grid(x[k], s.grid);
  }
  if (radius_squared) {
    mpz_set_ui(z.n2, 0);
    for (int k = 0; k < 3; ++k) {
      set_int128(z.t, c.num[k]);
      mpz_addmul(z.n2, z.t, z.t);
    }
    mpz_mul(z.t, z.den, z.den);
    set_quotient(radius_squared->get_mpq_t(), z.n2, z.t, z.gcd);
    scale_by_grid(*radius_squared, s.grid, 2);
  }
  return {x[0], x[1], x[2]};
}

ExactPoint3 exact_sample(const SurfaceSamples& s, std::uint32_t i) {
  std::array<mpq_class, 3> x;
  for (int k = 0; k < 3; ++k) {
    x[k] = s.lattice[i][k];
    scale_by_grid(x[k], s.grid);
  }
  return {x[0], x[1], x[2]};
}

std::size_t cgal_delaunay_cells(const SurfaceSamples& samples) {
  std::vector<K::Point_3> points;
  points.reserve(samples.lattice.size());
  for (std::size_t i = 0; i < samples.lattice.size(); ++i) {
    const P3 p = samples.point(i);
    points.emplace_back(p[0], p[1], p[2]);
  }
  const CGAL::Delaunay_triangulation_3<K> dt(points.begin(), points.end());
  return dt.number_of_finite_cells();
}

InnerVoronoi inner_voronoi(SurfaceSamples samples, const SolidLocator& solid) {
  InnerVoronoi out;
  out.samples = std::move(samples);
  Extractor(&out, solid).run();
  return out;
}

}  // namespace grassfire
