// junction_arrivals.cpp -- per-side arrivals along a singular curve, and kinks.
#include "burn3/discrete/junction_arrivals.h"

#include <cmath>
#include <stdexcept>

namespace grassfire {
namespace {

CurvePointArrivals empty_point(double t, const Vec3d& p, double bt) {
  CurvePointArrivals c;
  c.t = t;
  c.position = p;
  c.bt = bt;
  c.side_arrival.fill(DiscreteBurning::kInfinity);
  return c;
}

void record(CurvePointArrivals& c, int label, double time) {
  if (label < 0 || label >= 8) throw std::invalid_argument("arrivals_along_curve: labels must be in [0, 8)");
  c.side_arrival[label] = std::min(c.side_arrival[label], time);
}

}  // namespace

std::vector<CurvePointArrivals> arrivals_along_curve(const MedialComplex& mc, const DiscreteBurning& d,
                                                     std::uint32_t start, const std::vector<std::uint32_t>& chain,
                                                     const std::function<int(std::uint32_t)>& label) {
  std::vector<CurvePointArrivals> out;
  std::uint32_t at = start;
  double t0 = 0.0;
  auto add_vertex = [&](std::uint32_t v) {
    CurvePointArrivals c = empty_point(t0, mc.vertex(v).approx, d.vertex_bt[v]);
    const std::vector<double> arr = d.vertex_arrivals(v);
    const auto& elements = mc.link_elements(v);
    for (std::size_t j = 0; j < elements.size(); ++j)
      if (!elements[j].is_pole) record(c, label(mc.sectors()[elements[j].id].triangles.front()), arr[j]);
    out.push_back(c);
  };
  add_vertex(at);
  for (std::uint32_t e : chain) {
    const ComplexEdge& ed = mc.edge(e);
    if (ed.v[0] != at && ed.v[1] != at) throw std::invalid_argument("arrivals_along_curve: chain is not a path");
    const bool forward = ed.v[0] == at;
    const std::uint32_t n = d.steiner_count(e);
    for (std::uint32_t k = 1; k <= n; ++k) {
      const std::uint32_t i = forward ? k : n + 1 - k;
      const double s = static_cast<double>(i) / (n + 1);
      CurvePointArrivals c = empty_point(t0 + ed.length * k / (n + 1), DiscreteBurning::point_on_edge(mc, e, s),
                                         d.bt_on_edge(mc, e, i));
      const std::vector<double> arr = d.steiner_arrivals(mc, e, i);
      for (std::size_t j = 0; j < mc.edge_triangles(e).size(); ++j) record(c, label(mc.edge_triangles(e)[j]), arr[2 + j]);
      out.push_back(c);
    }
    t0 += ed.length;
    at = forward ? ed.v[1] : ed.v[0];
    add_vertex(at);
  }
  return out;
}

std::vector<double> kinks_along_curve(const std::vector<CurvePointArrivals>& points, int a, int b) {
  std::vector<double> kinks;
  bool have_prev = false;
  double t_prev = 0, d_prev = 0, zero_t = 0;
  bool zero_run = false;
  for (const CurvePointArrivals& p : points) {
    const double d = p.side_arrival[a] - p.side_arrival[b];
    if (!std::isfinite(d)) continue;
    if (d == 0) {  // an exact tie at a graph point: the kink is there if the sign flips
      if (!zero_run) zero_t = p.t;
      zero_run = true;
      continue;
    }
    if (have_prev && (d > 0) != (d_prev > 0))
      kinks.push_back(zero_run ? zero_t : t_prev + (p.t - t_prev) * d_prev / (d_prev - d));
    have_prev = true;
    zero_run = false;
    t_prev = p.t;
    d_prev = d;
  }
  return kinks;
}

std::vector<std::uint32_t> singular_curve_from(const MedialComplex& mc, std::uint32_t start) {
  std::vector<std::uint32_t> chain;
  std::vector<bool> used(mc.edge_count(), false);
  for (std::uint32_t at = start;;) {
    std::uint32_t next = kNoIndex;
    for (std::uint32_t e : mc.vertex_edges(at))
      if (!used[e] && mc.edge(e).stratum == EdgeStratum::Singular) {
        next = e;
        break;
      }
    if (next == kNoIndex) return chain;
    used[next] = true;
    chain.push_back(next);
    at = mc.edge(next).v[0] == at ? mc.edge(next).v[1] : mc.edge(next).v[0];
  }
}

}  // namespace grassfire
