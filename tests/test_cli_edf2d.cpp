// The `grassfire edf2d` command, run as a user would: exit codes, messages, outputs.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "support.h"

namespace {

using grassfire::testing::CliRun;
using grassfire::testing::temp_path;

CliRun run(const std::string& args) { return grassfire::testing::run_cli(args); }
std::string temp(const std::string& name) { return temp_path(name); }

}  // namespace

TEST_CASE("edf2d writes the documented JSON for a built-in shape", "[cli]") {
  const std::string out = temp("gf_cli_branches.json");
  std::filesystem::remove(out);
  const CliRun r = run("edf2d branches --samples 1500 --json " + out);
  REQUIRE(r.code == 0);
  CHECK(r.output.find("EMA        point") != std::string::npos);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["format"] == "grassfire-medial2d");
  CHECK(j["version"] == 1);
  CHECK(j["samples"] == 1500);
  REQUIRE(j["nodes"].size() > 100);
  CHECK(j["edges"].size() == j["nodes"].size() - 1);  // a tree
  for (const auto& n : j["nodes"]) {
    CHECK(n["edf"].get<double>() >= n["R"].get<double>() - j["error_bound"]["edf"].get<double>() -
                                         j["error_bound"]["R"].get<double>());
    CHECK(n["st"].get<double>() >= -1e-12);
    CHECK(n["st"].get<double>() <= 1.0);
  }
  CHECK(j["ema"]["kind"] == "point");
  CHECK(j["error_bound"]["edf"].get<double>() < 1e-9);
}

TEST_CASE("edf2d on a shape with a hole reports the cycles and infinite EDF", "[cli]") {
  const std::string out = temp("gf_cli_hole.json");
  REQUIRE(run("edf2d hole --json " + out + " --quiet").code == 0);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["ema"]["kind"] == "cycles");
  int infinite = 0;
  for (const auto& n : j["nodes"]) infinite += n["edf"].is_string() && n["edf"] == "inf";
  CHECK(infinite == static_cast<int>(j["ema"]["nodes"].size()));
}

TEST_CASE("edf2d rejects malformed input: message names the file, exit code 1, no output", "[cli]") {
  const std::string out = temp("gf_cli_never.json");
  std::filesystem::remove(out);
  // tests/data/shapes/README.md lists these four as valid; every other file is invalid.
  const std::set<std::string> valid{"reversed_orientation.wkt", "unclosed.txt", "multipolygon_one.wkt",
                                    "boost_polygon_43.wkt"};
  int rejected = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GF_TEST_DATA) + "/shapes")) {
    const std::string path = entry.path().string();
    const std::string ext = entry.path().extension();
    if (ext != ".json" && ext != ".wkt" && ext != ".txt") continue;
    if (valid.count(entry.path().filename().string())) {
      CHECK(run("edf2d " + path + " --quiet").code == 0);
      continue;
    }
    INFO(path);
    ++rejected;
    const CliRun r = run("edf2d " + path + " --json " + out);
    CHECK(r.code == 1);
    CHECK(r.output.find(entry.path().filename().string()) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  CHECK(rejected >= 25);
}

TEST_CASE("edf2d command-line errors and help", "[cli]") {
  CHECK(run("edf2d --help").code == 0);
  CHECK(run("--help").code == 0);
  CHECK(run("edf2d").code == 2);
  CHECK(run("edf2d branches --samples many").code == 1);
  CHECK(run("edf2d branches --bogus").code == 2);
  CHECK(run("edf2d branches --variant fast").code == 1);
  const CliRun missing = run("edf2d no-such-shape");
  CHECK(missing.code == 1);
  CHECK(missing.output.find("no-such-shape") != std::string::npos);
  CHECK(run("frobnicate").code == 2);
}

TEST_CASE("edf2d variants and the exact polygon axis run from the command line", "[cli]") {
  CHECK(run("edf2d rectangle --variant dissertation --quiet").code == 0);
  const CliRun exact = run("edf2d rectangle --exact");
  CHECK(exact.code == 0);
  CHECK(exact.output.find("exact polygon axis") != std::string::npos);
}
