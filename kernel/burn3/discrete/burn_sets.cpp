// burn_sets.cpp -- discrete burning sets from witnesses (see header).
#include "burn3/discrete/burn_sets.h"

#include <algorithm>

namespace grassfire {

BurnSets::BurnSets(const SteinerGraph& g, const DiscreteBurning& d, const BurnRuleOverride* rule_override)
    : g_(g), d_(d), override_(rule_override), witness_(g.slot_total(), DiscreteBurning::kInfinity) {
  for (std::uint32_t y = 0; y < g.node_count(); ++y) {
    const double bt = burn_time(y);
    if (!std::isfinite(bt)) continue;
    g.for_each_move(y, [&](std::uint32_t x, std::uint32_t local, double length) {
      double& w = witness_[g.slot(x, local)];
      w = std::min(w, bt + length);
    });
  }
}

double BurnSets::burn_time(std::uint32_t node) const {
  return g_.is_vertex(node) ? d_.vertex_bt[node] : d_.steiner_bt[node - g_.vertex_count()];
}

bool BurnSets::border(std::uint32_t node) const {
  const MedialComplex& mc = g_.complex();
  if (g_.is_vertex(node)) return mc.is_border_point(node);
  return MedialComplex::edge_link_burns(mc.edge_triangles(g_.edge_of(node)).size(), false, false, 0);
}

double BurnSets::ignition(std::uint32_t node) const {
  const MedialComplex& mc = g_.complex();
  if (g_.is_vertex(node)) return mc.ignition_at_vertex(node);
  const std::uint32_t e = g_.edge_of(node);
  if (mc.edge(e).stratum != EdgeStratum::Border) return DiscreteBurning::kInfinity;
  return mc.ignition_on_edge(e, g_.parameter(e, g_.index_on_edge(node)));
}

bool BurnSets::link_condition(std::uint32_t node, double t) const {
  const std::size_t n = g_.slot_count(node);
  std::vector<bool> arrived(n);
  for (std::size_t j = 0; j < n; ++j) arrived[j] = witness_[g_.slot(node, static_cast<std::uint32_t>(j))] <= t;
  if (g_.is_vertex(node)) {
    const bool rule = g_.complex().link_burns(node, arrived);
    return override_ ? override_->burns(vertex_link_arrivals(g_.complex(), node, arrived, rule)) : rule;
  }
  const std::size_t arcs = static_cast<std::size_t>(std::count(arrived.begin() + 2, arrived.end(), true));
  const bool rule = MedialComplex::edge_link_burns(n - 2, arrived[0], arrived[1], arcs);
  return override_ ? override_->burns(edge_link_arrivals(n - 2, arrived[0], arrived[1], arcs, rule)) : rule;
}

bool BurnSets::contains(std::uint32_t node, double t) const {
  if (border(node) && ignition(node) <= t) return true;
  // The link condition can only become true at a witness time; before the first, nothing
  // has arrived and it holds only at border points, which ignite rather than burn.
  const std::size_t n = g_.slot_count(node);
  bool any = false;
  for (std::size_t j = 0; j < n && !any; ++j) any = witness_[g_.slot(node, static_cast<std::uint32_t>(j))] <= t;
  return any && link_condition(node, t);
}

std::vector<double> BurnSets::candidate_times(std::uint32_t node) const {
  std::vector<double> times;
  if (border(node) && std::isfinite(ignition(node))) times.push_back(ignition(node));
  for (std::size_t j = 0; j < g_.slot_count(node); ++j) {
    const double w = witness_[g_.slot(node, static_cast<std::uint32_t>(j))];
    if (std::isfinite(w)) times.push_back(w);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

double BurnSets::first_time(std::uint32_t node) const {
  for (double t : candidate_times(node))
    if (contains(node, t)) return t;
  return DiscreteBurning::kInfinity;
}

}  // namespace grassfire
