// burn3d --field and curves3d / paths3d / prune3d --field: the burning written once and read
// back gives the same curves, paths and pruned axis as burning again; a field burned on
// another complex, or a file that is not a field, is refused naming the file, with no output.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support.h"

using grassfire::testing::run_cli;
using grassfire::testing::temp_path;

namespace {

bool exists(const std::string& path) { return std::ifstream(path).good(); }

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The document without its timings (members "seconds", "burning", "pruning" of "seconds").
nlohmann::json without_timings(nlohmann::json j) {
  if (j.is_object()) {
    j.erase("seconds");
    for (auto& [key, value] : j.items()) value = without_timings(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_timings(value);
  }
  return j;
}

nlohmann::json read_json(const std::string& path) { return without_timings(nlohmann::json::parse(file_text(path))); }

// Runs `args` and `with_field` (default: args) with --field FIELD, writing --json (and --vtk
// when `vtk`) each time; REQUIREs both succeed and write the same documents but for timings.
void require_same_with_field(const std::string& args, const std::string& field, bool vtk,
                             const std::string& with_field = "") {
  const std::string a = temp_path("field_a.json"), b = temp_path("field_b.json"), av = temp_path("field_a.vtk"),
                    bv = temp_path("field_b.vtk");
  const std::string out_a = " --json " + a + (vtk ? " --vtk " + av : ""), out_b = " --json " + b + (vtk ? " --vtk " + bv : "");
  const auto r1 = run_cli(args + out_a);
  INFO(r1.output);
  REQUIRE(r1.code == 0);
  const auto r2 = run_cli((with_field.empty() ? args : with_field) + " --field " + field + out_b);
  INFO(r2.output);
  REQUIRE(r2.code == 0);
  CHECK(read_json(a) == read_json(b));
  if (vtk) CHECK(file_text(av) == file_text(bv));
  for (const std::string& f : {a, b, av, bv}) std::remove(f.c_str());
}

}  // namespace

TEST_CASE("curves3d paths3d and prune3d give the same results from a burn3d --field file", "[cli_curves]") {
  const std::string field = temp_path("board_fin_field.json");
  const auto w = run_cli("burn3d board-fin --spacing 0.1 --field " + field);
  INFO(w.output);
  REQUIRE(w.code == 0);
  const nlohmann::json f = nlohmann::json::parse(file_text(field));
  CHECK(f["format"] == "grassfire-burn3d-field");
  CHECK(f["method"] == "discrete");
  CHECK(f["spacing"] == 0.1);
  require_same_with_field("curves3d board-fin --spacing 0.1", field, true);
  // Without --spacing the spacing is the file's.
  require_same_with_field("curves3d board-fin --spacing 0.1", field, true, "curves3d board-fin");
  require_same_with_field("paths3d board-fin --spacing 0.1 --from curves", field, false);
  require_same_with_field("paths3d board-fin --spacing 0.1 --from vertices", field, false);
  require_same_with_field("prune3d board-fin --method discrete --spacing 0.1 --et 0.5", field, false);
  std::remove(field.c_str());
}

TEST_CASE("a field file of another complex or not a field file is refused with no output", "[cli_curves]") {
  const std::string field = temp_path("box_field.json"), report = temp_path("box_report.json"),
                    out = temp_path("refused_curves.json");
  REQUIRE(run_cli("burn3d box:12:8:4 --spacing 0.25 --field " + field + " --json " + report).code == 0);
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      // The same counts, other coordinates: the digest tells them apart.
      {"curves3d box:12:8:5 --field " + field, field + ": the field was burned on another complex (its digest"},
      {"curves3d board-fin --field " + field, field + ": the field was burned on another complex ("},
      {"curves3d box:12:8:4 --field " + report, report + ": not a burning field"},
      {"curves3d box:12:8:4 --field " + field + " --spacing 0.5", "is not the spacing of --field " + field},
      {"curves3d box:12:8:4 --field " + field + " --method exact", "--field " + field + " holds a discrete burning"},
      {"prune3d box:12:8:4 --et 0.5 --field " + field, "goes with --method discrete"},
      {"curves3d box:12:8:4 --field " + temp_path("no_such_field.json"), "no_such_field.json: cannot open file"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    const auto r = run_cli(c.args + " --json " + out);
    INFO(r.output);
    CHECK(r.code == 1);
    CHECK(r.output.find(c.message) != std::string::npos);
    CHECK(r.output.find("logic_error") == std::string::npos);
    CHECK_FALSE(exists(out));
  }
  // A field with one entry too few, and one naming a graph point that does not exist.
  nlohmann::json f = nlohmann::json::parse(file_text(field));
  const std::string broken = temp_path("broken_field.json");
  for (const std::string& what : {"short", "index"}) {
    nlohmann::json g = f;
    if (what == "short") g["arrival_from"].erase(g["arrival_from"].size() - 1);
    else g["arrival_from"][0] = 4000000000u;
    std::ofstream(broken) << g.dump();
    const auto r = run_cli("curves3d box:12:8:4 --field " + broken + " --json " + out);
    INFO(r.output);
    CHECK(r.code == 1);
    CHECK(r.output.find(broken + ": \"arrival_from\"") != std::string::npos);
    CHECK_FALSE(exists(out));
  }
  // burn3d writes a field only for a discrete burning from the border.
  for (const std::string& args : {"--method exact", "--no-border-ignition"}) {
    const auto r = run_cli("burn3d box:12:8:4 " + args + " --field " + out);
    CHECK(r.code == 1);
    CHECK(r.output.find("--field writes a discrete burning from the border") != std::string::npos);
    CHECK_FALSE(exists(out));
  }
  for (const std::string& p : {field, report, broken}) std::remove(p.c_str());
}
