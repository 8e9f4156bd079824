// mutants3d.cpp -- the 3D burning mutants (see mutants3d.h).
#include "mutants3d.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

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

}  // namespace grassfire::checks
