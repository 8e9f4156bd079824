// prune3d: the 3D axis pruned by ET and ST thresholds, on complexes with known answers
// (a box's axis with a fin, a tube, an annulus), the kept area against a closed-form area of
// the threshold half-planes, Betti numbers kept on every synthetic complex and the small
// meshes, and the program's outputs and errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "curves3/axis_pruning3.h"
#include "complex3/synthetic_complexes.h"
#include "complex3/synthetic_tubes.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "pipeline/prune3d.h"
#include "support.h"

using grassfire::testing::run_cli;
using grassfire::testing::temp_path;

namespace grassfire {
namespace {

Prune3dRun prune(const std::string& input, const std::string& method, std::optional<mpq_class> et,
                 std::optional<mpq_class> st = std::nullopt, double spacing = 0.25) {
  Prune3dSetup s = default_prune3d_setup();
  s.field.input = input;
  s.field.method = method;
  s.field.spacing = spacing;
  s.erosion = std::move(et);
  s.tubularity = std::move(st);
  return prune3d(s);
}

double triangle_area(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return std::sqrt(x * x + y * y + z * z) / 2;
}

// The area of {f >= 0} in a triangle of area `area` on which f is linear with corner values f.
double positive_area(double area, std::array<double, 3> f) {
  int positive = 0;
  for (double x : f) positive += x >= 0 ? 1 : 0;
  if (positive == 3) return area;
  if (positive == 0) return 0;
  const bool flip = positive == 2;  // then the negative corner's corner triangle is cut off
  if (flip)
    for (double& x : f) x = -x;
  int i = 0;
  while (!(f[i] > 0 || (!flip && f[i] >= 0))) ++i;
  const double fi = f[i], fj = f[(i + 1) % 3], fk = f[(i + 2) % 3];
  const double corner = area * fi * fi / ((fi - fj) * (fi - fk));
  return flip ? area - corner : corner;
}

// A box's exact axis (a = 8, b = 6, c = 4, each piece a 4 x 4 grid) with a fin on its middle
// rectangle: the vertical rectangle |x| <= 2, y = 0, 0 <= z <= 1, R = 4, whose top ignites
// (f = R) and whose sides never do.
RawComplex box_with_fin() {
  RawComplex raw = box_medial_axis(8, 6, 4, 4);
  auto find = [&](long x) {
    for (std::uint32_t v = 0; v < raw.vertices.size(); ++v)
      if (raw.vertices[v].x == x && raw.vertices[v].y == 0 && raw.vertices[v].z == 0) return v;
    FAIL("no base vertex at x = " << x);
    return 0u;
  };
  std::uint32_t base[3] = {find(-2), find(0), find(2)}, top[3];
  for (int i = 0; i < 3; ++i) {
    top[i] = static_cast<std::uint32_t>(raw.vertices.size());
    raw.vertices.push_back({mpq_class(2 * i - 2), 0, 1});
    raw.radius_squared.push_back(16);
  }
  for (int i = 0; i < 2; ++i) {
    raw.triangles.push_back({base[i], base[i + 1], top[i + 1]});
    raw.triangles.push_back({base[i], top[i + 1], top[i]});
  }
  raw.border_rules.push_back({{base[0], top[0]}, IgnitionRule::Never, {}});
  raw.border_rules.push_back({{base[2], top[2]}, IgnitionRule::Never, {}});
  raw.source = "box-with-fin";
  return raw;
}

std::string write_temp_complex(const RawComplex& raw, const std::string& name) {
  const std::string path = temp_path(name);
  write_complex_json(raw, path);
  return path;
}

struct Areas {
  double fin = 0, rectangle = 0, total = 0;
};
Areas kept_areas(const MedialComplex& mc) {
  Areas a;
  for (const ComplexTriangle& t : mc.triangles()) {
    const Vec3d &p = mc.vertex(t.v[0]).approx, &q = mc.vertex(t.v[1]).approx, &r = mc.vertex(t.v[2]).approx;
    const double area = triangle_area(p, q, r);
    a.total += area;
    if (p[1] == 0 && q[1] == 0 && r[1] == 0 && std::max({p[2], q[2], r[2]}) > 0) a.fin += area;
    if (p[2] == 0 && q[2] == 0 && r[2] == 0) a.rectangle += area;
  }
  return a;
}

}  // namespace

TEST_CASE("prune3d: a box's axis with a fin loses the fin above its ET and keeps its sheet", "[prune3d]") {
  const std::string path = write_temp_complex(box_with_fin(), "box_with_fin.json");
  for (const std::string method : {"discrete", "exact"}) {
    INFO(method);
    // The fin burns from its top at f = 4: ET = 1 - z <= 1. The rectangle: ET >= 4 (sqrt2 - 1).
    const Prune3dRun above = prune(path, method, mpq_class(6, 5));
    const Areas a = kept_areas(*above.pruned_complex);
    CHECK(a.fin == 0);
    CHECK(a.rectangle == ::Approx(32).epsilon(1e-12));
    CHECK(above.pruned.betti_pruned.b0 == 1);
    CHECK(above.pruned.betti_pruned.b1 == 0);
    CHECK(above.pruned.stats.kept_failing_triangles == 0);
    // Below the fin's largest ET, its strip z <= 1 - T stays (area 4 (1 - T) = 2 at T = 1/2,
    // within the discrete baseline's error).
    const Prune3dRun below = prune(path, method, mpq_class(1, 2));
    const Areas b = kept_areas(*below.pruned_complex);
    CHECK(b.fin == ::Approx(2).margin(method == "exact" ? 1e-9 : 0.25));
    CHECK(b.rectangle == ::Approx(32).epsilon(1e-12));
  }
  std::remove(path.c_str());
}

TEST_CASE("prune3d: a tube's axis keeps its band, then its curve", "[prune3d]") {
  // BT = distance to the nearer rim, R = 0: ET = min(z, 8 - z), largest 4 on the ring z = 4.
  const Prune3dRun band = prune("tube", "exact", mpq_class(7, 2));
  for (const ComplexVertex& v : band.pruned_complex->vertices()) {
    CHECK(v.approx[2] >= 3.5 - 1e-9);
    CHECK(v.approx[2] <= 4.5 + 1e-9);
  }
  CHECK(band.pruned.stats.kept_failing_triangles == 0);
  CHECK(kept_areas(*band.pruned_complex).total > 0);
  const Prune3dRun curve = prune("tube", "exact", mpq_class(5));
  CHECK(curve.pruned_complex->triangle_count() == 0);
  CHECK(curve.pruned.betti_pruned == BettiNumbers{1, 1, 0});
  for (const ComplexVertex& v : curve.pruned_complex->vertices()) {
    CHECK(v.approx[2] >= 3 - 1e-9);
    CHECK(v.approx[2] <= 5 + 1e-9);
  }
}

TEST_CASE("prune3d: the kept area equals the closed-form area of the threshold half-planes", "[prune3d]") {
  for (const std::string input : {"tube", "annulus"}) {
    for (const mpq_class& t : {mpq_class(1, 3), mpq_class(1), mpq_class(3, 2)}) {
      INFO(input << " T = " << t.get_d());
      const Prune3dRun run = prune(input, "exact", t);
      const MedialComplex& mc = *run.field.complex;
      double expected = 0;
      for (std::uint32_t i = 0; i < mc.triangle_count(); ++i) {
        const ComplexTriangle& tr = mc.triangle(i);
        std::array<double, 3> f{};
        for (int k = 0; k < 3; ++k)
          f[k] = run.field.field->sample_in_triangle(i, mc.vertex(tr.v[k]).approx).bt - mc.vertex(tr.v[k]).radius -
                 t.get_d();
        expected += positive_area(
            triangle_area(mc.vertex(tr.v[0]).approx, mc.vertex(tr.v[1]).approx, mc.vertex(tr.v[2]).approx), f);
      }
      CHECK(run.pruned.stats.kept_failing_triangles == 0);
      CHECK(kept_areas(*run.pruned_complex).total == ::Approx(expected).epsilon(1e-9));
    }
  }
}

TEST_CASE("prune3d keeps the Betti numbers on every synthetic complex and the small meshes", "[prune3d]") {
  const std::string data = GF_TEST_DATA, project = GF_PROJECT_DATA;
  const std::vector<std::string> inputs = {"board-fin", "book:3", "y-junction", "tetrahedron", "octahedron",
                                           "double-cone", "tetrahedron-flap", "box:6:4:2", "tube", "annulus",
                                           "torus", data + "/3d/three_balls.cin", data + "/3d/two_triangles_segment.ma",
                                           data + "/3d/hinge.json", project + "/meshes/cube.off",
                                           project + "/meshes/tripod.off"};
  for (const std::string& input : inputs)
    for (const mpq_class& t : {mpq_class(1, 10), mpq_class(1, 2), mpq_class(2)})
      for (const bool relative : {true, false}) {  // absolute too: R = 0 on the synthetic complexes
        INFO(input << " T = " << t.get_d() << (relative ? " x max R" : ""));
        Prune3dSetup s = default_prune3d_setup();
        s.field.input = input;
        s.field.method = "discrete";
        s.erosion = t;
        s.relative = relative;
        if (t == 2) s.tubularity = mpq_class(1, 2);
        const Prune3dRun run = prune3d(s);  // throws when b0, b1, b2 of axis, K and result differ
        CHECK(run.pruned.betti_pruned == run.pruned.betti_axis);
        CHECK(run.report["pruned"]["betti"] == run.report["axis"]["betti"]);
      }
}

TEST_CASE("prune3d: above the largest ET everything fails and the collapse keeps a cycle", "[prune3d]") {
  // Removing every failing simplex (a plain threshold) would remove the whole tube; the
  // collapse keeps a cycle of failing edges.
  const Prune3dRun run = prune("tube", "exact", mpq_class(5));
  CHECK(run.pruned.stats.failing_triangles == run.pruned.stats.refined_triangles);
  CHECK(run.pruned.stats.kept_failing_edges > 0);  // the cycle the collapse could not remove
}

TEST_CASE("grassfire prune3d writes JSON, complex, .ma and PLY, and nothing on bad input", "[prune3d][cli_prune3d]") {
  const std::string json = temp_path("tube_pruned.json"), cx = temp_path("tube_pruned_complex.json"),
                    ma = temp_path("tube_pruned.ma"), ply = temp_path("tube_pruned.ply");
  auto r = run_cli("prune3d tube --et 0.5 --relative --spacing 0.5 --json " + json + " --complex " + cx + " --ma " + ma +
                   " --ply " + ply);
  INFO(r.output);
  REQUIRE(r.code == 0);
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["format"] == "grassfire-pruned3d");
  CHECK(j["method"] == "exact");
  CHECK(j["pruned"]["betti"] == j["axis"]["betti"]);
  CHECK(j["vertex_values"]["x"].size() == j["pruned"]["vertices"].get<std::size_t>());
  const MedialComplex from_json(read_complex_json(cx)), from_ma(read_ma(ma));
  CHECK(from_json.triangle_count() == j["pruned"]["triangles"].get<std::size_t>());
  CHECK(from_ma.triangle_count() == from_json.triangle_count());
  std::ifstream p(ply);
  std::string first;
  std::getline(p, first);
  CHECK(first == "ply");
  for (const std::string& f : {json, cx, ma, ply}) std::remove(f.c_str());
  for (const std::string& bad : {"tube --json " + json, "tube --et -1 --json " + json, "tube --st 2 --json " + json,
                                 "tube --et x --json " + json, "no-such.off --et 1 --json " + json,
                                 "tube --st 0.5 --relative --json " + json, "tube --et 1 --method fast --json " + json}) {
    r = run_cli("prune3d " + bad);
    INFO(bad << ": " << r.output);
    CHECK(r.code == 1);
    CHECK(r.output.find("grassfire prune3d: ") != std::string::npos);
    CHECK(!std::ifstream(json).good());
  }
  CHECK(run_cli("prune3d --help").code == 0);
}

TEST_CASE("prune3d: .ma files in the Q-MAT convention round-trip through medial3d, prune3d, burn3d, curves3d",
          "[prune3d][cli_prune3d]") {
  const std::string axis = temp_path("three_balls_axis.ma"), pruned = temp_path("three_balls_pruned.ma"),
                    again = temp_path("three_balls_again.json");
  auto r = run_cli("medial3d " + std::string(GF_TEST_DATA) + "/3d/three_balls.cin --ma " + axis);
  INFO(r.output);
  REQUIRE(r.code == 0);
  r = run_cli("prune3d " + axis + " --et 0.2 --relative --ma " + pruned + " --json " + again);
  REQUIRE(r.code == 0);
  std::ifstream in(again);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["pruned"]["betti"] == j["axis"]["betti"]);
  // The written file reads back as the same complex: v x y z r, e i j, f i j k lines.
  const RawComplex back = read_ma(pruned);
  CHECK(back.triangles.size() == j["pruned"]["triangles"].get<std::size_t>());
  CHECK(back.vertices.size() == j["pruned"]["vertices"].get<std::size_t>());
  std::ifstream text(pruned);
  std::string header, first;
  std::getline(text, header);
  std::getline(text, first);
  CHECK(first.rfind("v ", 0) == 0);
  CHECK(run_cli("burn3d " + pruned + " --quiet").code == 0);
  CHECK(run_cli("curves3d " + pruned + " --quiet").code == 0);
  for (const std::string& f : {axis, pruned, again}) std::remove(f.c_str());
}

}  // namespace grassfire
