// mutants3d.h -- deliberately broken 3D burning, to show that the chapter-4 rows can fail.
//
// Two kinds, never touching the reference side of a row:
//  - rule mutants, passed to the engine through DiscreteBurningOptions::rule_override (no
//    cost on the default path): junction-first (a junction burns at its first arrival),
//    junction-last (only when every sector has arrived, or by the rule along a curve),
//    ignition-late (every border point ignites at f + 4h), and rule-not-monotone (a point
//    is in B(t) while the rule holds and some sector is still unarrived: the definition's
//    rule itself, handed to the discrete burning sets as well);
//  - output mutants, applied to the burning times per graph point after the engine ran:
//    bt-bump (one point raised by the largest finite BT of the instance), bt-dip (one point
//    lowered to half its BT), bt-infinite (one burned point made infinite), closed-burns
//    (one point of the maximal closed subcomplex given BT = 0). The point is the burned
//    point of median BT among the points inside sheets (M2), or among all points with
//    BT > 0 where no point lies inside a sheet (sheets of single triangles).
// An exact engine (docs/exact-engine.md) applies the output mutants to its own per-point times with
// mutate_burning_times, and the rule mutants through its own hook.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/window_propagation.h"
#include "check_registry.h"
#include "number/interval.h"

namespace grassfire::checks {

MutantList burning_mutants();

// The engine's rule for the context's mutant (nullptr: the rule of discrete_burning.h).
std::unique_ptr<BurnRuleOverride> engine_rule(const CheckContext& ctx, double spacing);
// The rule of the discrete burning sets (Definition 9): replaced by rule-not-monotone only.
std::unique_ptr<BurnRuleOverride> definition_rule(const CheckContext& ctx);

// Engine mutants of the exact engine (burn3/exact/engine_mutant.h), named engine-...: they
// break the engine's own decisions (the junction rule's arrival rank, kink emission, the
// rotation into the other sheets, crossings by samples, the bending test in doubles), not
// its output. engine_options gives the options of the context's mutant (none otherwise).
MutantList engine_mutants();
ExactBurningOptions engine_options(const CheckContext& ctx);

// Applies an output mutant to bt (one value per graph point). in_sheet(i): point i lies in
// M2; closed(i): point i lies in the maximal closed subcomplex.
void mutate_burning_times(const CheckContext& ctx, std::vector<double>& bt, const std::function<bool(std::size_t)>& in_sheet,
                          const std::function<bool(std::size_t)>& closed);
// The same on certified enclosures (an exact engine's): the mutated value's shift moves the
// whole enclosure (an infinite value makes it infinite).
void mutate_enclosures(const CheckContext& ctx, std::vector<Interval>& bt, const std::function<bool(std::size_t)>& in_sheet,
                       const std::function<bool(std::size_t)>& closed);

}  // namespace grassfire::checks
