// mutants3d.cpp -- the 3D burning mutants (see mutants3d.h).
#include "mutants3d.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace grassfire::checks {
namespace {

class JunctionFirst : public BurnRuleOverride {
 public:
  bool burns(const LinkArrivals& a) const override {
    return a.junction ? a.sectors_arrived + a.poles_arrived >= 1 : a.rule;
  }
};

class JunctionLast : public BurnRuleOverride {
 public:
  bool burns(const LinkArrivals& a) const override {
    if (!a.junction) return a.rule;
    return a.sectors_arrived == a.sectors || (a.poles_arrived > 0 && a.rule);
  }
};

class LateIgnition : public BurnRuleOverride {
 public:
  explicit LateIgnition(double delay) : delay_(delay) {}
  bool burns(const LinkArrivals& a) const override { return a.rule; }
  double ignition(double f) const override { return f + delay_; }

 private:
  double delay_;
};

class NotMonotone : public BurnRuleOverride {
 public:
  bool burns(const LinkArrivals& a) const override { return a.rule && a.sectors_arrived < a.sectors; }
};

constexpr EngineMutant kEngineMutants[] = {EngineMutant::kth_arrival,     EngineMutant::first_arrival,
                                           EngineMutant::no_kink_emission, EngineMutant::mirrored_rotation,
                                           EngineMutant::sampled_crossings, EngineMutant::double_bending};

}  // namespace

MutantList engine_mutants() {
  const char* what[] = {
      "the exact engine: a singular edge with k sides burns at the k-th arrival (Definition 9: the (k-1)-th)",
      "the exact engine: a singular edge burns at its first arrival",
      "the exact engine: kink points of the junction rule emit no point source",
      "the exact engine: pieces continued across a singular edge enter mirrored through the edge's line",
      "the exact engine: crossings of two arrivals along an edge found by 32 samples (no certified isolation)",
      "the exact engine: whether a fan bends decided by a double sum of atan2 with a 1e-6 margin"};
  MutantList out;
  for (std::size_t i = 0; i < std::size(kEngineMutants); ++i) out.push_back({engine_mutant_name(kEngineMutants[i]), what[i]});
  return out;
}

ExactBurningOptions engine_options(const CheckContext& ctx) {
  ExactBurningOptions o;
  for (const EngineMutant m : kEngineMutants)
    if (ctx.mutant == engine_mutant_name(m)) o.mutant = m;
  return o;
}

MutantList burning_mutants() {
  return {
      {"bt-bump", "output: BT at one burned point inside a sheet (the median one) raised by the largest finite BT"},
      {"bt-dip", "output: BT at that point lowered to half its value"},
      {"bt-infinite", "output: BT at that point set to infinity"},
      {"closed-burns", "output: BT = 0 at one point of the maximal closed subcomplex (where there is one)"},
      {"junction-first", "engine rule (hook): a junction burns at its first arrival instead of the (k-1)-th"},
      {"junction-last", "engine rule (hook): a junction burns only when every sector has arrived (or along a curve)"},
      {"ignition-late", "engine rule (hook): every border point ignites at f + 4h"},
      {"rule-not-monotone", "definition and engine rule (hook): x is in B(t) only while a sector is unarrived"},
  };
}

std::unique_ptr<BurnRuleOverride> engine_rule(const CheckContext& ctx, double spacing) {
  if (ctx.mutated("junction-first")) return std::make_unique<JunctionFirst>();
  if (ctx.mutated("junction-last")) return std::make_unique<JunctionLast>();
  if (ctx.mutated("ignition-late")) return std::make_unique<LateIgnition>(4 * spacing);
  if (ctx.mutated("rule-not-monotone")) return std::make_unique<NotMonotone>();
  return nullptr;
}

std::unique_ptr<BurnRuleOverride> definition_rule(const CheckContext& ctx) {
  if (ctx.mutated("rule-not-monotone")) return std::make_unique<NotMonotone>();
  return nullptr;
}

void mutate_burning_times(const CheckContext& ctx, std::vector<double>& bt, const std::function<bool(std::size_t)>& in_sheet,
                          const std::function<bool(std::size_t)>& closed) {
  if (ctx.mutated("closed-burns")) {
    for (std::size_t i = 0; i < bt.size(); ++i)
      if (closed(i)) {
        bt[i] = 0;
        return;
      }
    return;
  }
  if (!ctx.mutated("bt-bump") && !ctx.mutated("bt-dip") && !ctx.mutated("bt-infinite")) return;
  std::vector<std::pair<double, std::size_t>> burned, elsewhere;
  double largest = 0;
  for (std::size_t i = 0; i < bt.size(); ++i) {
    if (!std::isfinite(bt[i])) continue;
    largest = std::max(largest, bt[i]);
    if (in_sheet(i)) burned.push_back({bt[i], i});
    if (bt[i] > 0) elsewhere.push_back({bt[i], i});
  }
  if (burned.empty()) burned.swap(elsewhere);  // sheets of single triangles: no point inside one
  if (burned.empty()) return;
  std::nth_element(burned.begin(), burned.begin() + burned.size() / 2, burned.end());
  double& x = bt[burned[burned.size() / 2].second];
  if (ctx.mutated("bt-bump")) x += largest;
  if (ctx.mutated("bt-dip")) x /= 2;
  if (ctx.mutated("bt-infinite")) x = DiscreteBurning::kInfinity;
}

void mutate_enclosures(const CheckContext& ctx, std::vector<Interval>& bt, const std::function<bool(std::size_t)>& in_sheet,
                       const std::function<bool(std::size_t)>& closed) {
  std::vector<double> mid(bt.size());
  for (std::size_t i = 0; i < bt.size(); ++i) mid[i] = bt[i].mid();
  std::vector<double> m = mid;
  mutate_burning_times(ctx, m, in_sheet, closed);
  for (std::size_t i = 0; i < bt.size(); ++i) {
    if (m[i] == mid[i]) continue;
    bt[i] = std::isinf(m[i]) ? Interval::infinity() : Interval(bt[i].lo + m[i] - mid[i], bt[i].hi + m[i] - mid[i]);
  }
}

}  // namespace grassfire::checks
