// The exact engine's junction rule on singular curves (Definition 9, 4.2.1; docs/exact-engine.md): BT on
// the synthetic complexes against closed forms (board and fin, book:K, the Y), the
// board-and-fin kink proved at exactly 2 + sqrt2, metamorphic checks, and the discrete
// baseline as an upper bound on complexes with singular edges.
//
// Closed form of the book (derived here; synthetic_complexes.h states it): pages j = 1..k
// of widths w_j and height S, every border edge igniting at 0 (zero radius). Inside page j
// alone, the time at distance u from the spine and height z is m_j(u, z) = min(w_j - u, z,
// S - z) (plane waves from the outer edge, bottom and top; the corners' point sources never
// beat them in a rectangle). At the spine point z, side j arrives at min(w_j, z, S - z); the
// (k-1)-th smallest of these is min(z, S - z, T), T the (k-1)-th smallest width, and no fire
// runs along the spine earlier (that would be min over z' of (BT(z') + |z - z'|), again at
// least min(z, S - z, T) since that function is 1-Lipschitz). From the spine fire enters page
// j at T + u (the plane wave realising T, rotated about the spine; z and S - z enter as
// themselves). So BT_j(u, z) = min(w_j - u, z, S - z, T + u): the widest pages burn from the
// spine near it, where T + u < w_j - u, i.e. u < (w_j - T) / 2 (the Y with widths 2, 3, 4:
// T = 3, the page of width 4 quenches at u = 1/2).
#include <catch2/catch.hpp>

#include <random>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "complex3/synthetic_complexes.h"
#include "number/sqrt_field.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

ExactSum root(const mpq_class& q) {
  ExactSum s = ExactSum::sqrt_of(q);
  s.simplify();
  return s;
}

// The exact engine run on the complex's border ignition.
struct Burned {
  MedialComplex mc;
  std::unique_ptr<ExactBurning> eb;
  explicit Burned(const RawComplex& raw, ExactBurningOptions o = {}) : mc(built(raw)) {
    eb = std::make_unique<ExactBurning>(mc, o);
    eb->add_border_ignition();
    eb->run();
  }
};

// The kinks the engine found, as exact x coordinates (ExactSum) and exact times.
struct Kink {
  ExactSum x, y, z, bt;
};
std::vector<Kink> exact_kinks(ExactBurning& eb, double below) {
  std::vector<Kink> r;
  const WindowStore& s = eb.propagation().store();
  for (const SweepEvent& ev : eb.propagation().events()) {
    if (ev.kind != SweepEvent::Kind::Kink || s.times[ev.time].value.lo > below) continue;
    const EdgePoint& ep = s.edge_points[ev.id];
    REQUIRE(ep.exact >= 0);
    const ExactSum& l = s.exact_times[ep.exact];
    const ExactPoint3& a = eb.complex().vertex(eb.complex().edge(ep.edge).v[0]).exact;
    const ExactPoint3& b = eb.complex().vertex(eb.complex().edge(ep.edge).v[1]).exact;
    auto coord = [&](const mpq_class& p, const mpq_class& q) {
      ExactSum c = l;
      c.scale(q - p);
      c += ExactSum::rational(p);
      c.simplify();
      return c;
    };
    const ExactSum* bt = eb.certifier().exact_expr(ev.time);
    REQUIRE(bt);
    r.push_back({coord(a.x, b.x), coord(a.y, b.y), coord(a.z, b.z), *bt});
  }
  return r;
}

// The edge of N (the singular curve) of triangle t that holds x, or t's first edge.
std::uint32_t edge_on_n(const MedialComplex& mc, std::uint32_t t, const ExactPoint3& x) {
  for (std::uint32_t e : mc.triangle(t).e) {
    if (mc.edge(e).stratum != EdgeStratum::Singular) continue;
    const ExactPoint3 &a = mc.vertex(mc.edge(e).v[0]).exact, &b = mc.vertex(mc.edge(e).v[1]).exact;
    if (std::min(a.x, b.x) <= x.x && x.x <= std::max(a.x, b.x)) return e;
  }
  return mc.triangle(t).e[0];
}

bool on_singular_curve(const MedialComplex& mc, std::uint32_t v) {
  for (std::uint32_t e : mc.vertex_edges(v))
    if (mc.edge(e).stratum == EdgeStratum::Singular) return true;
  return false;
}

double book_bt(const BookOptions& o, double w, double u, double z) {
  std::vector<long> ws = o.widths;
  std::sort(ws.begin(), ws.end());
  const double T = static_cast<double>(ws[ws.size() - 2]), S = book_height(o);
  return std::min({w - u, z, S - z, T + u});
}

}  // namespace

TEST_CASE("board and fin: BT equals the closed form of 4.2.1 everywhere it holds", "[exact3][junction]") {
  BoardFinOptions o;
  o.extent = 6;
  Burned b(board_fin(o));
  const auto& st = b.eb->propagation().stats();
  CHECK(b.eb->certification().uncertified == 0);
  CHECK(st.uncertified_breaks == 0);
  CHECK(st.kinks >= 1);  // 2 + sqrt2, and kinks near the truncated far end (times above E)
  CHECK(st.merges > 0);
  std::mt19937 rng(23);
  int checked = 0, beyond_kink = 0;
  for (std::uint32_t t = 0; t < b.mc.triangle_count(); ++t)
    for (const ExactPoint3& x : sample_triangle(b.mc, t, 4, rng)) {
      const double expected = board_fin_burning_time(to_vec(x));
      if (expected > o.extent - 1e-9) continue;  // the truncation's far end matters there
      const bool on_n = x.x == x.y && sgn(x.z) == 0 && x.x >= 1;
      const Interval bt = on_n ? b.eb->edge_burn_time(edge_on_n(b.mc, t, x), x) : b.eb->burn_time(t, x);
      CAPTURE(x.x.get_d(), x.y.get_d(), x.z.get_d(), bt.lo, bt.hi, expected);
      CHECK(bt.lo - 1e-12 <= expected);
      CHECK(expected <= bt.hi + 1e-12);
      CHECK(bt.hi - bt.lo <= 1e-10);  // widened by undecided memberships near wedge rays
      ++checked;
      beyond_kink += sgn(x.z) == 0 && x.y > x.x && x.x.get_d() > 2 + std::sqrt(2.0);
    }
  CHECK(checked > 300);
  CHECK(beyond_kink > 5);  // the region that only the kink's point source reaches
}

TEST_CASE("board and fin: the kink is proved at exactly 2 + sqrt2", "[exact3][junction]") {
  for (int g : {1, 2}) {
    BoardFinOptions o;
    o.extent = 6;
    o.cells_per_unit = g;
    Burned b(board_fin(o));
    // Only one below E (the closed form's range); the truncation adds kinks near (E, E, 0).
    const std::vector<Kink> kinks = exact_kinks(*b.eb, o.extent);
    REQUIRE(kinks.size() == 1);
    const ExactSum k = ExactSum::rational(2) + root(2);
    CHECK(exact_sign(kinks[0].x - k) == 0);
    CHECK(exact_sign(kinks[0].y - k) == 0);
    CHECK(exact_sign(kinks[0].z) == 0);
    CHECK(exact_sign(kinks[0].bt - k) == 0);  // BT at the kink: s = sqrt2 (s - 1) = 2 + sqrt2
  }
}

TEST_CASE("book:K and the Y: BT = min(w - u, z, S - z, T + u) on every page", "[exact3][junction]") {
  const std::vector<BookOptions> books = {y_junction_options(2), BookOptions{4, {1, 2, 2, 3}, 0, 1},
                                          BookOptions{5, {2, 3, 1, 4, 2}, 0, 1}, BookOptions{3, {2, 2, 2}, 0, 1}};
  for (const BookOptions& o : books) {
    Burned b(book(o));
    CAPTURE(o.pages);
    CHECK(b.eb->certification().uncertified == 0);
    std::mt19937 rng(29);
    int below_own = 0;
    for (std::uint32_t t = 0; t < b.mc.triangle_count(); ++t) {
      mpq_class w2 = 0;
      for (std::uint32_t t2 : b.mc.sheets()[b.mc.triangle(t).sheet].triangles)
        for (std::uint32_t v : b.mc.triangle(t2).v) {
          const ExactPoint3& p = b.mc.vertex(v).exact;
          w2 = std::max(w2, mpq_class(p.x * p.x + p.y * p.y));
        }
      const double w = std::sqrt(w2.get_d());
      for (const ExactPoint3& x : sample_triangle(b.mc, t, 3, rng)) {
        const double u = std::hypot(x.x.get_d(), x.y.get_d()), z = x.z.get_d();
        const double expected = book_bt(o, w, u, z);
        if (sgn(x.x) == 0 && sgn(x.y) == 0) continue;  // the spine: checked below
        const Interval bt = b.eb->burn_time(t, x);
        CAPTURE(u, z, w, bt.lo, bt.hi, expected);
        CHECK(bt.lo - 1e-12 <= expected);
        CHECK(expected <= bt.hi + 1e-12);
        CHECK(bt.hi - bt.lo <= 1e-10);
        below_own += expected < std::min({w - u, z, book_height(o) - z}) - 1e-9;
        // Exact where every candidate window is exact (planar pages, rational crossings).
        if (const auto e = b.eb->exact_burn_time(t, x)) CHECK(std::abs(e->to_double() - expected) < 1e-12);
      }
    }
    // The spine: min(z, S - z, T) by the junction rule (edge_burn_time).
    std::vector<long> ws = o.widths;
    std::sort(ws.begin(), ws.end());
    for (std::uint32_t e = 0; e < b.mc.edge_count(); ++e) {
      if (b.mc.edge(e).stratum != EdgeStratum::Singular) continue;
      const ExactPoint3 &p = b.mc.vertex(b.mc.edge(e).v[0]).exact, &q = b.mc.vertex(b.mc.edge(e).v[1]).exact;
      const ExactPoint3 m{(p.x + q.x) / 2, (p.y + q.y) / 2, (p.z + q.z) / 2};
      const double z = m.z.get_d(), expected = std::min({z, book_height(o) - z, double(ws[ws.size() - 2])});
      const Interval bt = b.eb->edge_burn_time(e, m);
      CAPTURE(z, bt.lo, bt.hi, expected);
      CHECK(bt.lo - 1e-12 <= expected);
      CHECK(expected <= bt.hi + 1e-12);
    }
    const bool spine_matters = o.widths != std::vector<long>{2, 2, 2};
    CHECK((below_own > 0) == spine_matters);  // the spine's fire realises BT somewhere
  }
}

// Walls (fronts stop at singular curves) leave out the fire the curves emit, so off the
// curves they bound BT from above; on a curve they give its first arrival instead of its
// (k-1)-th, which is earlier.
TEST_CASE("singular walls stay an upper bound of the junction rule off the curves", "[exact3][junction]") {
  ExactBurningOptions walls;
  walls.singular_walls = true;
  for (const RawComplex& raw : {board_fin(), book(BookOptions{3, {2, 2, 6}, 0, 1}), box_medial_axis(4, 3, 1, 2)}) {
    Burned j(raw), w(raw, walls);
    int lower = 0;
    for (std::uint32_t v = 0; v < j.mc.vertex_count(); ++v) {
      if (!j.mc.vertex_edges(v).empty() && on_singular_curve(j.mc, v)) continue;  // the curve burns later
      const Interval a = j.eb->vertex_burn_time(v), b = w.eb->vertex_burn_time(v);
      CHECK(a.lo <= b.hi);
      lower += a.hi < b.lo;
    }
    CHECK(lower > 0);  // the junction rule changes BT somewhere on each
    CHECK(j.eb->propagation().stats().merges > 0);
    CHECK(w.eb->propagation().stats().merges == 0);
  }
}

TEST_CASE("box medial axis: the rectangle burns from its singular border at c sqrt2", "[exact3][junction]") {
  for (const auto& [a, b, c, n] : {std::array<long, 4>{4, 3, 1, 2}, std::array<long, 4>{5, 5, 2, 1}}) {
    Burned box(box_medial_axis(a, b, c, static_cast<int>(n)));
    CHECK(box.eb->certification().uncertified == 0);
    std::mt19937 rng(31);
    int rectangle = 0;
    for (std::uint32_t t = 0; t < box.mc.triangle_count(); ++t)
      for (const ExactPoint3& x : sample_triangle(box.mc, t, 3, rng)) {
        const double expected = box_medial_axis_burning_time(a, b, c, to_vec(x));
        bool on_curve = false;
        for (std::uint32_t e : box.mc.triangle(t).e)
          if (box.mc.edge(e).stratum == EdgeStratum::Singular) {
            const ExactPoint3 &p = box.mc.vertex(box.mc.edge(e).v[0]).exact, &q = box.mc.vertex(box.mc.edge(e).v[1]).exact;
            on_curve = on_curve || (cross(q - p, x - p) == ExactPoint3{});
          }
        if (on_curve) continue;  // the curve's value: edge_burn_time (the book test checks it)
        const Interval bt = box.eb->burn_time(t, x);
        CAPTURE(a, b, c, x.x.get_d(), x.y.get_d(), x.z.get_d(), bt.lo, bt.hi, expected);
        CHECK(bt.lo - 1e-12 <= expected);
        CHECK(expected <= bt.hi + 1e-12);
        rectangle += sgn(x.z) == 0 && std::abs(x.x.get_d()) < a - c && std::abs(x.y.get_d()) < b - c;
      }
    CHECK(rectangle > 3);
  }
}
