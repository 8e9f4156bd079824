// grassfire curves3d and paths3d: documented JSON, polylines, errors without output.
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

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("curves3d writes grassfire-curves3d JSON with the axis' Betti numbers, PLY and VTK", "[cli_curves]") {
  const std::string json = temp_path("annulus_curves.json"), ply = temp_path("annulus_curves.ply"),
                    vtk = temp_path("annulus_curves.vtk");
  const auto r = run_cli("curves3d annulus --spacing 0.25 --json " + json + " --ply " + ply + " --vtk " + vtk);
  INFO(r.output);
  REQUIRE(r.code == 0);
  const nlohmann::json j = read_json(json);
  CHECK(j["format"] == "grassfire-curves3d");
  CHECK(j["version"] == 1);
  CHECK(j["betti"] == nlohmann::json::array({1, 1}));
  CHECK(j["axis_betti"] == nlohmann::json::array({1, 1, 0}));
  REQUIRE(j["nodes"].size() > 10);
  for (const auto& e : j["edges"]) {
    const auto& u = j["nodes"][e["u"].get<std::size_t>()];
    const auto& v = j["nodes"][e["v"].get<std::size_t>()];
    const double dx = u["x"].get<double>() - v["x"].get<double>(), dy = u["y"].get<double>() - v["y"].get<double>(),
                 dz = u["z"].get<double>() - v["z"].get<double>();
    CHECK(e["length"].get<double>() == Approx(std::sqrt(dx * dx + dy * dy + dz * dz)));
  }
  for (const auto& n : j["nodes"]) CHECK(n["et"].get<double>() == Approx(n["bt"].get<double>() - n["R"].get<double>()));
  std::ifstream p(ply), v(vtk);
  std::string first;
  std::getline(p, first);
  CHECK(first == "ply");
  std::stringstream vs;
  vs << v.rdbuf();
  CHECK(vs.str().find("LINES " + std::to_string(j["edges"].size())) != std::string::npos);
  for (const std::string& f : {json, ply, vtk}) std::remove(f.c_str());
}

TEST_CASE("paths3d writes the burning paths of curve nodes, vertices and given points", "[cli_curves]") {
  const std::string json = temp_path("paths.json"), points = temp_path("paths_points.txt");
  {
    std::ofstream out(points);
    out << "# points\nx,y,z\n5, 5, 2\n-2,3,0\n";
  }
  auto r = run_cli("paths3d board-fin --spacing 0.25 --from points --points " + points + " --json " + json);
  INFO(r.output);
  REQUIRE(r.code == 0);
  nlohmann::json j = read_json(json);
  CHECK(j["format"] == "grassfire-paths3d");
  REQUIRE(j["paths"].size() == 2);
  CHECK(j["paths"][0]["bt"].get<double>() == Approx(4 * std::sqrt(2.0)).margin(1e-9));  // the fin: sqrt2 (s - 1)
  CHECK(j["paths"][1]["bt"].get<double>() == Approx(3).margin(1e-9));                     // the board: y
  CHECK(j["paths"][1]["points"].back()[1].get<double>() == Approx(0).margin(1e-12));      // down to B
  r = run_cli("paths3d tube --spacing 0.5 --from vertices --json " + json);
  REQUIRE(r.code == 0);
  j = read_json(json);
  CHECK(j["from"] == "vertices");
  CHECK(j["paths"].size() > 50);
  for (const std::string& f : {json, points}) std::remove(f.c_str());
}

TEST_CASE("curves3d and paths3d: bad input gives one message and no output", "[cli_curves]") {
  const std::string json = temp_path("bad_curves.json"), points = temp_path("bad_points.txt");
  auto r = run_cli("curves3d no-such-file.off --json " + json);
  CHECK(r.code == 1);
  CHECK(r.output.find("no-such-file.off") != std::string::npos);
  CHECK(!exists(json));
  r = run_cli("curves3d annulus --arrive-cosine 2 --json " + json);
  CHECK(r.code == 1);
  CHECK(!exists(json));
  {
    std::ofstream out(points);
    out << "x,y,z\n1,2\n";
  }
  r = run_cli("paths3d annulus --from points --points " + points + " --json " + json);
  CHECK(r.code == 1);
  CHECK(r.output.find(points + ":2:") != std::string::npos);
  CHECK(!exists(json));
  r = run_cli("paths3d annulus --from nowhere");
  CHECK(r.code == 1);
  std::remove(points.c_str());
}

TEST_CASE("curves3d and paths3d --method exact: the exact engine's field, Definition 9 at singular edges",
          "[cli_curves][exact3]") {
  const std::string json = temp_path("exact_curves.json"), paths = temp_path("exact_paths.json");
  auto r = run_cli("curves3d annulus --method exact --spacing 0.25 --json " + json);
  INFO(r.output);
  REQUIRE(r.code == 0);
  nlohmann::json j = read_json(json);
  CHECK(j["betti"] == nlohmann::json::array({1, 1}));
  CHECK(j["method"].get<std::string>().find("exact") != std::string::npos);
  // The tube burns from both rims: BT = distance to the nearer rim, the path straight down
  // or up to it (the side unrolls into a strip).
  r = run_cli("paths3d tube --method exact --from vertices --json " + paths);
  REQUIRE(r.code == 0);
  j = read_json(paths);
  REQUIRE(j["paths"].size() > 50);
  for (const auto& p : j["paths"]) {
    const double z = p["points"][0][2].get<double>(), end = p["points"].back()[2].get<double>();
    CHECK(p["bt"].get<double>() == Approx(std::min(z, 8 - z)).margin(1e-9));
    CHECK(std::min(end, 8 - end) == Approx(0).margin(1e-9));
  }
  // Singular edges burn by Definition 9: the curves keep the (contractible) axis' topology.
  r = run_cli("curves3d board-fin --method exact --json " + json);
  REQUIRE(r.code == 0);
  j = read_json(json);
  CHECK(j["method"].get<std::string>().find("Definition 9") != std::string::npos);
  CHECK(j["betti"] == nlohmann::json::array({1, 0}));
  CHECK(j["axis_betti"] == nlohmann::json::array({1, 0, 0}));
  r = run_cli("paths3d board-fin --method exact --singular-walls --from vertices --json " + paths);
  CHECK(r.code == 0);
  r = run_cli("curves3d annulus --singular-walls --json " + json);
  CHECK(r.code == 1);
  CHECK(r.output.find("--singular-walls needs --method exact") != std::string::npos);
  for (const std::string& f : {json, paths}) std::remove(f.c_str());
}
