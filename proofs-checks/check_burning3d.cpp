// check_burning3d.cpp -- chapter 4 on the discrete baseline: Prop. 7, Lemma 2, Definition
// 10 and Prop. 4 (with an allowance of h), on synthetic, generated and real complexes.
//
// Corpora: synthetic = the reference complexes of synthetic_complexes.h; generated =
// seeded random books, box medial axes and closed octahedra with flaps and hairs; real =
// the .ma files in data/ma (exact box medial axes) and the exact medial axes of the convex
// meshes in data/meshes and of cubes cut by planes with Pythagorean normals
// (kernel/complex3/builders/convex_polyhedron_axis.h). Distances for Prop. 4: within a planar sheet, the exact geodesic
// |x - y| when the segment xy stays in the sheet (tested against the sheet's border and
// singular edges in its plane); else, and on curved sheets, the baseline's graph distance
// inside the sheet, an upper bound of the geodesic; along a singular curve, the exact
// arclength. See each row's note for how many pairs used which.
#include <algorithm>
#include <cmath>
#include <dirent.h>
#include <map>
#include <queue>
#include <random>
#include <set>

#include "burn3/burn_sets.h"
#include "burn3/discrete_burning.h"
#include "burn3/steiner_graph.h"
#include "check_registry.h"
#include "complex3/builders/convex_polyhedron_axis.h"
#include "complex3/closed_subcomplex.h"
#include "complex3/complex_builder.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_ma.h"
#include "io/mesh_io.h"

namespace grassfire::checks {
namespace {

struct Instance {
  std::string name;
  MedialComplex mc;
};

struct Corpus {
  std::string name;
  std::vector<Instance> instances;
};

RawComplex octahedron_with_flaps(std::mt19937& rng, int scale) {
  ComplexBuilder b("octahedron+flaps");
  const RawComplex oct = octahedron_surface();
  auto v = [&](const ExactPoint3& p) { return b.vertex(mpq_class(scale) * p); };
  for (const auto& t : oct.triangles) b.triangle(v(oct.vertices[t[0]]), v(oct.vertices[t[1]]), v(oct.vertices[t[2]]));
  std::bernoulli_distribution coin(0.4);
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const auto& t : oct.triangles)
    for (int i = 0; i < 3; ++i) {  // a flap outside the edge t[i] t[i+1], in the plane of it and O
      const std::uint32_t a = std::min(t[i], t[(i + 1) % 3]), c = std::max(t[i], t[(i + 1) % 3]);
      if (!seen.insert({a, c}).second || !coin(rng)) continue;
      b.triangle(v(oct.vertices[a]), v(oct.vertices[c]), v(oct.vertices[a] + oct.vertices[c]));
    }
  for (const ExactPoint3& p : oct.vertices)
    if (coin(rng)) b.segment(v(p), v(mpq_class(2) * p));  // a hair
  return b.take();
}

void add(Corpus& c, const std::string& name, const RawComplex& raw) {
  MedialComplex mc(raw);
  mc.validate();
  c.instances.push_back({name, std::move(mc)});
}

std::vector<Corpus> corpora(const CheckContext& ctx) {
  Corpus syn{"synthetic", {}}, gen{"generated (seeded)", {}}, real{"real (data/ma)", {}},
      convex{"convex polyhedra (builder)", {}};
  add(syn, "board-fin", board_fin({8, 1}));
  add(syn, "board-cylinder", board_cylinder({16, 3, 4, 2.0, 6}));
  for (int k = 2; k <= (ctx.quick ? 4 : 6); ++k) add(syn, "book:" + std::to_string(k), book({k, {}, 0, 1}));
  add(syn, "y-junction", y_junction(1));
  add(syn, "tetrahedron", tetrahedron_surface());
  add(syn, "octahedron", octahedron_surface());
  add(syn, "double-cone", pinched_double_cone(8));
  add(syn, "tetrahedron-flap", tetrahedron_with_flap());
  std::mt19937 rng(2011);
  const int n = ctx.quick ? 3 : 12;
  for (int i = 0; i < n; ++i) {
    std::uniform_int_distribution<int> pages(2, 6), width(1, 4), dim(1, 6);
    BookOptions o;
    o.pages = pages(rng);
    for (int j = 0; j < o.pages; ++j) o.widths.push_back(width(rng));
    o.cells_per_unit = 1;
    add(gen, "random book " + std::to_string(i), book(o));
    long d[3] = {dim(rng), dim(rng), dim(rng)};
    std::sort(d, d + 3, std::greater<long>());
    if (d[1] == d[2]) ++d[0], ++d[1];
    add(gen, "random box " + std::to_string(i), box_medial_axis(d[0], d[1], d[2], 1 + i % 2));
    add(gen, "octahedron+flaps " + std::to_string(i), octahedron_with_flaps(rng, 2));
  }
  if (DIR* dir = opendir((ctx.data_dir + "/ma").c_str())) {
    std::vector<std::string> files;
    while (dirent* e = readdir(dir)) {
      const std::string f = e->d_name;
      if (f.size() > 3 && f.substr(f.size() - 3) == ".ma") files.push_back(f);
    }
    closedir(dir);
    std::sort(files.begin(), files.end());
    for (const std::string& f : files) add(real, f, read_ma(ctx.data_dir + "/ma/" + f));
  }
  for (const char* mesh : {"cube.off", "octahedron.off"}) {
    const std::string path = ctx.data_dir + "/meshes/" + mesh;
    add(convex, mesh, convex_polyhedron_axis(convex_polyhedron_from_mesh(read_triangle_mesh(path))).complex);
  }
  // The cube [-2, 2]^3 cut by three planes with Pythagorean normals (|n| = 5) and offsets
  // 6..9: every |n|^2 is a square, so the builder is exact (s = 1). A fixed list: some
  // random cuts crash convex_polyhedron_axis (reported to the lead; e.g. the cube with
  // 3y - 4z <= 9, 4x + 3z <= 6, 4x - 3z <= 7).
  const int pythagorean[6][3] = {{3, 4, 0}, {0, 3, 4}, {4, 0, 3}, {-3, 4, 0}, {0, -3, 4}, {4, 0, -3}};
  const int cuts[8][3][2] = {{{0, 7}, {2, 8}, {4, 6}}, {{1, 7}, {3, 8}, {5, 9}}, {{0, 6}, {1, 7}, {2, 8}},
                             {{3, 9}, {4, 7}, {5, 6}}, {{0, 8}, {4, 8}, {5, 7}}, {{1, 6}, {2, 9}, {3, 7}},
                             {{0, 9}, {1, 9}, {2, 9}}, {{2, 7}, {3, 6}, {4, 9}}};
  for (int i = 0; i < (ctx.quick ? 2 : 8); ++i) {
    ConvexPolyhedron p;
    p.source = "cut cube " + std::to_string(i);
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {1, -1}) {
        mpq_class n[3] = {0, 0, 0};
        n[axis] = sign;
        p.planes.push_back({n[0], n[1], n[2], 2});
      }
    for (const auto& cut : cuts[i]) {
      const int* d = pythagorean[cut[0]];
      p.planes.push_back({d[0], d[1], d[2], cut[1]});
    }
    add(convex, p.source, convex_polyhedron_axis(p).complex);
  }
  return {std::move(syn), std::move(gen), std::move(real), std::move(convex)};
}

double spacing_for(const MedialComplex& mc, bool quick) {
  Vec3d lo = mc.vertex(0).approx, hi = lo;
  for (const ComplexVertex& v : mc.vertices())
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], v.approx[i]), hi[i] = std::max(hi[i], v.approx[i]);
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / (quick ? 24 : 48);
}

double bt_at(const SteinerGraph& g, const DiscreteBurning& d, std::uint32_t node) {
  return g.is_vertex(node) ? d.vertex_bt[node] : d.steiner_bt[node - g.vertex_count()];
}

// Prop. 7: graph points with BT = infinity against the peeled maximal closed subcomplex.
std::uint64_t prop7_mismatches(const SteinerGraph& g, const DiscreteBurning& d, const ClosedSubcomplex& k) {
  std::uint64_t bad = 0;
  for (std::uint32_t node = 0; node < g.node_count(); ++node) {
    const bool closed = g.is_vertex(node) ? k.vertex[node] : k.edge[g.edge_of(node)];
    bad += (std::isinf(bt_at(g, d, node)) != closed) ? 1 : 0;
  }
  return bad;
}

struct Tally {
  std::uint64_t instances = 0, points = 0, violations = 0;
  double worst = 0;
  std::uint64_t exact_pairs = 0, bound_pairs = 0;
};

// Lemma 2 and Definition 10 on the burning sets recomputed from witnesses.
void check_burn_sets(const SteinerGraph& g, const DiscreteBurning& d, Tally& lemma2, Tally& def10) {
  const BurnSets sets(g, d);
  std::vector<double> times;
  for (std::uint32_t node = 0; node < g.node_count(); ++node)
    if (std::isfinite(bt_at(g, d, node))) times.push_back(bt_at(g, d, node));
  std::sort(times.begin(), times.end());
  std::vector<double> samples;
  for (int q = 0; q <= 16 && !times.empty(); ++q) samples.push_back(times[(times.size() - 1) * q / 16]);
  for (std::uint32_t node = 0; node < g.node_count(); ++node) {
    bool was_in = false;
    for (double t : samples) {
      const bool in = sets.contains(node, t);
      if (was_in && !in) ++lemma2.violations;
      was_in = was_in || in;
      ++lemma2.points;
    }
    const double first = sets.first_time(node), bt = bt_at(g, d, node);
    ++def10.points;
    if (first != bt && !(std::isinf(first) && std::isinf(bt))) {
      ++def10.violations;
      def10.worst = std::max(def10.worst, std::isfinite(first - bt) ? std::abs(first - bt) : 1e300);
    }
  }
}

// The sheet whose open part M2 contains the graph point, or kNoIndex.
std::uint32_t sheet_of(const SteinerGraph& g, std::uint32_t node) {
  const MedialComplex& mc = g.complex();
  if (g.is_vertex(node)) {
    const VertexKind k = mc.vertex(node).kind;
    return (k == VertexKind::Interior || k == VertexKind::Border) ? mc.triangle(mc.vertex_triangles(node)[0]).sheet : kNoIndex;
  }
  const std::uint32_t e = g.edge_of(node);
  const EdgeStratum s = mc.edge(e).stratum;
  return (s == EdgeStratum::Manifold || s == EdgeStratum::Border) ? mc.triangle(mc.edge_triangles(e)[0]).sheet : kNoIndex;
}

double orient2(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Is the segment xy inside the planar sheet? 1 yes, 0 no, -1 too close to decide in doubles.
int segment_in_sheet(const MedialComplex& mc, std::uint32_t sheet, const Vec3d& x, const Vec3d& y) {
  const PlanarFrame& f = mc.frames()[mc.sheets()[sheet].frame];
  const Vec3d o = to_double(f.origin), e1 = to_double(f.e1), e2 = to_double(f.e2);
  const double n1 = f.e1_norm2.get_d(), n2 = f.e2_norm2.get_d();
  auto local = [&](const Vec3d& p) {
    const Vec3d d = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    return std::array<double, 2>{(d[0] * e1[0] + d[1] * e1[1] + d[2] * e1[2]) / n1,
                                 (d[0] * e2[0] + d[1] * e2[1] + d[2] * e2[2]) / n2};
  };
  const auto px = local(x), py = local(y);
  const double scale = 1e-9 * (std::abs(px[0]) + std::abs(px[1]) + std::abs(py[0]) + std::abs(py[1]) + 1);
  for (std::uint32_t t : mc.sheets()[sheet].triangles)
    for (std::uint32_t e : mc.triangle(t).e) {
      if (mc.edge(e).stratum == EdgeStratum::Manifold) continue;  // inside the sheet
      const auto a = local(mc.vertex(mc.edge(e).v[0]).approx), b = local(mc.vertex(mc.edge(e).v[1]).approx);
      const double o1 = orient2(a, b, px), o2 = orient2(a, b, py), o3 = orient2(px, py, a), o4 = orient2(px, py, b);
      if (o1 * o2 >= 0) continue;
      if (std::abs(o3) < scale || std::abs(o4) < scale) return -1;  // through an end of a border edge
      if (o3 * o4 < 0) return 0;
    }
  return 1;
}

// Prop. 4 inside sheets: from sampled sources, a Dijkstra over graph moves between points of
// the same sheet up to radius r gives d_graph >= d; the straight distance is exact when the
// segment stays in a planar sheet.
void check_prop4_sheets(const SteinerGraph& g, const DiscreteBurning& d, std::mt19937& rng, int sources, Tally& tally) {
  const MedialComplex& mc = g.complex();
  const double h = g.spacing(), radius = 4 * h;
  std::uniform_int_distribution<std::uint64_t> pick(0, g.node_count() - 1);
  for (int s = 0, tries = 0; s < sources && tries < 50 * sources; ++tries) {
    const auto x = static_cast<std::uint32_t>(pick(rng));
    const std::uint32_t sheet = sheet_of(g, x);
    if (sheet == kNoIndex || !std::isfinite(bt_at(g, d, x))) continue;
    ++s;
    std::map<std::uint32_t, double> dist{{x, 0.0}};
    std::priority_queue<std::pair<double, std::uint32_t>, std::vector<std::pair<double, std::uint32_t>>, std::greater<>> q;
    q.push({0.0, x});
    while (!q.empty()) {
      const auto [du, u] = q.top();
      q.pop();
      if (du > dist[u]) continue;
      g.for_each_move(u, [&](std::uint32_t y, std::uint32_t, double len) {
        if (du + len > radius || sheet_of(g, y) != sheet) return;
        auto it = dist.find(y);
        if (it == dist.end() || du + len < it->second) {
          dist[y] = du + len;
          q.push({du + len, y});
        }
      });
    }
    const Vec3d px = g.position(x);
    for (const auto& [y, dg] : dist) {
      if (y == x || !std::isfinite(bt_at(g, d, y))) continue;
      double dd = dg;
      const Vec3d py = g.position(y);
      if (mc.sheets()[sheet].planar && segment_in_sheet(mc, sheet, px, py) == 1) {
        dd = std::hypot(px[0] - py[0], px[1] - py[1], px[2] - py[2]);
        ++tally.exact_pairs;
      } else {
        ++tally.bound_pairs;
      }
      const double excess = std::abs(bt_at(g, d, x) - bt_at(g, d, y)) - dd;
      ++tally.points;
      tally.worst = std::max(tally.worst, excess);
      if (excess > h) ++tally.violations;
    }
  }
}

// Prop. 4 along singular curves: maximal chains of singular edges through M1 vertices,
// pairs within 32 points, distance = arclength (exact).
void check_prop4_curves(const SteinerGraph& g, const DiscreteBurning& d, Tally& tally) {
  const MedialComplex& mc = g.complex();
  std::vector<bool> used(mc.edge_count(), false);
  for (std::uint32_t e0 = 0; e0 < mc.edge_count(); ++e0) {
    if (used[e0] || mc.edge(e0).stratum != EdgeStratum::Singular) continue;
    // Walk back to the chain's start, then forward collecting (arclength, node).
    std::uint32_t at = mc.edge(e0).v[0], e = e0;
    for (std::size_t guard = 0; mc.vertex(at).kind == VertexKind::SingularCurve && guard < mc.edge_count(); ++guard) {
      std::uint32_t next = kNoIndex;
      for (std::uint32_t f : mc.vertex_edges(at))
        if (f != e && mc.edge(f).stratum == EdgeStratum::Singular) next = f;
      if (next == kNoIndex || next == e0) break;
      e = next;
      at = mc.edge(e).v[0] == at ? mc.edge(e).v[1] : mc.edge(e).v[0];
    }
    std::vector<std::pair<double, std::uint32_t>> pts;
    double t = 0;
    for (std::size_t guard = 0; guard <= mc.edge_count(); ++guard) {
      if (used[e]) break;
      used[e] = true;
      const bool forward = mc.edge(e).v[0] == at;
      const std::uint32_t n = g.steiner_count(e);
      for (std::uint32_t k = 1; k <= n; ++k)
        pts.push_back({t + mc.edge(e).length * k / (n + 1), g.steiner_node(e, forward ? k : n + 1 - k)});
      t += mc.edge(e).length;
      at = forward ? mc.edge(e).v[1] : mc.edge(e).v[0];
      if (mc.vertex(at).kind != VertexKind::SingularCurve) break;
      pts.push_back({t, at});
      std::uint32_t next = kNoIndex;
      for (std::uint32_t f : mc.vertex_edges(at))
        if (f != e && mc.edge(f).stratum == EdgeStratum::Singular) next = f;
      if (next == kNoIndex) break;
      e = next;
    }
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size() && j <= i + 32; ++j) {
        const double bi = bt_at(g, d, pts[i].second), bj = bt_at(g, d, pts[j].second);
        if (!std::isfinite(bi) || !std::isfinite(bj)) continue;
        const double excess = std::abs(bi - bj) - (pts[j].first - pts[i].first);
        ++tally.points;
        ++tally.exact_pairs;
        tally.worst = std::max(tally.worst, excess);
        if (excess > 1e-9) ++tally.violations;
      }
  }
}

CheckRow row(const std::string& prop, const std::string& corpus, const Tally& t, const std::string& unit,
             double worst, bool pass, const std::string& note) {
  CheckRow r;
  r.proposition = prop;
  r.corpus = corpus;
  r.instances = t.instances;
  r.points = t.points;
  r.worst_violation = worst;
  r.unit = unit;
  r.pass = pass;
  r.note = note;
  return r;
}

std::vector<CheckRow> check_burning3d(const CheckContext& ctx) {
  std::vector<CheckRow> rows;
  std::mt19937 rng(42);
  for (const Corpus& c : corpora(ctx)) {
    if (c.instances.empty()) continue;
    Tally p7, l2, d10, p4s, p4c;
    std::size_t closed_instances = 0;
    double worst_h = 0;
    for (const Instance& in : c.instances) {
      const double h = spacing_for(in.mc, ctx.quick);
      worst_h = std::max(worst_h, h);
      const SteinerGraph g(in.mc, h, 20'000'000);
      const DiscreteBurning d = burn_discrete(in.mc, {h});
      const ClosedSubcomplex k = maximal_closed_subcomplex(in.mc);
      closed_instances += k.triangles > 0 ? 1 : 0;
      p7.violations += prop7_mismatches(g, d, k);
      p7.points += g.node_count();
      check_burn_sets(g, d, l2, d10);
      check_prop4_sheets(g, d, rng, ctx.quick ? 20 : 80, p4s);
      check_prop4_curves(g, d, p4c);
      for (Tally* t : {&p7, &l2, &d10, &p4s, &p4c}) ++t->instances;
    }
    const std::string hs = "h = bounding diagonal / " + std::string(ctx.quick ? "24" : "48");
    rows.push_back(row("Prop 7 (BT = inf exactly on the maximal closed subcomplex)", c.name, p7, "points",
                       static_cast<double>(p7.violations), p7.violations == 0,
                       "closed subcomplex peeled combinatorially; non-empty in " + std::to_string(closed_instances) +
                           " instances; " + hs));
    rows.push_back(row("Lemma 2 (B(s) within B(t) for s <= t)", c.name, l2, "points", static_cast<double>(l2.violations),
                       l2.violations == 0, "B(t) recomputed from witnesses BT(y) + |xy| at 17 quantile times"));
    rows.push_back(row("Def. 10 (BT = inf {t : x in B(t)}) on the baseline", c.name, d10, "length", d10.worst,
                       d10.violations == 0, "first time of the recomputed burning set vs the event loop's BT"));
    rows.push_back(row("Prop 4 in a sheet (|BT(x) - BT(y)| <= d + h)", c.name, p4s, "length", std::max(0.0, p4s.worst),
                       p4s.violations == 0,
                       std::to_string(p4s.exact_pairs) + " pairs with exact d (planar, segment in sheet), " +
                           std::to_string(p4s.bound_pairs) + " with graph distance (upper bound); pairs within 4h; " +
                           "worst shown without the allowance h"));
    rows.push_back(row("Prop 4 on singular curves (|BT(x) - BT(y)| <= arclength)", c.name, p4c, "length",
                       std::max(0.0, p4c.worst), p4c.violations == 0,
                       p4c.points == 0 ? "no singular curves" : "exact arclength, pairs within 32 points"));
  }
  return rows;
}

GF_REGISTER_CHECK("burning3d", check_burning3d);

}  // namespace
}  // namespace grassfire::checks
