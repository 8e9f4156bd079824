// grassfire complex / medial3d --complex / burn3d with JSON complexes, sources, queries, CSV;
// burn3d --method exact: closed-form values with certified errors, the certification
// counts, the discrete baseline as an upper bound, clean refusals.
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

TEST_CASE("grassfire burn3d --method exact --singular-walls: the board and fin with N as a wall", "[cli][exact3]") {
  // Part 1's semantics: fire stops at the singular curve N (x = y, z = 0). Closed forms
  // (4.2.1 before any junction rule): on the fin sqrt 2 (x - 1); on the back of the board
  // y; on the front, past the corner c = (1, 1, 0), 1 + |p - c|.
  const std::string at = temp_path("gf_walls_at.csv"), csv = temp_path("gf_walls.csv"),
                    json = temp_path("gf_walls.json");
  write_text(at, "x,y,z\n3,3,1\n4,2,0\n2,4,0\n");
  const testing::CliRun r =
      run_cli("burn3d board-fin --method exact --singular-walls --at " + at + " --csv " + csv + " --json " + json);
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("singular edges burned as walls, not Definition 9"));
  const auto rows = csv_rows(slurp(csv));
  REQUIRE(rows.size() == 4);
  const double expected[] = {2 * std::sqrt(2.0), 2.0, 1 + std::sqrt(10.0)};
  for (int i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(std::fabs(std::stod(rows[i + 1][3]) - expected[i]) <= std::stod(rows[i + 1][4]) + 1e-15);
    CHECK(std::stod(rows[i + 1][4]) < 1e-10);
  }
  const nlohmann::json j = nlohmann::json::parse(slurp(json));
  CHECK(j["stats"]["uncertified"] == 0);
  CHECK_THAT(j["stats"]["singular_edges"].get<std::string>(), Catch::Contains("walls"));
  // Without the flag: Definition 9 (the junction rule). The front of the board burns from N
  // at y where x < 2 + sqrt 2 (4.2.1), the back and the fin as before; one kink below E at
  // (2 + sqrt 2, 2 + sqrt 2, 0) with BT 2 + sqrt 2 in the report.
  const testing::CliRun def9 = run_cli("burn3d board-fin --method exact --at " + at + " --csv " + csv + " --json " + json);
  INFO(def9.output);
  REQUIRE(def9.code == 0);
  const auto rows9 = csv_rows(slurp(csv));
  REQUIRE(rows9.size() == 4);
  const double expected9[] = {2 * std::sqrt(2.0), 2.0, 4.0};
  for (int i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(std::fabs(std::stod(rows9[i + 1][3]) - expected9[i]) <= std::stod(rows9[i + 1][4]) + 1e-15);
  }
  const nlohmann::json j9 = nlohmann::json::parse(slurp(json));
  CHECK_THAT(j9["stats"]["singular_edges"].get<std::string>(), Catch::Contains("junction rule"));
  CHECK(j9["stats"]["events"]["kinks"].get<int>() == 1);
  CHECK(j9["stats"]["events"]["continued_pieces"].get<int>() > 0);
  CHECK(j9["stats"]["unclassified_switches"].get<int>() == 0);
  CHECK(j9["stats"]["merges"].empty());
  // The quench where the kink's front meets the fire of the far end (12, 12, 0) on N
  // (test_burn3_junction_points.cpp): s = 13/2 + 3 sqrt2, BT 6 + 11/2 sqrt2.
  REQUIRE(j9["stats"]["quenches"].size() == 1);
  CHECK(j9["stats"]["events"]["quenches"].get<int>() == 1);
  for (const auto& k : j9["stats"]["quenches"]) {
    const double s = 6.5 + 3 * std::sqrt(2.0), bt = 6 + 5.5 * std::sqrt(2.0), err = k["error"].get<double>();
    CHECK(err < 1e-9);
    for (const char* c : {"x", "y"}) CHECK(std::fabs(k[c].get<double>() - s) <= err + 4e-15);
    CHECK(std::fabs(k["bt"].get<double>() - bt) <= err + 4e-15);
  }
  int below_e = 0;
  for (const auto& k : j9["stats"]["kinks"]) {
    if (k["bt"].get<double>() > 12) continue;
    ++below_e;
    const double root = 2 + std::sqrt(2.0), err = k["error"].get<double>();
    CHECK(err < 1e-10);
    for (const char* c : {"x", "y", "bt"}) CHECK(std::fabs(k[c].get<double>() - root) <= err + 4e-16);
    CHECK(std::fabs(k["z"].get<double>()) <= err);
  }
  CHECK(below_e == 1);
  // The flag needs the exact method.
  const testing::CliRun discrete = run_cli("burn3d board-fin --singular-walls");
  CHECK(discrete.code == 1);
  CHECK_THAT(discrete.output, Catch::Contains("--singular-walls needs --method exact"));
  for (const std::string& p : {at, csv, json}) std::remove(p.c_str());
}

TEST_CASE("grassfire burn3d --method exact: the cube's geodesic distances, certified", "[cli][exact3]") {
  const std::string sources = temp_path("gf_exact_sources.csv"), at = temp_path("gf_exact_at.csv"),
                    csv = temp_path("gf_exact_bt.csv"), json = temp_path("gf_exact.json"),
                    dcsv = temp_path("gf_exact_discrete.csv"), djson = temp_path("gf_exact_discrete.json");
  // The cube [-1, 1]^3: the centre of the top face ignites at 0, the corner (1, 1, 1) at 1/2.
  write_text(sources, "x,y,z,t0\n0,0,1,0\n1,1,1,0.5\n");
  write_text(at, "x,y,z\n0,0,-1\n1,0,0\n0.5,0.5,1\n5,5,5\n");
  const std::string args = std::string(GF_PROJECT_DATA) + "/meshes/cube.off" + " --mesh-is-complex --sources " + sources + " --at " + at;
  testing::CliRun r = run_cli("burn3d " + args + " --method exact --csv " + csv + " --json " + json);
  INFO(r.output);
  REQUIRE(r.code == 0);
  // Unfolded by hand: the bottom centre is sqrt(10) from the corner (over the face x = 1)
  // and 4 from the top centre; (1, 0, 0) is 2 from the top centre, sqrt(2) from the corner.
  const double expected[] = {0.5 + std::sqrt(10.0), 0.5 + std::sqrt(2.0), std::sqrt(0.5), 0.5};
  const auto rows = csv_rows(slurp(csv));
  REQUIRE(rows.size() == 5);
  for (int i = 0; i < 4; ++i) {
    INFO("query " << i);
    const double bt = std::stod(rows[i + 1][3]), err = std::stod(rows[i + 1][4]);
    CHECK(std::fabs(bt - expected[i]) <= err + 1e-15);
    CHECK(err < 1e-10);
  }
  CHECK(rows[4][5] != "0");  // (5, 5, 5) snaps to the corner
  const nlohmann::json j = nlohmann::json::parse(slurp(json));
  CHECK(j["method"] == "exact");
  CHECK(j["stats"]["uncertified"] == 0);
  CHECK(j["stats"]["certification"]["filter"].get<long>() > 0);
  for (const char* key : {"exact", "arb", "exact_equal", "structural_equal", "kept_undecided", "max_bits"})
    CHECK(j["stats"]["certification"].contains(key));
  const auto& bt = j["vertex_values"]["BT"];
  const auto& err = j["vertex_values"]["BT_error"];
  REQUIRE(bt.size() == 8);
  REQUIRE(err.size() == 8);
  // The discrete baseline is an upper bound of the exact BT at every vertex and query.
  r = run_cli("burn3d " + args + " --spacing 0.05 --csv " + dcsv + " --json " + djson);
  REQUIRE(r.code == 0);
  const nlohmann::json d = nlohmann::json::parse(slurp(djson));
  CHECK_FALSE(d["vertex_values"].contains("BT_error"));
  for (std::size_t v = 0; v < 8; ++v) {
    const double e = bt[v].get<double>(), de = err[v].get<double>(), dv = d["vertex_values"]["BT"][v].get<double>();
    CHECK(dv >= e - de);
    CHECK(dv <= e + 0.05);
    if (v == 6) CHECK(std::fabs(e - 0.5) <= de);  // the corner source (1, 1, 1)
  }
  const auto drows = csv_rows(slurp(dcsv));
  for (int i = 1; i <= 4; ++i) CHECK(std::stod(drows[i][3]) >= std::stod(rows[i][3]) - std::stod(rows[i][4]));
  for (const std::string& p : {sources, at, csv, json, dcsv, djson}) std::remove(p.c_str());
}

TEST_CASE("grassfire burn3d --method exact: a hinge with a hair, and clean refusals", "[cli][exact3]") {
  const std::string hinge = std::string(GF_TEST_DATA) + "/3d/hinge.json";
  const std::string sources = temp_path("gf_exact_bad_sources.csv"), at = temp_path("gf_exact_hinge_at.csv"),
                    csv = temp_path("gf_exact_hinge.csv"), json = temp_path("gf_exact_hinge.json");
  // The hair [(2,0,0), (3,0,0)] burns from its free end (f = R = 0 there) and from the
  // hinge's vertex (2,0,0), which burns at R = 1/2: BT(2.5, 0, 0) = 1/2 from both ends.
  write_text(at, "x,y,z\n3,0,0\n2.5,0,0\n2.75,0,0\n");
  testing::CliRun r = run_cli("burn3d " + hinge + " --method exact --at " + at + " --csv " + csv);
  INFO(r.output);
  REQUIRE(r.code == 0);
  const auto rows = csv_rows(slurp(csv));
  REQUIRE(rows.size() == 4);
  const double expected[] = {0.0, 0.5, 0.25};
  for (int i = 0; i < 3; ++i) CHECK(std::fabs(std::stod(rows[i + 1][3]) - expected[i]) <= std::stod(rows[i + 1][4]));
  const auto check_fails = [&](const std::string& args, const std::string& message) {
    std::remove(csv.c_str());
    std::remove(json.c_str());
    const testing::CliRun f = run_cli("burn3d " + args + " --method exact --at " + at + " --csv " + csv + " --json " + json);
    INFO(f.output);
    CHECK(f.code == 1);
    CHECK_THAT(f.output, Catch::Contains(message));
    CHECK_FALSE(exists(csv));
    CHECK_FALSE(exists(json));
  };
  // Singular points burn by the link rule now: the double cone's apex is no refusal.
  const testing::CliRun cone = run_cli("burn3d double-cone --method exact --at " + at + " --csv " + csv);
  INFO(cone.output);
  CHECK(cone.code == 0);
  write_text(sources, "x,y,z,t0\n2.5,0,0,0\n");
  check_fails(hinge + " --sources " + sources, "hinge.json: source 1: a point source inside a segment (edge 5)");
  for (const std::string& p : {sources, at}) std::remove(p.c_str());
}

namespace {

// An octahedron whose coordinates are written as a mesh file writes them (7 significant
// digits, none a double exactly), in each text format; vertices 0..5 = c +- d e_i.
const char* const kOctaVertices[6][3] = {{"0.0265006", "0.00349105", "0.0598442"},
                                         {"0.0065004", "0.00349105", "0.0598442"},
                                         {"0.0165005", "0.01349115", "0.0598442"},
                                         {"0.0165005", "-0.00650905", "0.0598442"},
                                         {"0.0165005", "0.00349105", "0.0698443"},
                                         {"0.0165005", "0.00349105", "0.0498441"}};
const int kOctaFaces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

std::string octahedron_text(const std::string& format) {
  std::ostringstream o;
  auto xyz = [&](int v, const char* sep) {
    o << kOctaVertices[v][0] << sep << kOctaVertices[v][1] << sep << kOctaVertices[v][2];
  };
  if (format == "off") o << "OFF\n6 8 0\n";
  if (format == "ply")
    o << "ply\nformat ascii 1.0\nelement vertex 6\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 8\nproperty list uchar int vertex_indices\nend_header\n";
  if (format == "json") o << "{\"format\": \"grassfire-complex\", \"version\": 1, \"vertices\": [";
  if (format == "stl") {
    o << "solid octa\n";
    for (const auto& f : kOctaFaces) {
      o << "facet normal 0 0 0\nouter loop\n";
      for (int v : f) o << "vertex ", xyz(v, " "), o << "\n";
      o << "endloop\nendfacet\n";
    }
    o << "endsolid octa\n";
    return o.str();
  }
  for (int v = 0; v < 6; ++v) {
    if (format == "obj") o << "v ";
    if (format == "json") o << (v ? ", [" : "[");
    xyz(v, format == "json" ? ", " : " ");
    o << (format == "json" ? "]" : "\n");
  }
  if (format == "json") o << "], \"triangles\": [";
  for (int f = 0; f < 8; ++f) {
    const auto& t = kOctaFaces[f];
    if (format == "json") o << (f ? ", " : "") << "[" << t[0] << ", " << t[1] << ", " << t[2] << "]";
    else if (format == "obj") o << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    else o << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  if (format == "json") o << "]}\n";
  return o.str();
}

}  // namespace

TEST_CASE("a mesh's own vertex coordinates are sources and queries on it, in every text format", "[cli][exact3][decimals]") {
  const std::string sources = temp_path("gf_octa_sources.csv"), at = temp_path("gf_octa_at.csv"),
                    csv = temp_path("gf_octa_bt.csv");
  write_text(sources, std::string("x,y,z,t0\n") + kOctaVertices[0][0] + "," + kOctaVertices[0][1] + "," +
                          kOctaVertices[0][2] + ",0\n");
  std::string queries = "x,y,z\n";
  for (const auto& v : kOctaVertices) queries += std::string(v[0]) + "," + v[1] + "," + v[2] + "\n";
  write_text(at, queries);
  for (const std::string format : {"off", "obj", "ply", "stl", "json"}) {
    const std::string mesh = temp_path("gf_octa." + format);
    write_text(mesh, octahedron_text(format));
    std::remove(csv.c_str());
    const testing::CliRun r = run_cli("burn3d " + mesh + " --mesh-is-complex --method exact --sources " + sources +
                                      " --at " + at + " --csv " + csv + " --no-border-ignition");
    INFO(format << ": " << r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("within the rounding") == std::string::npos);  // located exactly
    const auto rows = csv_rows(slurp(csv));
    REQUIRE(rows.size() == 7);
    // BT at the source vertex is its t0; at the opposite vertex the straight path across two
    // faces (unfolded, the long diagonal of a rhombus of side d sqrt(2)): d sqrt(6).
    CHECK(std::fabs(std::stod(rows[1][3])) <= std::stod(rows[1][4]));
    CHECK(std::fabs(std::stod(rows[2][3]) - 0.0100001 * std::sqrt(6.0)) <= std::stod(rows[2][4]) + 1e-15);
    std::remove(mesh.c_str());
  }
  // A source off the mesh by its coordinates' rounding is moved to the mesh, with a note;
  // one farther off is refused.
  const std::string off = temp_path("gf_octa.off");
  write_text(off, octahedron_text("off"));
  write_text(sources, "x,y,z,t0\n0.026500600000000000001,0.00349105,0.0598442,0\n");
  testing::CliRun r = run_cli("burn3d " + off + " --mesh-is-complex --method exact --sources " + sources + " --at " + at +
                              " --csv " + csv + " --no-border-ignition");
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK_THAT(r.output, Catch::Contains("located at its nearest point of the complex, at distance 1"));
  write_text(sources, "x,y,z,t0\n0.0265006000001,0.00349105,0.0598442,0\n");
  r = run_cli("burn3d " + off + " --mesh-is-complex --method exact --sources " + sources + " --at " + at + " --csv " + csv);
  CHECK(r.code == 1);
  CHECK_THAT(r.output, Catch::Contains("does not lie on the complex (its nearest point is at distance "));
  for (const std::string& p : {sources, at, csv, off}) std::remove(p.c_str());
}
