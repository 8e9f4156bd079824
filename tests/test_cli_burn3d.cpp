// grassfire complex / medial3d --complex / burn3d with JSON complexes, sources, queries, CSV.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "burn3/point_sources.h"
#include "io/complex_json.h"
#include "support.h"
#include "test_sheets_support.h"

using namespace grassfire;
using testing::run_cli;
using testing::temp_path;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

bool exists(const std::string& path) { return std::filesystem::exists(path); }

nlohmann::json burn_report(const std::string& args) {
  const std::string json = temp_path("gf_cli_burn3d_report.json");
  std::remove(json.c_str());
  const testing::CliRun r = run_cli("burn3d " + args + " --json " + json);
  INFO(r.output);
  REQUIRE(r.code == 0);
  const nlohmann::json j = nlohmann::json::parse(slurp(json));
  std::remove(json.c_str());
  return j;
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::istringstream ls(line);
    for (std::string f; std::getline(ls, f, ',');) row.push_back(f);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("grassfire complex --json: a synthetic complex burns the same from its JSON", "[cli][complex_json]") {
  const std::string path = temp_path("gf_cli_book.json");
  const testing::CliRun r = run_cli("complex book:3 --json " + path);
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("3 sheets"));
  const nlohmann::json a = burn_report("book:3 --spacing 0.25");
  const nlohmann::json b = burn_report(path + " --spacing 0.25");
  CHECK(a["complex"] == b["complex"]);
  CHECK(a["vertex_values"]["BT"] == b["vertex_values"]["BT"]);
  std::remove(path.c_str());
}

TEST_CASE("grassfire medial3d --complex: the axis as JSON burns like the axis built in burn3d", "[cli][complex_json]") {
  const std::string cube = std::string(GF_PROJECT_DATA) + "/meshes/cube.off";
  const std::string path = temp_path("gf_cli_cube_axis.json");
  const testing::CliRun r = run_cli("medial3d " + cube + " --complex " + path);
  INFO(r.output);
  REQUIRE(r.code == 0);
  const RawComplex axis = read_complex_json(path);
  CHECK(axis.triangles.size() > 0);
  const nlohmann::json a = burn_report(cube + " --spacing 0.1");
  const nlohmann::json b = burn_report(path + " --spacing 0.1");
  CHECK(b["complex"]["singular_edges"] == 8);
  CHECK(a["vertex_values"]["BT"] == b["vertex_values"]["BT"]);
  CHECK(a["vertex_values"]["R"] == b["vertex_values"]["R"]);
  std::remove(path.c_str());
}

TEST_CASE("grassfire burn3d --sources --at --csv: rows in query order with the query's own text", "[cli][sources]") {
  const std::string complex = temp_path("gf_cli_square.json");
  write_complex_json(testing::grid_sheet({{"##", "##"}, 2}), complex);  // [0,2]^2, border ignites at 0
  const std::string sources = temp_path("gf_cli_sources.csv"), at = temp_path("gf_cli_at.csv"),
                    out = temp_path("gf_cli_bt.csv");
  write_text(sources, "x,y,z,t0\n# a comment\n1.25, 0.5, 0, 0.125\n");
  write_text(at, " x , y , z \n1.250,0.5,0\n+1,1,0\n\n1,1,2.5\n3,1,0\n");
  std::remove(out.c_str());
  testing::CliRun r = run_cli("burn3d " + complex + " --no-border-ignition --spacing 0.05 --sources " + sources +
                              " --at " + at + " --csv " + out);
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("1 point sources, 4 queries"));
  std::vector<std::vector<std::string>> rows = csv_rows(slurp(out));
  REQUIRE(rows.size() == 5);
  CHECK(rows[0] == std::vector<std::string>{"x", "y", "z", "bt", "bt_error", "snap"});
  CHECK(rows[1][0] == "1.250");  // the query's own text
  CHECK(rows[2][0] == "+1");
  CHECK(std::stod(rows[1][3]) == 0.125);  // at the source
  const double d = std::hypot(0.25, 0.5);
  CHECK(std::stod(rows[2][3]) >= 0.125 + d - 1e-12);  // (1, 1): straight distance to the source
  CHECK(std::stod(rows[2][3]) <= 0.125 + d + 0.01);
  CHECK(rows[2][4] == "inf");  // the discrete method certifies no two-sided bound
  CHECK(rows[3][5] == "2.5");  // (1, 1, 2.5) snaps to (1, 1, 0)
  CHECK(rows[3][3] == rows[2][3]);
  CHECK(rows[4][5] == "1");    // (3, 1, 0) snaps to (2, 1, 0)
  // With the border burning too (f = 0 there), (1, 1) is 1 from the border.
  r = run_cli("burn3d " + complex + " --spacing 0.05 --sources " + sources + " --at " + at + " --csv " + out);
  REQUIRE(r.code == 0);
  rows = csv_rows(slurp(out));
  CHECK(std::stod(rows[2][3]) == Approx(0.125 + d).margin(0.01));
  CHECK(std::stod(rows[4][3]) == 0);  // (2, 1) is on the border
  // A closed surface without sources never burns: inf.
  write_text(at, "x,y,z\n0.25,0.25,0\n");
  r = run_cli("burn3d tetrahedron --at " + at + " --csv " + out);
  REQUIRE(r.code == 0);
  CHECK(csv_rows(slurp(out))[1] == std::vector<std::string>{"0.25", "0.25", "0", "inf", "inf", "0"});
  for (const std::string& p : {complex, sources, at, out}) std::remove(p.c_str());
}

TEST_CASE("grassfire burn3d: bad sources, queries and complexes fail cleanly, with no output", "[cli][sources]") {
  const std::string sources = temp_path("gf_cli_bad_sources.csv"), at = temp_path("gf_cli_bad_at.csv"),
                    out = temp_path("gf_cli_bad_out.csv"), json = temp_path("gf_cli_bad_out.json");
  write_text(at, "x,y,z\n0,0,0\n");
  const auto check_fails = [&](const std::string& args, const std::string& message) {
    std::remove(out.c_str());
    std::remove(json.c_str());
    const testing::CliRun r = run_cli("burn3d " + args + " --csv " + out + " --json " + json);
    INFO(args);
    INFO(r.output);
    CHECK(r.code == 1);
    CHECK_THAT(r.output, Catch::Contains(message));
    CHECK_FALSE(exists(out));
    CHECK_FALSE(exists(json));
    CHECK_FALSE(exists(out + ".partial"));
  };
  write_text(sources, "x,y,z,t0\n0,0,0,0\n0,0,-0.5,1\n");
  check_fails("tetrahedron --sources " + sources + " --at " + at,
              sources + ":3: source (0, 0, -0.5) does not lie on the complex (its nearest point is at distance 0.5)");
  write_text(sources, "x,y,z\n0,0,0\n");
  check_fails("tetrahedron --sources " + sources + " --at " + at, sources + ":1: the header must be 'x,y,z,t0'");
  write_text(sources, "x,y,z,t0\n0,0,nan,0\n");
  check_fails("tetrahedron --sources " + sources + " --at " + at, sources + ":2: z is not a decimal number: 'nan'");
  write_text(sources, "x,y,z,t0\n0,0,0\n");
  check_fails("tetrahedron --sources " + sources + " --at " + at, sources + ":2: 3 fields where 'x,y,z,t0' has 4");
  write_text(sources, "");
  check_fails("tetrahedron --sources " + sources + " --at " + at, sources + ": no header line");
  check_fails("tetrahedron --at " + at + " --method exact", "method 'exact' is not available yet");
  check_fails(std::string(GF_TEST_DATA) + "/3d/bad_complex_index.json --at " + at,
              "bad_complex_index.json: triangles[0][2]: vertex index 7 is out of range");
  check_fails(std::string(GF_TEST_DATA) + "/3d/bad_complex_degenerate.json --at " + at, "bad_complex_degenerate.json");
  const testing::CliRun no_at = run_cli("burn3d tetrahedron --csv " + out);
  CHECK(no_at.code == 1);
  CHECK_THAT(no_at.output, Catch::Contains("--csv needs --at"));
  // An output that cannot be written: an error naming it, nothing left behind.
  const std::string missing_dir = temp_path("gf_no_such_dir") + "/bt.csv";
  const testing::CliRun unwritable = run_cli("burn3d tetrahedron --at " + at + " --csv " + missing_dir);
  CHECK(unwritable.code == 1);
  CHECK_THAT(unwritable.output, Catch::Contains(missing_dir));
  CHECK_FALSE(exists(missing_dir + ".partial"));
  for (const std::string& p : {sources, at}) std::remove(p.c_str());
}
