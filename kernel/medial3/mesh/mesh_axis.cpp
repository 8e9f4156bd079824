// mesh_axis.cpp -- see mesh_axis.h.
#include "medial3/mesh/mesh_axis.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "medial3/mesh/axis_pruning.h"
#include "medial3/mesh/inner_voronoi.h"
#include "medial3/mesh/mesh_checks.h"
#include "medial3/mesh/mesh_samples.h"
#include "geometry3/exact_predicates3.h"
#include "support/cpu_clock.h"
#include "medial3/mesh/mesh_repair.h"
#include "number/exact_sum.h"

namespace grassfire {

namespace {



// The angle test of a Voronoi vertex x against two samples u, v on its empty sphere:
// |u - v|^2 >= kappa R(x)^2. In lattice units R(x) = |N| / |D| (the centre is
// n_0 + N / D and n_0 lies on the sphere), so the test is D^2 |u - v|^2 >= kappa |N|^2:
// an interval filter, then exact integers.
class AngleTest {
 public:
  AngleTest(const InnerVoronoi& vor, double angle_degrees)
      : vor_(vor), kappa_(2 * (1 - std::cos(angle_degrees * M_PI / 180))), exact_kappa_(kappa_) {}

  bool wide(std::uint32_t x, std::uint32_t u, std::uint32_t v) const {
    if (kappa_ <= 0) return true;
    const auto& a = vor_.samples.lattice[u];
    const auto& b = vor_.samples.lattice[v];
    const LatticeCentre& c = vor_.vertices[x].centre;
    std::int64_t d2 = 0;  // < 3 * 2^54
    for (int k = 0; k < 3; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
    Interval n2(0.0);
    for (int k = 0; k < 3; ++k) n2 += square(around(c.num[k]));
    const int sign = certified_sign(square(around(c.den)) * Interval(static_cast<double>(d2)) - Interval(kappa_) * n2);
    if (sign != kUndecided) return sign >= 0;
    mpq_class nn = 0;
    for (int k = 0; k < 3; ++k) nn += to_mpq(c.num[k]) * to_mpq(c.num[k]);
    const mpq_class den = to_mpq(c.den);
    return sgn(den * den * mpq_class(d2) - exact_kappa_ * nn) >= 0;
  }

 private:
  static Interval around(__int128 x) {
    const double d = static_cast<double>(x);
    return {round_down(d), round_up(d)};
  }
  const InnerVoronoi& vor_;
  double kappa_;
  mpq_class exact_kappa_;
};

// The separation test of two samples: |u - v| >= lambda max(h_u, h_v), h the spacing of
// the triangles a sample lies on. Exact: |u - v|^2 is an integer in lattice units, compared
// with the ceiling of the double threshold.
class SeparationTest {
 public:
  SeparationTest(const InnerVoronoi& vor, const std::vector<double>& triangle_spacing, double lambda)
      : vor_(vor), spacing_(vor.samples.lattice.size(), INFINITY), lambda_(lambda) {
    for (std::size_t t = 0; t + 1 < vor.samples.offset.size(); ++t)
      for (std::uint32_t i = vor.samples.offset[t]; i < vor.samples.offset[t + 1]; ++i) {
        double& h = spacing_[vor.samples.on_triangle[i]];
        h = std::min(h, triangle_spacing[t] / vor.samples.grid);
      }
  }

  bool apart(std::uint32_t u, std::uint32_t v) const {
    if (lambda_ <= 0) return true;
    const auto& a = vor_.samples.lattice[u];
    const auto& b = vor_.samples.lattice[v];
    std::int64_t d2 = 0;  // < 3 * 2^54
    for (int k = 0; k < 3; ++k) d2 += (a[k] - b[k]) * (a[k] - b[k]);
    const double h = lambda_ * std::max(spacing_[u], spacing_[v]);
    const double threshold = std::ceil(h * h);
    return threshold < 0x1p62 && d2 >= static_cast<std::int64_t>(threshold);
  }

 private:
  const InnerVoronoi& vor_;
  std::vector<double> spacing_;  // per sample, in lattice units
  double lambda_;
};

// The tests of the pruning: which polygons and edges may not be collapsed away.
struct KeepTests {
  const InnerVoronoi& vor;
  const AngleTest& angle;
  const SeparationTest& separation;

  bool polygon(std::uint32_t i) const {
    if (!separation.apart(vor.pq[i][0], vor.pq[i][1])) return false;
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k)
      if (!angle.wide(vor.polygons.ring(i)[k], vor.pq[i][0], vor.pq[i][1])) return false;
    return true;
  }

  bool edge(const EdgeOrigin& o) const {
    std::array<std::uint32_t, 2> ends;
    std::array<std::uint32_t, 3> t;
    if (o.segment) {
      ends = vor.segments[o.index].v;
      t = vor.segments[o.index].triangle;
    } else {
      ends = vor.polygons.side(o.index, o.side);
      t = {vor.pq[o.index][0], vor.pq[o.index][1], vor.apex[vor.polygons.offset[o.index] + o.side]};
    }
    if (!separation.apart(t[0], t[1]) && !separation.apart(t[1], t[2]) && !separation.apart(t[2], t[0])) return false;
    for (std::uint32_t x : ends)
      if (!angle.wide(x, t[0], t[1]) && !angle.wide(x, t[1], t[2]) && !angle.wide(x, t[2], t[0])) return false;
    return true;
  }
};

PrunedComplex prune(const InnerVoronoi& vor, const KeepTests& keep) {
  PolygonalComplex complex;
  complex.vertex_count = vor.vertices.size();
  complex.polygons = vor.polygons;
  for (const auto& s : vor.segments) complex.segments.push_back(s.v);
  return prune_by_collapse(complex, [&](std::uint32_t i) { return keep.polygon(i); },
                           [&](const EdgeOrigin& o) { return keep.edge(o); });
}

// The kept cells with compact vertex ids: fans of the polygons, bare edges, and every
// kept vertex (isolated ones are components of the axis).
struct AxisCells {
  std::vector<std::uint32_t> vertex_id;  // per Voronoi vertex, UINT32_MAX when dropped
  std::vector<std::uint32_t> voronoi_vertex;
  PolygonRings rings;  // the kept polygons, in compact vertex ids
  std::vector<std::array<std::uint32_t, 2>> segments;
  std::vector<std::uint32_t> polygons;  // kept polygon ids
};

AxisCells axis_cells(const InnerVoronoi& vor, const PrunedComplex& pruned) {
  AxisCells out;
  out.vertex_id.assign(vor.vertices.size(), UINT32_MAX);
  for (std::uint32_t v = 0; v < vor.vertices.size(); ++v)
    if (pruned.vertex_kept[v]) {
      out.vertex_id[v] = static_cast<std::uint32_t>(out.voronoi_vertex.size());
      out.voronoi_vertex.push_back(v);
    }
  for (std::uint32_t i = 0; i < vor.polygons.size(); ++i) {
    if (!pruned.polygon_kept[i]) continue;
    out.polygons.push_back(i);
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k) out.rings.vertex.push_back(out.vertex_id[vor.polygons.ring(i)[k]]);
    out.rings.close();
  }
  for (const auto& e : pruned.bare_edges) out.segments.push_back({out.vertex_id[e[0]], out.vertex_id[e[1]]});
  return out;
}

// Exact coordinates and R^2 of the kept vertices; border rules on the polygons' free sides.
RawComplex assemble(const InnerVoronoi& vor, const AxisCells& cells, const std::string& source) {
  RawComplex raw;
  raw.source = source + " (inner Voronoi medial axis)";
  raw.vertices.reserve(cells.voronoi_vertex.size());
  raw.radius_squared.reserve(cells.voronoi_vertex.size());
  raw.triangles.reserve(cells.rings.vertex.size());
  for (std::uint32_t v : cells.voronoi_vertex) {
    mpq_class r2;
    raw.vertices.push_back(exact_point(vor.samples, vor.vertices[v].centre, &r2));
    raw.radius_squared.push_back(r2);
  }
  for (std::size_t i = 0; i < cells.rings.size(); ++i) {  // fans: the polygons are strictly convex
    const std::uint32_t* ring = cells.rings.ring(i);
    for (std::uint32_t k = 1; k + 1 < cells.rings.ring_size(i); ++k) raw.triangles.push_back({ring[0], ring[k], ring[k + 1]});
  }
  raw.segments = cells.segments;
  std::vector<std::uint64_t> sides;
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  };
  for (std::uint32_t i : cells.polygons)
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k) {
      const auto [a, b] = vor.polygons.side(i, k);
      sides.push_back(key(a, b));
    }
  std::sort(sides.begin(), sides.end());
  for (std::uint32_t i : cells.polygons)
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k) {
      const auto [a, b] = vor.polygons.side(i, k);
      const auto range = std::equal_range(sides.begin(), sides.end(), key(a, b));
      if (range.second - range.first != 1) continue;
      BorderIgnition rule;
      rule.edge = {cells.vertex_id[a], cells.vertex_id[b]};
      rule.rule = IgnitionRule::DistanceToPoint;
      rule.point = exact_sample(vor.samples, vor.pq[i][0]);  // every point x of the face has R(x) = |x - p|
      raw.border_rules.push_back(rule);
    }
  return raw;
}

// The next spacing per triangle: where the poles of its samples say that the local
// feature size f is small (spacing > f / 2, the sampling density of the power crust's
// experiments), down to f / 2 but at most by a factor 4 per round; if nowhere, everywhere
// by half.
void refine(const InnerVoronoi& vor, const MeshAxisOptions& options, std::vector<double>* spacing) {
  bool changed = false;
  for (std::size_t t = 0; t < spacing->size(); ++t) {
    double f = INFINITY;
    for (std::uint32_t i = vor.samples.offset[t]; i < vor.samples.offset[t + 1]; ++i)
      f = std::min(f, vor.pole_distance[vor.samples.on_triangle[i]]);
    double& h = (*spacing)[t];
    if (options.feature_ratio * f < h) {
      h = std::max(options.feature_ratio * f, h / 4);
      changed = true;
    }
  }
  if (!changed)
    for (double& h : *spacing) h /= 2;
}


// Whether each inner Voronoi vertex has a cell of dimension > 0 in V_in (a polygon or a
// segment), and one that the pruning's tests keep. The tests, not the pruned complex: which
// cells the collapses also keep (to preserve the topology) follows the sample order, which a
// rotation changes, and the refinement must not (the same rounds for a moved mesh).
struct PoleSupport {
  std::vector<bool> had_cell, kept_cell;
};

PoleSupport pole_support(const InnerVoronoi& vor, const KeepTests& keep) {
  PoleSupport out;
  out.had_cell.assign(vor.vertices.size(), false);
  out.kept_cell.assign(vor.vertices.size(), false);
  for (std::uint32_t i = 0; i < vor.polygons.size(); ++i) {
    const bool kept = keep.polygon(i);
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k) {
      const std::uint32_t x = vor.polygons.ring(i)[k];
      out.had_cell[x] = true;
      if (kept) out.kept_cell[x] = true;
    }
  }
  for (std::uint32_t i = 0; i < vor.segments.size(); ++i) {
    const bool kept = keep.edge({true, i, 0});
    for (std::uint32_t x : vor.segments[i].v) {
      out.had_cell[x] = true;
      if (kept) out.kept_cell[x] = true;
    }
  }
  return out;
}

// Whether the lost pole x is the deepest point of its neighbourhood on the axis: no vertex
// of V_in within R(x) of x (walking along polygon sides and segments) that keeps a cell of
// the pruned axis is deeper. A pole near the end of a sheet (a smooth tip, where the
// object angle goes to 0 and the pruning trims the sheet by design) has a deeper kept
// vertex next to it; the centre of an octahedron whose sheets were all pruned has none.
class LostCore {
 public:
  LostCore(const InnerVoronoi& vor, const PoleSupport& support) : vor_(vor), support_(support) {}

  bool operator()(std::uint32_t x) {
    if (verdict_.empty()) build_adjacency();
    if (verdict_[x] < 0) verdict_[x] = deepest(x) ? 1 : 0;
    return verdict_[x] == 1;
  }

 private:
  // The neighbours along polygon sides and segments, built at the first query: most
  // rounds lose no pole, and the sort is a tenth of a thickness round's cost.
  void build_adjacency() {
    const InnerVoronoi& vor = vor_;
    const std::size_t n = vor.vertices.size();
    auto each_edge = [&](auto&& visit) {
      for (std::uint32_t i = 0; i < vor.polygons.size(); ++i)
        for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k) {
          const auto [a, b] = vor.polygons.side(i, k);
          visit(a, b);
        }
      for (const InnerVoronoi::Segment& seg : vor.segments) visit(seg.v[0], seg.v[1]);
    };
    // Counting sort by the first end (linear, unlike sorting the pairs), then each
    // vertex's short list sorted and its repeats (a side is in about three polygons) dropped.
    std::vector<std::uint32_t> count(n + 1, 0);
    each_edge([&](std::uint32_t a, std::uint32_t b) { ++count[a + 1], ++count[b + 1]; });
    for (std::size_t v = 0; v < n; ++v) count[v + 1] += count[v];
    std::vector<std::uint32_t> all(count[n]), fill(count.begin(), count.end() - 1);
    each_edge([&](std::uint32_t a, std::uint32_t b) { all[fill[a]++] = b, all[fill[b]++] = a; });
    start_.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) {
      const auto first = all.begin() + count[v], last = all.begin() + count[v + 1];
      std::sort(first, last);
      next_.insert(next_.end(), first, std::unique(first, last));
      start_[v + 1] = static_cast<std::uint32_t>(next_.size());
    }
    seen_.assign(n, false);
    verdict_.assign(n, -1);
  }

  bool deepest(std::uint32_t x) {
    const auto cx = centre(x);
    const double r2 = radius2(x);
    std::vector<std::uint32_t> stack{x}, visited{x};
    seen_[x] = true;
    bool deepest = true;
    for (std::size_t steps = 0; !stack.empty() && deepest && steps < vor_.vertices.size(); ++steps) {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      for (std::uint32_t i = start_[v]; i < start_[v + 1]; ++i) {
        const std::uint32_t w = next_[i];
        if (seen_[w]) continue;
        const auto cw = centre(w);
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (cw[k] - cx[k]) * (cw[k] - cx[k]);
        if (d2 > r2) continue;
        seen_[w] = true;
        visited.push_back(w);
        if (support_.kept_cell[w] && radius2(w) > r2) deepest = false;
        stack.push_back(w);
      }
    }
    for (std::uint32_t v : visited) seen_[v] = false;
    return deepest;
  }
  std::array<double, 3> centre(std::uint32_t v) const {
    const auto& b = vor_.vertices[v].box;
    return {b[0].mid(), b[1].mid(), b[2].mid()};
  }
  double radius2(std::uint32_t v) const {
    const LatticeCentre& c = vor_.vertices[v].centre;
    double n2 = 0;
    for (int k = 0; k < 3; ++k) n2 += static_cast<double>(c.num[k]) * static_cast<double>(c.num[k]);
    const double g = vor_.samples.grid / static_cast<double>(c.den);
    return n2 * g * g;
  }
  const InnerVoronoi& vor_;
  const PoleSupport& support_;
  std::vector<std::uint32_t> start_, next_;
  std::vector<bool> seen_;
  std::vector<signed char> verdict_;  // per vertex: -1 not asked yet, 0 or 1
};

// Marks the triangles of every sample bounding a polygon at a lost pole.
void halve_partners(const InnerVoronoi& vor, const std::vector<bool>& lost, std::vector<bool>* halve) {
  const SurfaceSamples& s = vor.samples;
  std::vector<bool> partner(s.lattice.size(), false);
  for (std::uint32_t i = 0; i < vor.polygons.size(); ++i)
    for (std::uint32_t k = 0; k < vor.polygons.ring_size(i); ++k)
      if (lost[vor.polygons.ring(i)[k]])
        for (std::uint32_t p : vor.pq[i]) partner[p] = true;
  for (std::size_t t = 0; t < halve->size(); ++t)
    for (std::uint32_t i = s.offset[t]; i < s.offset[t + 1]; ++i)
      if (partner[s.on_triangle[i]]) (*halve)[t] = true;
}

// The thickness rule, once the Betti numbers are right. Triangle t is too coarse when
//  (a) lambda h_t > 2 f_t, f_t the largest inner pole distance of its samples (the
//      half-thickness of the part it bounds: samples across a slab of half-thickness f are
//      about 2 f apart, and the separation test keeps only pairs at least lambda h apart);
//      then h_t = max(rho 2 f_t / lambda, h_t / 4), rho = feature_ratio; or
//  (b) the pruning's tests keep no polygon or segment at that deepest pole x although V_in
//      has some, and no kept vertex within R(x) of x is deeper (LostCore): the sheets through
//      the deepest point of the part were pruned. (a) misses this
//      where the sheets are wedges, not slabs: the touching samples of a sheet of object
//      angle alpha at depth R are 2 R sin(alpha / 2) apart (the octahedron's sheets: 1.15 R,
//      which kept its axis one vertex). Then t and the triangles of every sample bounding a
//      polygon at x get half their spacing: the test compares |p - q| with the larger
//      spacing of p and q, so refining t alone would not bring the sheet back.
// The largest pole, not the least: near a convex edge the inner pole of a sample is about as
// far as the edge (lfs = 0 there), so the least would refine every sharp edge for ever. The
// margin 1 / rho of (a) is also the hysteresis that stops the refinement once the estimates
// of f settle. Returns how many triangles were too coarse.
std::size_t refine_thin(const InnerVoronoi& vor, const KeepTests& keep, const MeshAxisOptions& options,
                        std::vector<double>* spacing) {
  if (!(options.separation > 0)) return 0;
  const PoleSupport support = pole_support(vor, keep);
  LostCore lost_core(vor, support);
  const SurfaceSamples& s = vor.samples;
  std::vector<bool> lost(vor.vertices.size(), false), halve(spacing->size(), false);
  std::vector<double> next = *spacing;
  std::size_t coarse = 0;
  for (std::size_t t = 0; t < spacing->size(); ++t) {
    double f = 0;
    std::uint32_t pole = UINT32_MAX;
    for (std::uint32_t i = s.offset[t]; i < s.offset[t + 1]; ++i) {
      const std::uint32_t p = s.on_triangle[i];
      if (vor.inner_pole[p] != UINT32_MAX && vor.inner_pole_distance[p] > f) {
        f = vor.inner_pole_distance[p];
        pole = vor.inner_pole[p];
      }
    }
    if (pole == UINT32_MAX) continue;  // no inner Voronoi vertex on its samples: nothing to resolve
    const double h = (*spacing)[t], limit = 2 * f / options.separation;
    if (limit < h) {
      next[t] = std::max(options.feature_ratio * limit, h / 4);
      ++coarse;
    } else if (support.had_cell[pole] && !support.kept_cell[pole] && lost_core(pole)) {
      lost[pole] = true;
      halve[t] = true;
    }
  }
  if (std::find(lost.begin(), lost.end(), true) != lost.end()) halve_partners(vor, lost, &halve);
  for (std::size_t t = 0; t < spacing->size(); ++t)
    if (halve[t] && next[t] == (*spacing)[t]) {
      next[t] /= 2;
      ++coarse;
    }
  *spacing = std::move(next);
  return coarse;
}

// The accepted round: its Voronoi complex and kept cells, assembled once at the end.
struct AcceptedAxis {
  std::size_t round = 0;
  InnerVoronoi vor;
  AxisCells cells;
};

}  // namespace

MeshAxis mesh_medial_axis(const TriangleMesh3& mesh, const MeshAxisOptions& options) {
  const double start = cpu_seconds();
  if (!(options.samples_per_edge > 0)) throw std::invalid_argument(mesh.source + ": samples per edge must be positive");
  require_solid(mesh);  // with the defects and the --repair hint when it refuses
  MeshAxis out;
  out.solid = solid_topology(mesh);
  const SolidLocator solid(mesh);
  out.check_seconds = cpu_seconds_since(start);
  std::vector<double> spacing(mesh.triangles.size(), mean_edge_length(mesh) / options.samples_per_edge);
  std::optional<AcceptedAxis> accepted;
  for (int round = 0;; ++round) {
    MeshAxisRound r;
    r.spacing = *std::min_element(spacing.begin(), spacing.end());
    r.max_spacing = *std::max_element(spacing.begin(), spacing.end());
    double t = cpu_seconds();
    SurfaceSamples samples = sample_surface(mesh, spacing);
    r.samples = samples.lattice.size();
    if (r.samples > options.max_samples) {
      if (accepted) break;  // thickness refinement only: the accepted axis stands
      std::string history;
      for (const MeshAxisRound& done : out.rounds)
        history += (history.empty() ? "" : ", ") + std::to_string(done.samples) + " samples (Betti " + betti_text(done.betti) + ")";
      throw MeshAxisTopologyError(mesh.source + ": the next round needs " + std::to_string(r.samples) +
                                  " samples, over the limit of " + std::to_string(options.max_samples) +
                                  " (medial3d --max-samples); the rounds so far: " + history + "; the solid's Betti numbers are " +
                                  betti_text(out.solid.betti) + "; no axis is returned");
    }
    r.sample_seconds = cpu_seconds_since(t);
    // A thickness round that adds under min_thickness_growth samples refines a handful of triangles (at
    // the ends of sheets) for the cost of a whole round: the accepted axis stands.
    if (accepted && out.rounds.back().betti == out.solid.betti &&
        static_cast<double>(r.samples) < (1 + options.min_thickness_growth) * static_cast<double>(out.rounds.back().samples))
      break;
    InnerVoronoi vor = inner_voronoi(std::move(samples), solid);
    r.tetrahedra = vor.tetrahedra;
    r.cells = vor.cells;
    r.inner_cells = vor.vertices.size();
    r.interior_samples = vor.interior_samples;
    r.polygons = vor.polygons.size();
    r.segments = vor.segments.size();
    r.delaunay_seconds = vor.delaunay_seconds;
    r.classify_seconds = vor.classify_seconds;
    r.extract_seconds = vor.extract_seconds;
    t = cpu_seconds();
    const AngleTest angle(vor, options.angle_degrees);
    const SeparationTest separation(vor, spacing, options.separation);
    const KeepTests keep{vor, angle, separation};
    const PrunedComplex pruned = prune(vor, keep);
    AxisCells cells = axis_cells(vor, pruned);
    r.kept_polygons = cells.polygons.size();
    r.kept_segments = cells.segments.size();
    r.prune_seconds = cpu_seconds_since(t);
    t = cpu_seconds();
    r.betti = polygonal_betti_numbers(cells.voronoi_vertex.size(), cells.segments, cells.rings);
    r.betti_seconds = cpu_seconds_since(t);
    const bool right = r.betti == out.solid.betti;
    if (right) {
      t = cpu_seconds();
      std::vector<double> next = spacing;
      r.coarse_triangles = refine_thin(vor, keep, options, &next);
      r.refine_seconds = cpu_seconds_since(t);
      out.rounds.push_back(r);
      accepted = AcceptedAxis{out.rounds.size() - 1, std::move(vor), std::move(cells)};
      if (r.coarse_triangles == 0 || round >= options.max_refinements) break;
      spacing = std::move(next);
      continue;
    }
    out.rounds.push_back(r);
    // A thickness round whose sampling broke the topology (femur's thin features) would
    // need Betti refinements of the whole sample (rounds of 10^5-10^6 samples): the
    // accepted axis stands.
    if (accepted) break;
    if (round >= options.max_refinements) {
      throw MeshAxisTopologyError(mesh.source + ": the axis has Betti numbers " + betti_text(r.betti) +
                                  ", the solid " + betti_text(out.solid.betti) + ", after " + std::to_string(round) +
                                  " refinements (" + std::to_string(r.samples) +
                                  " samples); no axis is returned. Try a larger --samples");
    }
    t = cpu_seconds();
    refine(vor, options, &spacing);
    out.rounds.back().refine_seconds = cpu_seconds_since(t);
  }
  const double t = cpu_seconds();
  out.axis_round = accepted->round;
  out.complex = assemble(accepted->vor, accepted->cells, mesh.source);
  out.samples = std::move(accepted->vor.samples);
  out.axis_betti = out.rounds[out.axis_round].betti;
  out.exact_locator_tests = solid.stats().exact_tests;
  out.assemble_seconds = cpu_seconds_since(t);
  out.total_seconds = cpu_seconds_since(start);
  return out;
}

nlohmann::json mesh_axis_json(const MeshAxis& a) {
  auto betti = [](const BettiNumbers& b) { return nlohmann::json{b.b0, b.b1, b.b2}; };
  nlohmann::json rounds = nlohmann::json::array();
  for (const MeshAxisRound& r : a.rounds)
    rounds.push_back({{"spacing", r.spacing},
                      {"max_spacing", r.max_spacing},
                      {"samples", r.samples},
                      {"tetrahedra", r.tetrahedra},
                      {"delaunay_cells", r.cells},
                      {"inner_cells", r.inner_cells},
                      {"interior_samples", r.interior_samples},
                      {"voronoi_polygons", r.polygons},
                      {"voronoi_segments", r.segments},
                      {"kept_polygons", r.kept_polygons},
                      {"kept_segments", r.kept_segments},
                      {"coarse_triangles", r.coarse_triangles},
                      {"betti", betti(r.betti)},
                      {"seconds",
                       {{"samples", r.sample_seconds},
                        {"delaunay", r.delaunay_seconds},
                        {"classify", r.classify_seconds},
                        {"extract", r.extract_seconds},
                        {"prune", r.prune_seconds},
                        {"betti", r.betti_seconds},
                        {"refine", r.refine_seconds}}}});
  nlohmann::json shells = nlohmann::json::array();
  for (const MeshShell& s : a.solid.shells)
    shells.push_back({{"triangles", s.triangles.size()}, {"vertices", s.vertices}, {"genus", s.genus}, {"depth", s.depth}});
  return {{"solid_betti", betti(a.solid.betti)},
          {"axis_betti", betti(a.axis_betti)},
          {"refinements", a.refinements()},
          {"axis_round", a.axis_round},
          {"shells", shells},
          {"rounds", rounds},
          {"exact_locator_tests", a.exact_locator_tests},
          {"check_seconds", a.check_seconds},
          {"assemble_seconds", a.assemble_seconds},
          {"seconds", a.total_seconds}};
}

}  // namespace grassfire
