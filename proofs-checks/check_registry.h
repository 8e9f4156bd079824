// check_registry.h -- the proof checks: rows of evidence that the propositions hold, and
// the mutants that show each row could have failed.
//
// A row claims that a proposition of the dissertation holds on a corpus. It is evidence
// only if it could have failed (STYLE.md, "How the most trusted projects test their
// tests"), so every row carries:
//  - `reference`: the independent computation the engine is compared with (a closed form,
//    the definition evaluated by brute force, another algorithm, exact geodesic
//    distances, a combinatorial peeling). A row with no independent computation yet has
//    the verdict NotChecked, says why in its note, and counts as "not checked" in the
//    summary, never as "pass".
//  - `tolerance`: where any allowance comes from: "exact" (certified comparisons), or a
//    bound that is stated and derived in the note or in a header, never the engine's own
//    measured error.
//  - its mutants: each check family declares the mutants it can inject (deliberately
//    broken engine outputs, a broken rule passed to an engine through a hook such as
//    DiscreteBurningOptions::rule_override, or an input seen by the engine only; the
//    reference side is never mutated). `proof_checks --mutants` reruns each family once
//    per mutant (ctx.mutant) and reports, per row, the mutants that turned its pass into a
//    fail. Every checked row must detect at least one mutant that violates its
//    proposition; CTest fails otherwise.
//
// Adding rows (for instance chapter 4 on the exact burning time, docs/exact-engine.md):
//  1. In a new proofs-checks/check_*.cpp (CMake globs them), write
//       std::vector<CheckRow> my_check(const CheckContext& ctx)
//     building its corpora at the size ctx.size asks for (Tiny is what `--mutants` runs
//     once per mutant, in CTest too: keep it to a second or two). Fill one CheckRow per
//     (proposition, corpus): `reference`, `tolerance`, and `verdict = verdict_of(t)` from
//     a Tally of instances, points and violations, or Verdict::NotChecked with the reason
//     in `note` when there is no independent computation yet.
//  2. Inject ctx.mutant where the engine's output is produced, before any row reads it:
//     the 3D mutants of mutants3d.h (a bump, a dip or an infinite value at one point, the
//     junction rule at the first or last arrival, late ignition) apply to any burning
//     time given per graph point; the 2D ones of mutants2d.h to a GrassfireResult.
//  3. Register with the mutants it understands:
//       GF_REGISTER_CHECK("my-check", my_check, (MutantList{{"bt-bump", "..."}, ...}));
//     Mutants the family does not list are never passed to it. Under a mutant a family
//     may leave out rows that mutant cannot reach (e.g. PR rows under a mutant of the
//     burning, which PR never reads), to keep the mutant runs short.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace grassfire::checks {

enum class Verdict { Pass, Fail, NotChecked };
const char* to_string(Verdict v);

struct CheckRow {
  std::string proposition;  // e.g. "Prop 1 (EDF >= R, = only at leaves)"
  std::string corpus;       // what the instances are: "real", "generated", "synthetic"
  std::string reference;    // the independent computation the engine is compared with
  std::string tolerance;    // "exact", or the stated bound any allowance comes from
  std::uint64_t instances = 0;
  std::uint64_t points = 0;
  double worst_violation = 0.0;
  std::string unit;  // "length", "count", ...
  Verdict verdict = Verdict::Fail;
  std::string note;
};

// Counts of one row. A row with no instance or no point checked fails: it tested nothing.
struct Tally {
  std::uint64_t instances = 0, points = 0, violations = 0;
  double worst = 0;
};
inline Verdict verdict_of(const Tally& t) {
  return t.instances > 0 && t.points > 0 && t.violations == 0 ? Verdict::Pass : Verdict::Fail;
}

// A row from a Tally: worst violation t.worst, the verdict verdict_of(t), and the count
// of violations appended to the note.
inline CheckRow tally_row(const std::string& prop, const std::string& corpus, const std::string& reference,
                          const std::string& tolerance, const Tally& t, const std::string& unit,
                          const std::string& note) {
  CheckRow r;
  r.proposition = prop;
  r.corpus = corpus;
  r.reference = reference;
  r.tolerance = tolerance;
  r.instances = t.instances;
  r.points = t.points;
  r.worst_violation = t.worst;
  r.unit = unit;
  r.verdict = verdict_of(t);
  r.note = note + (t.violations ? " (" + std::to_string(t.violations) + " violations)" : "");
  return r;
}

enum class CorpusSize { Full, Quick, Tiny };

struct CheckContext {
  std::string data_dir;                // the project's data/ folder
  CorpusSize size = CorpusSize::Full;  // Quick: CTest; Tiny: one run per mutant
  std::string mutant;                  // empty: no mutant; else one of the family's mutants
  bool quick() const { return size != CorpusSize::Full; }
  bool tiny() const { return size == CorpusSize::Tiny; }
  bool mutated(const char* name) const { return mutant == name; }
};

struct MutantInfo {
  std::string name;    // e.g. "bt-bump"
  std::string breaks;  // what is broken and where it is injected
};
using MutantList = std::vector<MutantInfo>;

using CheckFn = std::function<std::vector<CheckRow>(const CheckContext&)>;
struct RegisteredCheck {
  std::string name;
  CheckFn fn;
  MutantList mutants;
};
bool register_check(std::string name, CheckFn fn, MutantList mutants);
std::vector<RegisteredCheck> registered_checks();

}  // namespace grassfire::checks

#define GF_CHECK_CONCAT_INNER(a, b) a##b
#define GF_CHECK_CONCAT(a, b) GF_CHECK_CONCAT_INNER(a, b)
#define GF_REGISTER_CHECK(name, fn, mutants)                                      \
  static const bool GF_CHECK_CONCAT(gf_registered_check_, __LINE__) = \
      ::grassfire::checks::register_check(name, fn, mutants)
