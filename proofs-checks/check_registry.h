// check_registry.h -- the proof checks: one function per proposition, one report table.
//
// Each proofs-checks/check_*.cpp registers functions that check a proposition of the
// dissertation numerically on many instances and return rows of the report:
// proposition, instances, points checked, worst violation, verdict (DESIGN.md 6).
// `worst_violation` is the largest amount by which a checked inequality failed (0 when
// none did), or the count of failed exact conditions, as `unit` says.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace grassfire::checks {

struct CheckRow {
  std::string proposition;     // e.g. "Prop 1 (EDF >= R, = only at leaves)"
  std::string corpus;          // e.g. "shapes2d (116 real) + 200 generated"
  std::uint64_t instances = 0;
  std::uint64_t points = 0;
  double worst_violation = 0.0;
  std::string unit;            // "length", "count", ...
  bool pass = false;
  std::string note;
};

struct CheckContext {
  std::string data_dir;  // the project's data/ folder
  bool quick = false;    // CTest: fewer instances; the main job runs the full set
};

using CheckFn = std::function<std::vector<CheckRow>(const CheckContext&)>;
bool register_check(std::string name, CheckFn fn);
std::vector<std::pair<std::string, CheckFn>> registered_checks();

}  // namespace grassfire::checks

#define GF_CHECK_CONCAT_INNER(a, b) a##b
#define GF_CHECK_CONCAT(a, b) GF_CHECK_CONCAT_INNER(a, b)
#define GF_REGISTER_CHECK(name, fn) \
  static const bool GF_CHECK_CONCAT(gf_registered_check_, __LINE__) = ::grassfire::checks::register_check(name, fn)
