// mesh_axis.cpp -- see mesh_axis.h.
#include "medial3/mesh/mesh_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "medial3/mesh/axis_pruning.h"
#include "medial3/mesh/axis_resolution.h"
#include "medial3/mesh/inner_voronoi.h"
#include "medial3/mesh/mesh_checks.h"
#include "medial3/mesh/mesh_samples.h"
#include "geometry3/exact_predicates3.h"
#include "support/cpu_clock.h"
#include "medial3/mesh/mesh_repair.h"
#include "number/exact_sum.h"

namespace grassfire {

namespace {

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

// The cells without the vertices `drop` marks (whole components: no kept cell has a
// dropped and a kept vertex), ids compacted again.
void drop_vertices(const std::vector<bool>& drop, AxisCells* cells) {
  AxisCells out;
  std::vector<std::uint32_t> id(cells->voronoi_vertex.size(), UINT32_MAX);
  out.vertex_id.assign(cells->vertex_id.size(), UINT32_MAX);
  for (std::uint32_t v = 0; v < cells->voronoi_vertex.size(); ++v)
    if (!drop[v]) {
      id[v] = static_cast<std::uint32_t>(out.voronoi_vertex.size());
      out.vertex_id[cells->voronoi_vertex[v]] = id[v];
      out.voronoi_vertex.push_back(cells->voronoi_vertex[v]);
    }
  for (std::size_t i = 0; i < cells->rings.size(); ++i) {
    if (drop[cells->rings.ring(i)[0]]) continue;
    out.polygons.push_back(cells->polygons[i]);
    for (std::uint32_t k = 0; k < cells->rings.ring_size(i); ++k) out.rings.vertex.push_back(id[cells->rings.ring(i)[k]]);
    out.rings.close();
  }
  for (const auto& e : cells->segments)
    if (!drop[e[0]]) out.segments.push_back({id[e[0]], id[e[1]]});
  *cells = std::move(out);
}

// The resolution rule (axis_resolution.h), in a round whose Betti numbers differ from the
// solid's: its components made of unresolved vertices only are dropped and the Betti
// numbers computed again. Returns how many were dropped.
std::size_t drop_unresolved(const ResolutionTest& resolution, AxisCells* cells, BettiNumbers* betti) {
  const UnresolvedComponents unresolved = unresolved_components(
      cells->voronoi_vertex.size(), cells->rings, cells->segments,
      [&](std::uint32_t v) { return resolution.unresolved(cells->voronoi_vertex[v]); });
  if (unresolved.components == 0) return 0;
  drop_vertices(unresolved.vertex_dropped, cells);
  *betti = polygonal_betti_numbers(cells->voronoi_vertex.size(), cells->segments, cells->rings);
  return unresolved.components;
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

// The next spacing by the thickness rule for an accepted round's Voronoi complex.
std::size_t thickness_spacing(const InnerVoronoi& vor, const MeshAxisOptions& options, std::vector<double>* spacing) {
  const AngleTest angle(vor, options.angle_degrees);
  const std::vector<double> density = sample_spacing(vor.samples, *spacing);
  const SeparationTest separation(vor, density, options.separation);
  return refine_thin(vor, KeepTests{vor, angle, separation}, options, spacing);
}

// How far Betti numbers are from the solid's: the sum of the differences.
long discrepancy(const BettiNumbers& a, const BettiNumbers& b) {
  return std::labs(a.b0 - b.b0) + std::labs(a.b1 - b.b1) + std::labs(a.b2 - b.b2);
}

// An accepted round, or a candidate of the resolution rule: its Voronoi complex, kept
// cells and spacing, assembled once at the end.
struct AcceptedAxis {
  std::size_t round = 0;
  InnerVoronoi vor;
  AxisCells cells;
  std::vector<double> spacing;
};

// The rounds of mesh_medial_axis (mesh_axis.h, steps 2-6, and the resolution rule).
class Rounds {
 public:
  Rounds(const TriangleMesh3& mesh, const MeshAxisOptions& options, MeshAxis* out)
      : mesh_(mesh), options_(options), out_(*out), solid_(mesh) {}

  AcceptedAxis run() {
    std::vector<double> spacing(mesh_.triangles.size(), mean_edge_length(mesh_) / options_.samples_per_edge);
    for (int round = 0;; ++round) {
      MeshAxisRound r;
      r.spacing = *std::min_element(spacing.begin(), spacing.end());
      r.max_spacing = *std::max_element(spacing.begin(), spacing.end());
      double t = cpu_seconds();
      SurfaceSamples samples = sample_surface(mesh_, spacing);
      r.samples = samples.lattice.size();
      if (r.samples > options_.max_samples) {
        if (accepted_) break;  // thickness refinement only: the accepted axis stands
        if (candidate_ && accept_candidate(round, &spacing)) continue;
        if (accepted_) break;
        throw_over_limit(r.samples);
      }
      r.sample_seconds = cpu_seconds_since(t);
      // A thickness round that adds under min_thickness_growth samples refines a handful of triangles (at
      // the ends of sheets) for the cost of a whole round: the accepted axis stands.
      if (accepted_ && static_cast<double>(r.samples) <
                           (1 + options_.min_thickness_growth) * static_cast<double>(out_.rounds[accepted_->round].samples))
        break;
      InnerVoronoi vor = inner_voronoi(std::move(samples), solid_);
      std::optional<AxisCells> resolved;
      AxisCells cells = axis_of_round(vor, spacing, &r, &resolved);
      if (r.betti == out_.solid.betti) {
        t = cpu_seconds();
        std::vector<double> next = spacing;
        r.coarse_triangles = thickness_spacing(vor, options_, &next);
        r.refine_seconds = cpu_seconds_since(t);
        out_.rounds.push_back(r);
        accepted_ = AcceptedAxis{out_.rounds.size() - 1, std::move(vor), std::move(cells), spacing};
        if (r.coarse_triangles == 0 || round >= options_.max_refinements) break;
        spacing = std::move(next);
        continue;
      }
      out_.rounds.push_back(r);
      // A thickness round whose sampling broke the topology (femur's thin features) would
      // need Betti refinements of the whole sample (rounds of 10^5-10^6 samples): the
      // accepted axis stands.
      if (accepted_) break;
      if (resolved) candidate_ = AcceptedAxis{out_.rounds.size() - 1, std::move(vor), std::move(*resolved), spacing};
      const InnerVoronoi& round_vor = resolved ? candidate_->vor : vor;
      const long off = discrepancy(r.betti, out_.solid.betti);
      const bool stalled = off >= last_discrepancy_;
      last_discrepancy_ = off;
      if (candidate_ && (stalled || round >= options_.max_refinements)) {
        if (accept_candidate(round, &spacing)) continue;
        break;
      }
      if (round >= options_.max_refinements) {
        throw MeshAxisTopologyError(mesh_.source + ": the axis has Betti numbers " + betti_text(r.betti) +
                                    ", the solid " + betti_text(out_.solid.betti) + ", after " + std::to_string(round) +
                                    " refinements (" + std::to_string(r.samples) +
                                    " samples); no axis is returned. Try a larger --samples");
      }
      t = cpu_seconds();
      refine(round_vor, options_, &spacing);
      out_.rounds.back().refine_seconds = cpu_seconds_since(t);
    }
    out_.exact_locator_tests = solid_.stats().exact_tests;
    return std::move(*accepted_);
  }

 private:
  // Steps 3-5 for one round: V_in, the pruned axis, its Betti numbers; when they are not
  // the solid's, also without the unresolved components: those cells are the round's
  // axis once the resolution rule applies, else `resolved` when their Betti numbers are
  // the solid's (a candidate).
  AxisCells axis_of_round(const InnerVoronoi& vor, const std::vector<double>& spacing, MeshAxisRound* r,
                          std::optional<AxisCells>* resolved) {
    r->tetrahedra = vor.tetrahedra;
    r->cells = vor.cells;
    r->inner_cells = vor.vertices.size();
    r->interior_samples = vor.interior_samples;
    r->polygons = vor.polygons.size();
    r->segments = vor.segments.size();
    r->delaunay_seconds = vor.delaunay_seconds;
    r->classify_seconds = vor.classify_seconds;
    r->extract_seconds = vor.extract_seconds;
    double t = cpu_seconds();
    const AngleTest angle(vor, options_.angle_degrees);
    const std::vector<double> density = sample_spacing(vor.samples, spacing);
    const SeparationTest separation(vor, density, options_.separation);
    AxisCells cells = axis_cells(vor, prune(vor, KeepTests{vor, angle, separation}));
    r->kept_polygons = cells.polygons.size();
    r->kept_segments = cells.segments.size();
    r->prune_seconds = cpu_seconds_since(t);
    t = cpu_seconds();
    r->betti = r->all_components_betti = polygonal_betti_numbers(cells.voronoi_vertex.size(), cells.segments, cells.rings);
    if (r->betti != out_.solid.betti && options_.resolution_rule) {
      AxisCells resolved_cells = cells;
      BettiNumbers betti = r->betti;
      r->unresolved_components = drop_unresolved(ResolutionTest(vor, density, options_.separation), &resolved_cells, &betti);
      if (resolving_) {
        cells = std::move(resolved_cells);
        r->betti = betti;
        r->resolution_rule = true;
      } else if (betti == out_.solid.betti) {
        *resolved = std::move(resolved_cells);
      }
    }
    r->betti_seconds = cpu_seconds_since(t);
    return cells;
  }

  // The resolution rule takes over: the last candidate becomes the accepted axis (its
  // Betti numbers are those without its unresolved components) and the thickness rounds
  // continue from it, every later round dropping its unresolved components too. Returns
  // whether a thickness round follows.
  bool accept_candidate(int round, std::vector<double>* spacing) {
    resolving_ = true;
    accepted_ = std::move(*candidate_);
    candidate_.reset();
    MeshAxisRound& r = out_.rounds[accepted_->round];
    r.betti = out_.solid.betti;
    r.resolution_rule = true;
    const double t = cpu_seconds();
    *spacing = accepted_->spacing;
    r.coarse_triangles = thickness_spacing(accepted_->vor, options_, spacing);
    r.refine_seconds += cpu_seconds_since(t);
    return r.coarse_triangles > 0 && round < options_.max_refinements;
  }

  [[noreturn]] void throw_over_limit(std::size_t samples) const {
    std::string history;
    for (const MeshAxisRound& done : out_.rounds)
      history += (history.empty() ? "" : ", ") + std::to_string(done.samples) + " samples (Betti " + betti_text(done.betti) +
                 (done.unresolved_components > 0 ? ", " + std::to_string(done.unresolved_components) + " components below the resolution"
                                                 : "") + ")";
    throw MeshAxisTopologyError(mesh_.source + ": the next round needs " + std::to_string(samples) +
                                " samples, over the limit of " + std::to_string(options_.max_samples) +
                                " (medial3d --max-samples); the rounds so far: " + history + "; the solid's Betti numbers are " +
                                betti_text(out_.solid.betti) + "; no axis is returned");
  }

  const TriangleMesh3& mesh_;
  const MeshAxisOptions& options_;
  MeshAxis& out_;
  const SolidLocator solid_;
  std::optional<AcceptedAxis> accepted_, candidate_;
  bool resolving_ = false;                            // the resolution rule applies to every round
  long last_discrepancy_ = std::numeric_limits<long>::max();  // of the last Betti round
};

}  // namespace

MeshAxis mesh_medial_axis(const TriangleMesh3& mesh, const MeshAxisOptions& options) {
  const double start = cpu_seconds();
  if (!(options.samples_per_edge > 0)) throw std::invalid_argument(mesh.source + ": samples per edge must be positive");
  require_solid(mesh);  // with the defects and the --repair hint when it refuses
  MeshAxis out;
  out.solid = solid_topology(mesh);
  Rounds rounds(mesh, options, &out);
  out.check_seconds = cpu_seconds_since(start);
  AcceptedAxis accepted = rounds.run();
  const double t = cpu_seconds();
  out.axis_round = accepted.round;
  out.complex = assemble(accepted.vor, accepted.cells, mesh.source);
  out.samples = std::move(accepted.vor.samples);
  out.axis_betti = out.rounds[out.axis_round].betti;
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
                      {"all_components_betti", betti(r.all_components_betti)},
                      {"unresolved_components", r.unresolved_components},
                      {"resolution_rule", r.resolution_rule},
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
          {"resolution_rule", a.rounds[a.axis_round].resolution_rule},
          {"dropped_components", a.rounds[a.axis_round].resolution_rule ? a.rounds[a.axis_round].unresolved_components : 0},
          {"shells", shells},
          {"rounds", rounds},
          {"exact_locator_tests", a.exact_locator_tests},
          {"check_seconds", a.check_seconds},
          {"assemble_seconds", a.assemble_seconds},
          {"seconds", a.total_seconds}};
}

}  // namespace grassfire
