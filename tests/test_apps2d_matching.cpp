// apps2d/boundary_matching.h: the cyclic dynamic-programming correspondence of two
// boundaries guided by a signature (3.5.3), against its definition.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "apps2d/boundary_matching.h"
#include "pipeline/edf2d.h"
#include "io/load_shape.h"
#include "support.h"

using namespace grassfire;

namespace {

// Multiples of 1/8 in [0, 1]: every cost the DP and the reference add up is exact.
std::vector<double> dyadic_signature(std::mt19937_64& rng, std::size_t n) {
  std::uniform_int_distribution<int> u(0, 8);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng) / 8.0;
  return v;
}

std::vector<double> rotated(const std::vector<double>& v, std::size_t k) {
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) r[i] = v[(i + k) % v.size()];
  return r;
}

std::vector<double> real_signature(const char* name, std::size_t samples) {
  const Shape2 s = load_shape(std::string(GF_PROJECT_DATA) + "/shapes2d/" + name);
  Edf2dOptions o;
  o.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(s, o);
  return local_feature_size(boundary_samples(s, samples).points, *r.graph);
}

}  // namespace

TEST_CASE("the DP equals the enumeration of every monotone path on tiny signatures", "[apps2d]") {
  std::mt19937_64 rng(2024);
  MatchOptions o;
  o.normalise = false;
  o.stretch = 0.125;
  for (int k = 0; k < 300; ++k) {
    const std::size_t n = 1 + rng() % 6, m = 1 + rng() % 6;
    const auto a = dyadic_signature(rng, n), b = dyadic_signature(rng, m);
    const BoundaryMatch fast = match_signatures(a, b, o), slow = match_signatures_reference(a, b, o);
    CHECK(fast.cost == slow.cost);
    CHECK(fast.offset == slow.offset);
    // The path is monotone, starts at (0, offset), ends at (n-1, offset + m - 1 mod m).
    REQUIRE(!fast.path.empty());
    CHECK(fast.path.front() == std::make_pair(std::uint32_t{0}, fast.offset));
    CHECK(fast.path.back().first == n - 1);
    CHECK(fast.path.back().second == (fast.offset + m - 1) % m);
    CHECK(fast.path.size() >= std::max(n, m));
  }
}

TEST_CASE("a boundary matched with itself gives the identity", "[apps2d]") {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 20; ++k) {
    const auto a = dyadic_signature(rng, 40);
    const BoundaryMatch m = match_signatures(a, a);
    CHECK(m.offset == 0);
    CHECK(m.cost == 0);
    CHECK(m.stretch_steps == 0);
    const auto corr = correspondence_of(m, a.size());
    for (std::uint32_t i = 0; i < a.size(); ++i) CHECK(corr[i] == i);
  }
  const auto lfs = real_signature("key-1.json", 120);
  const BoundaryMatch m = match_signatures(lfs, lfs);
  CHECK(m.offset == 0);
  CHECK(m.path.size() == lfs.size());
}

TEST_CASE("matching a cyclically shifted copy recovers the shift", "[apps2d]") {
  std::mt19937_64 rng(9);
  for (int k = 0; k < 20; ++k) {
    const auto a = dyadic_signature(rng, 50);
    const std::size_t shift = rng() % 50;
    const BoundaryMatch m = match_signatures(a, rotated(a, shift));
    // b = a rotated by `shift`: b_j = a_{j + shift}, so a_0 corresponds to b_{n - shift}.
    // A random signature of 50 values has no cyclic symmetry to tie with.
    CHECK(m.offset == (50 - shift) % 50);
    CHECK(m.cost == 0);
  }
  for (const char* name : {"key-1.json", "children-1.json"}) {
    const auto lfs = real_signature(name, 100);
    const BoundaryMatch m = match_signatures(lfs, rotated(lfs, 37));
    CHECK(m.offset == 63);
    CHECK(m.stretch_steps == 0);
  }
}

TEST_CASE("bad signatures are rejected with a message", "[apps2d]") {
  CHECK_THROWS_WITH(match_signatures({}, {1.0}), Catch::Contains("empty"));
  CHECK_THROWS_WITH(match_signatures({0.0, 0.0}, {1.0}), Catch::Contains("zero everywhere"));
  CHECK_THROWS_WITH(match_signatures({std::nan(""), 1.0}, {1.0}), Catch::Contains("not finite"));
}

TEST_CASE("curvature of a regular polygon is its turning angle over its side", "[apps2d]") {
  std::vector<Point2> hexagon;
  for (int i = 0; i < 6; ++i) hexagon.push_back({std::cos(i * M_PI / 3), std::sin(i * M_PI / 3)});
  for (double k : curvature_signature(hexagon)) CHECK(k == Approx(M_PI / 3).epsilon(1e-12));
  std::reverse(hexagon.begin(), hexagon.end());
  for (double k : curvature_signature(hexagon)) CHECK(k == Approx(-M_PI / 3).epsilon(1e-12));
}

TEST_CASE("boundary eccentricity signature: BE(p) >= |p - EMA| and self-matching", "[apps2d]") {
  const Shape2 s = load_shape(std::string(GF_PROJECT_DATA) + "/shapes2d/children-1.json");
  const std::size_t n = 100, refine = 5;
  const BoundarySignature be = eccentricity_signature(s, n, refine);
  REQUIRE(be.values.size() == n);
  // The same sampled axis as the signature's (n * refine samples): its EMA point.
  Edf2dOptions o;
  o.samples = n * refine;
  const Edf2dResult r = compute_edf2d(s, o);
  REQUIRE(r.burning->ema.size() == 1);
  const Point2 ema = position_of(*r.graph, r.burning->ema[0].point);
  // BE(p) = E(x) + R(x) >= |x - ema| + |x - p| >= |p - ema| (3.5.3; triangle inequality).
  for (std::size_t i = 0; i < n; ++i) {
    CHECK(be.points[i] == r.samples[0][i * refine]);
    CHECK(be.values[i] >= std::hypot(be.points[i].x - ema.x, be.points[i].y - ema.y) - 1e-9);
  }
  const BoundaryMatch m = match_signatures(be.values, be.values);
  CHECK(m.offset == 0);
  CHECK(m.cost == 0);
  CHECK_THROWS_WITH(eccentricity_signature(load_shape("hole"), 50), Catch::Contains("simply connected"));
}

TEST_CASE("signature maxima of a cyclic signal", "[apps2d]") {
  const std::vector<double> v{0, 1, 3, 1, 0, 2, 2, 0, 5, 4};
  CHECK(signature_maxima(v, 1) == std::vector<std::uint32_t>{2, 5, 8});
  CHECK(signature_maxima(v, 3) == std::vector<std::uint32_t>{8});
  CHECK(signature_maxima(std::vector<double>(6, 1.0), 2).empty());
}

using grassfire::testing::CliRun;
using grassfire::testing::run_cli;
using grassfire::testing::temp_path;

TEST_CASE("match2d: documented JSON, identity on a shape with itself, clear errors", "[apps2d][cli]") {
  const std::string a = std::string(GF_PROJECT_DATA) + "/shapes2d/key-1.json";
  const std::string out = temp_path("gf_apps2d_match.json");
  const std::string svg = temp_path("gf_apps2d_match.svg");
  std::filesystem::remove(out);
  std::filesystem::remove(svg);
  const CliRun r = run_cli("match2d " + a + " " + a + " --samples 60 --json " + out + " --svg " + svg);
  REQUIRE(r.code == 0);
  CHECK(r.output.find("offset 0") != std::string::npos);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["format"] == "grassfire-match2d");
  CHECK(j["version"] == 1);
  CHECK(j["signature"] == "be");
  CHECK(j["samples"] == 60);
  CHECK(j["offset"] == 0);
  CHECK(j["cost"] == 0.0);
  REQUIRE(j["correspondence"].size() == 60);
  for (std::size_t i = 0; i < 60; ++i) CHECK(j["correspondence"][i] == i);
  CHECK(j["a_samples"].size() == 60);
  CHECK(std::filesystem::file_size(svg) > 1000);

  const std::string missing = temp_path("gf_apps2d_no_such_shape.json");
  std::filesystem::remove(out);
  const CliRun bad = run_cli("match2d " + a + " " + missing + " --json " + out);
  CHECK(bad.code != 0);
  CHECK(bad.output.find("gf_apps2d_no_such_shape.json") != std::string::npos);
  CHECK(!std::filesystem::exists(out));
  const CliRun kind = run_cli("match2d " + a + " " + a + " --signature area");
  CHECK(kind.code != 0);
  CHECK(kind.output.find("--signature") != std::string::npos);
  const CliRun holes = run_cli("match2d hole branches");
  CHECK(holes.code != 0);
  CHECK(holes.output.find("simply connected") != std::string::npos);
}
