// discrete_burning.cpp -- Dijkstra with the link rule over vertices and Steiner points.
#include "burn3/discrete_burning.h"

#include <chrono>
#include <cmath>
#include <queue>
#include <stdexcept>

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

double distance(const Vec3d& a, const Vec3d& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

class Burner {
 public:
  Burner(const MedialComplex& mc, DiscreteBurning& out) : mc_(mc), out_(out), nv_(mc.vertex_count()) {}

  void layout(const DiscreteBurningOptions& o) {
    const double h = o.spacing;
    if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("discrete burning: spacing must be > 0");
    out_.spacing = h;
    out_.edge_first_steiner.assign(mc_.edge_count() + 1, 0);
    out_.edge_slot.assign(mc_.edge_count() + 1, 0);
    out_.vertex_slot.assign(nv_ + 1, 0);
    for (std::uint32_t v = 0; v < nv_; ++v) out_.vertex_slot[v + 1] = out_.vertex_slot[v] + mc_.link_elements(v).size();
    out_.edge_slot[0] = out_.vertex_slot[nv_];
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      const double n = std::ceil(mc_.edge(e).length / h) - 1;
      if (n > static_cast<double>(o.max_points))
        throw std::invalid_argument("discrete burning: spacing too small for the point budget");
      const auto count = static_cast<std::uint64_t>(std::max(0.0, n));
      out_.edge_first_steiner[e + 1] = out_.edge_first_steiner[e] + count;
      out_.edge_slot[e + 1] = out_.edge_slot[e] + count * (2 + mc_.edge_triangles(e).size());
      if (out_.edge_first_steiner[e + 1] + nv_ > o.max_points)
        throw std::invalid_argument("discrete burning: more than " + std::to_string(o.max_points) +
                                    " graph points at spacing " + std::to_string(h));
    }
    const std::uint64_t steiner = out_.edge_first_steiner.back();
    out_.stats.steiner_points = steiner;
    steiner_edge_.resize(steiner);
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e)
      for (std::uint64_t i = out_.edge_first_steiner[e]; i < out_.edge_first_steiner[e + 1]; ++i) steiner_edge_[i] = e;
    bt_.assign(nv_ + steiner, DiscreteBurning::kInfinity);
    out_.arrival_time.assign(out_.edge_slot.back(), DiscreteBurning::kInfinity);
    done_.assign(out_.edge_slot.back(), 0);
    tri_edge_pos_.assign(3 * mc_.triangle_count(), 0);
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      const auto& tris = mc_.edge_triangles(e);
      for (std::uint32_t idx = 0; idx < tris.size(); ++idx) {
        const ComplexTriangle& t = mc_.triangle(tris[idx]);
        for (int c = 0; c < 3; ++c)
          if (t.e[c] == e) tri_edge_pos_[3 * tris[idx] + c] = idx;
      }
    }
  }

  void run() {
    for (std::uint32_t v = 0; v < nv_; ++v)
      if (std::isfinite(mc_.ignition_at_vertex(v))) heap_.push({mc_.ignition_at_vertex(v), v, kIgnite});
    for (std::uint32_t e = 0; e < mc_.edge_count(); ++e) {
      if (mc_.edge(e).stratum != EdgeStratum::Border) continue;
      const std::uint32_t n = count(e);
      for (std::uint32_t i = 1; i <= n; ++i) {
        const double f = mc_.ignition_on_edge(e, static_cast<double>(i) / (n + 1));
        if (std::isfinite(f)) heap_.push({f, steiner_node(e, i), kIgnite});
      }
    }
    while (!heap_.empty()) {
      const Arrival a = heap_.top();
      heap_.pop();
      ++out_.stats.pops;
      if (std::isfinite(bt_[a.node])) continue;
      if (a.slot == kIgnite) {
        burn(a.node, a.time);
        continue;
      }
      const std::uint64_t g = slot(a.node, a.slot);
      if (done_[g] || a.time > out_.arrival_time[g]) continue;
      done_[g] = 1;
      if (condition(a.node)) burn(a.node, a.time);
    }
  }

  void finish() {
    out_.vertex_bt.assign(bt_.begin(), bt_.begin() + nv_);
    out_.steiner_bt.assign(bt_.begin() + nv_, bt_.end());
    out_.vertex_et.resize(nv_);
    for (std::uint32_t v = 0; v < nv_; ++v) out_.vertex_et[v] = out_.vertex_bt[v] - mc_.vertex(v).radius;
    for (std::size_t g = 0; g < done_.size(); ++g)
      if (!done_[g]) out_.arrival_time[g] = DiscreteBurning::kInfinity;
  }

 private:
  std::uint32_t count(std::uint32_t e) const { return out_.steiner_count(e); }
  std::uint32_t steiner_node(std::uint32_t e, std::uint32_t i) const {
    return static_cast<std::uint32_t>(nv_ + out_.edge_first_steiner[e] + i - 1);
  }
  std::uint64_t slot(std::uint32_t node, std::uint32_t local) const {
    if (node < nv_) return out_.vertex_slot[node] + local;
    const std::uint64_t s = node - nv_;
    const std::uint32_t e = steiner_edge_[s];
    return out_.edge_slot[e] + (s - out_.edge_first_steiner[e]) * (2 + mc_.edge_triangles(e).size()) + local;
  }

  bool condition(std::uint32_t node) {
    if (node < nv_) {
      const std::uint64_t first = out_.vertex_slot[node];
      std::vector<bool> arrived(out_.vertex_slot[node + 1] - first);
      for (std::size_t j = 0; j < arrived.size(); ++j) arrived[j] = done_[first + j] != 0;
      return mc_.remaining_link_contractible(node, arrived);
    }
    const std::uint32_t e = steiner_edge_[node - nv_];
    const std::uint64_t first = slot(node, 0);
    const std::size_t k = mc_.edge_triangles(e).size();
    std::size_t arcs = 0;
    for (std::size_t j = 0; j < k; ++j) arcs += done_[first + 2 + j];
    return MedialComplex::remaining_edge_link_contractible(k, done_[first], done_[first + 1], arcs);
  }

  void push(std::uint32_t node, std::uint32_t local, double time) {
    if (std::isfinite(bt_[node])) return;
    const std::uint64_t g = slot(node, local);
    if (!(time < out_.arrival_time[g])) return;
    out_.arrival_time[g] = time;
    heap_.push({time, node, local});
    ++out_.stats.pushes;
  }

  // Fire from p at time T into every Steiner point of edge e through triangle slot `local`.
  void into_edge(const Vec3d& p, double time, std::uint32_t e, std::uint32_t local) {
    const std::uint32_t n = count(e);
    const Vec3d& a = mc_.vertex(mc_.edge(e).v[0]).approx;
    const Vec3d& b = mc_.vertex(mc_.edge(e).v[1]).approx;
    for (std::uint32_t i = 1; i <= n; ++i) {
      const double s = static_cast<double>(i) / (n + 1);
      const Vec3d q = {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
      push(steiner_node(e, i), local, time + distance(p, q));
    }
  }

  void burn(std::uint32_t node, double time) {
    bt_[node] = time;
    if (node < nv_) {
      emit_from_vertex(node, time);
      return;
    }
    const std::uint32_t e = steiner_edge_[node - nv_];
    emit_from_steiner(e, static_cast<std::uint32_t>(node - nv_ - out_.edge_first_steiner[e] + 1), time);
  }

  void emit_from_vertex(std::uint32_t v, double time) {
    const Vec3d& p = mc_.vertex(v).approx;
    for (std::uint32_t e : mc_.vertex_edges(v)) {
      const int j = mc_.edge(e).v[0] == v ? 0 : 1;
      const std::uint32_t n = count(e);
      const double step = mc_.edge(e).length / (n + 1);
      if (n > 0)
        push(steiner_node(e, j == 0 ? 1 : n), static_cast<std::uint32_t>(j), time + step);
      else
        push(mc_.edge(e).v[1 - j], mc_.edge_end_element(e, 1 - j), time + step);
    }
    for (std::uint32_t t : mc_.vertex_triangles(v)) {
      const int c = corner_of(mc_.triangle(t), v);
      into_edge(p, time, mc_.triangle(t).e[c], 2 + tri_edge_pos_[3 * t + c]);
    }
  }

  void emit_from_steiner(std::uint32_t e, std::uint32_t i, double time) {
    const std::uint32_t n = count(e);
    const double s = static_cast<double>(i) / (n + 1);
    const Vec3d p = DiscreteBurning::point_on_edge(mc_, e, s);
    const double step = mc_.edge(e).length / (n + 1);
    // Along the edge: the neighbour towards v[0] receives fire from its v[1] side (slot 1).
    if (i > 1)
      push(steiner_node(e, i - 1), 1, time + step);
    else
      push(mc_.edge(e).v[0], mc_.edge_end_element(e, 0), time + step);
    if (i < n)
      push(steiner_node(e, i + 1), 0, time + step);
    else
      push(mc_.edge(e).v[1], mc_.edge_end_element(e, 1), time + step);
    for (std::uint32_t t : mc_.edge_triangles(e)) {
      const ComplexTriangle& tr = mc_.triangle(t);
      const int c = tr.e[0] == e ? 0 : tr.e[1] == e ? 1 : 2;
      push(tr.v[c], mc_.corner_element(t, c), time + distance(p, mc_.vertex(tr.v[c]).approx));
      for (int d : {(c + 1) % 3, (c + 2) % 3}) into_edge(p, time, tr.e[d], 2 + tri_edge_pos_[3 * t + d]);
    }
  }

  const MedialComplex& mc_;
  DiscreteBurning& out_;
  const std::uint32_t nv_;
  std::vector<std::uint32_t> steiner_edge_;
  std::vector<double> bt_;
  std::vector<std::uint8_t> done_;
  std::vector<std::uint32_t> tri_edge_pos_;
  std::priority_queue<Arrival, std::vector<Arrival>, std::greater<Arrival>> heap_;
};

}  // namespace

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
  Burner burner(mc, out);
  burner.layout(options);
  burner.run();
  burner.finish();
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace grassfire
