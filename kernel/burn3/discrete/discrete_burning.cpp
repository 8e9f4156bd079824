// discrete_burning.cpp -- Dijkstra with the link rule over vertices and Steiner points.
#include "burn3/discrete/discrete_burning.h"

#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>

#include "burn3/discrete/steiner_graph.h"

namespace grassfire {
namespace {

constexpr std::uint32_t kIgnite = std::numeric_limits<std::uint32_t>::max();

struct Arrival {
  double time;
  std::uint32_t node;
  std::uint32_t slot;  // local slot at the node, or kIgnite
  bool operator>(const Arrival& o) const {
    if (time != o.time) return time > o.time;
    if (node != o.node) return node > o.node;  // deterministic order among equal times
    return slot > o.slot;
  }
};

class Burner {
 public:
  Burner(const SteinerGraph& g, DiscreteBurning& out, const BurnRuleOverride* rule_override)
      : g_(g), mc_(g.complex()), out_(out), nv_(g.vertex_count()), override_(rule_override) {}

  void layout() {
    out_.spacing = g_.spacing();
    out_.edge_first_steiner = g_.first_steiner();
    out_.stats.steiner_points = g_.steiner_total();
    out_.vertex_slot = g_.vertex_slots();
    out_.edge_slot = g_.edge_slots();
    bt_.assign(g_.node_count(), DiscreteBurning::kInfinity);
    out_.arrival_time.assign(g_.slot_total(), DiscreteBurning::kInfinity);
    out_.arrival_from.assign(g_.slot_total(), kNoIndex);
    out_.burn_slot.assign(g_.node_count(), kNoIndex);
    done_.assign(g_.slot_total(), 0);
  }

  void run(const DiscreteBurningOptions& options) {
    for (std::uint32_t i = 0; i < options.sources.size(); ++i) ignite(options.sources[i], i);
    for (const PointSource& source : options.sources) out_.source_points.push_back(source.location.approx());
    for (std::uint32_t v = 0; v < nv_; ++v)
      if (std::isfinite(mc_.ignition_at_vertex(v))) heap_.push({ignition(mc_.ignition_at_vertex(v)), v, kIgnite});
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      if (mc_.edge(e).stratum != EdgeStratum::Border) continue;
      for (std::uint32_t i = 1; i <= g_.steiner_count(e); ++i) {
        const double f = mc_.ignition_on_edge(e, g_.parameter(e, i));
        if (std::isfinite(f)) heap_.push({ignition(f), g_.steiner_node(e, i), kIgnite});
      }
    }
    // Flat event loop: pop the earliest arrival, drop stale ones, record it, burn when the
    // link rule holds. Each slot is recorded once, so the loop ends after O(pushes) pops.
    while (!heap_.empty()) {
      const Arrival a = heap_.top();
      heap_.pop();
      ++out_.stats.pops;
      if (options.progress && (out_.stats.pops & 0xFFFF) == 0) options.progress(burned_, g_.node_count());
      if (std::isfinite(bt_[a.node])) continue;
      if (a.slot == kIgnite) {
        out_.burn_slot[a.node] = DiscreteBurning::kIgnited;
        burn(a.node, a.time);
        continue;
      }
      const std::uint64_t g = slot(a.node, a.slot);
      if (done_[g] || a.time > out_.arrival_time[g]) continue;
      done_[g] = 1;
      if (!condition(a.node)) continue;
      out_.burn_slot[a.node] = a.slot;
      burn(a.node, a.time);
    }
  }

  void finish() {
    out_.vertex_bt.assign(bt_.begin(), bt_.begin() + nv_);
    out_.steiner_bt.assign(bt_.begin() + nv_, bt_.end());
    out_.vertex_et.resize(nv_);
    for (std::uint32_t v = 0; v < nv_; ++v) out_.vertex_et[v] = out_.vertex_bt[v] - mc_.vertex(v).radius;
    for (std::size_t g = 0; g < done_.size(); ++g)
      if (!done_[g]) out_.arrival_time[g] = DiscreteBurning::kInfinity, out_.arrival_from[g] = kNoIndex;
  }

 private:
  std::uint64_t slot(std::uint32_t node, std::uint32_t local) const { return g_.slot(node, local); }

  double ignition(double f) const { return override_ ? override_->ignition(f) : f; }

  bool condition(std::uint32_t node) const {
    if (node < nv_) {
      const std::uint64_t first = out_.vertex_slot[node];
      std::vector<bool> arrived(out_.vertex_slot[node + 1] - first);
      for (std::size_t j = 0; j < arrived.size(); ++j) arrived[j] = done_[first + j] != 0;
      const bool rule = mc_.link_burns(node, arrived);
      return override_ ? override_->burns(vertex_link_arrivals(mc_, node, arrived, rule)) : rule;
    }
    const std::size_t k = mc_.edge_triangles(g_.edge_of(node)).size();
    const std::uint64_t first = slot(node, 0);
    std::size_t arcs = 0;
    for (std::size_t j = 0; j < k; ++j) arcs += done_[first + 2 + j];
    const bool rule = MedialComplex::edge_link_burns(k, done_[first], done_[first + 1], arcs);
    return override_ ? override_->burns(edge_link_arrivals(k, done_[first], done_[first + 1], arcs, rule)) : rule;
  }

  void burn(std::uint32_t node, double time) {
    bt_[node] = time;
    ++burned_;
    g_.for_each_move(node, [&](std::uint32_t y, std::uint32_t local, double length) { arrive(y, local, time + length, node); });
  }

  // `from`: the graph point that emitted the fire, or DiscreteBurning::kFromSource + i for
  // the moves of point source i (recorded for the burning paths).
  void arrive(std::uint32_t y, std::uint32_t local, double t, std::uint32_t from) {
    if (std::isfinite(bt_[y])) return;
    const std::uint64_t s = slot(y, local);
    if (!(t < out_.arrival_time[s])) return;
    out_.arrival_time[s] = t;
    out_.arrival_from[s] = from;
    heap_.push({t, y, local});
    ++out_.stats.pushes;
  }

  // A point source: its graph point ignites, or its straight moves carry fire to the graph
  // points of its closed triangles (see DiscreteBurningOptions::sources).
  void ignite(const PointSource& source, std::uint32_t index) {
    const double t0 = source.t0.get_d();
    const ComplexPoint& x = source.location;
    const std::uint32_t from = DiscreteBurning::kFromSource + index;
    auto move = [&](std::uint32_t y, std::uint32_t local, double length) { arrive(y, local, t0 + length, from); };
    if (x.kind == ComplexPoint::Kind::Vertex) {
      heap_.push({t0, x.id, kIgnite});
    } else if (x.kind == ComplexPoint::Kind::Triangle) {
      g_.for_each_move_from_triangle_point(x.approx(), x.id, move);
    } else {
      const mpq_class scaled = x.parameter * (g_.steiner_count(x.id) + 1);
      const mpz_class lower = scaled.get_num() / scaled.get_den();  // floor: scaled > 0
      const auto i = static_cast<std::uint32_t>(lower.get_ui());
      if (scaled == lower)
        heap_.push({t0, g_.steiner_node(x.id, i), kIgnite});
      else
        g_.for_each_move_from_edge_point(x.approx(), x.id, i, move);
    }
  }

  const SteinerGraph& g_;
  const MedialComplex& mc_;
  DiscreteBurning& out_;
  const std::uint32_t nv_;
  const BurnRuleOverride* override_;
  std::vector<double> bt_;
  std::uint64_t burned_ = 0;
  std::vector<std::uint8_t> done_;
  std::priority_queue<Arrival, std::vector<Arrival>, std::greater<Arrival>> heap_;
};

}  // namespace

LinkArrivals vertex_link_arrivals(const MedialComplex& mc, std::uint32_t v, const std::vector<bool>& arrived, bool rule) {
  LinkArrivals a;
  const std::vector<LinkElement>& elements = mc.link_elements(v);
  for (std::size_t j = 0; j < elements.size(); ++j) {
    (elements[j].is_pole ? a.poles : a.sectors)++;
    if (arrived[j]) (elements[j].is_pole ? a.poles_arrived : a.sectors_arrived)++;
  }
  const VertexKind kind = mc.vertex(v).kind;
  a.junction = kind == VertexKind::SingularCurve || kind == VertexKind::SingularPoint;
  a.rule = rule;
  return a;
}

LinkArrivals edge_link_arrivals(std::size_t triangles, bool pole0, bool pole1, std::size_t arcs, bool rule) {
  LinkArrivals a;
  a.sectors = triangles;
  a.sectors_arrived = arcs;
  a.poles = 2;
  a.poles_arrived = std::size_t{pole0} + std::size_t{pole1};
  a.junction = triangles >= 3;
  a.rule = rule;
  return a;
}

Vec3d DiscreteBurning::point_on_edge(const MedialComplex& mc, std::uint32_t e, double s) {
  const Vec3d& a = mc.vertex(mc.edge(e).v[0]).approx;
  const Vec3d& b = mc.vertex(mc.edge(e).v[1]).approx;
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

double DiscreteBurning::bt_on_edge(const MedialComplex& mc, std::uint32_t e, std::uint32_t i) const {
  if (i == 0) return vertex_bt[mc.edge(e).v[0]];
  if (i == steiner_count(e) + 1) return vertex_bt[mc.edge(e).v[1]];
  return steiner_bt[edge_first_steiner[e] + i - 1];
}

std::vector<double> DiscreteBurning::vertex_arrivals(std::uint32_t v) const {
  return {arrival_time.begin() + static_cast<std::ptrdiff_t>(vertex_slot[v]),
          arrival_time.begin() + static_cast<std::ptrdiff_t>(vertex_slot[v + 1])};
}

std::vector<double> DiscreteBurning::steiner_arrivals(const MedialComplex& mc, std::uint32_t e, std::uint32_t i) const {
  const std::size_t width = 2 + mc.edge_triangles(e).size();
  const auto first = static_cast<std::ptrdiff_t>(edge_slot[e] + (i - 1) * width);
  return {arrival_time.begin() + first, arrival_time.begin() + first + static_cast<std::ptrdiff_t>(width)};
}

DiscreteBurning burn_discrete(const MedialComplex& mc, const DiscreteBurningOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  DiscreteBurning out;
  const SteinerGraph graph(mc, options.spacing, options.max_points);
  Burner burner(graph, out, options.rule_override);
  burner.layout();
  for (const PointSource& s : options.sources)
    if (sgn(s.location.snap_squared) != 0)
      throw std::invalid_argument(mc.source() + ": a point source does not lie on the complex");
  burner.run(options);
  burner.finish();
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace grassfire
