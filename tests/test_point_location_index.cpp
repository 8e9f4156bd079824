// ComplexLocator's spatial index against its reference (locate_by_scan, every cell): the
// same cell, point and exact squared distance on seeded queries near and on several
// complexes, including points equidistant from several cells (ties), points on vertices
// and edges, and far points; plus the interval closest-point enclosures against the exact
// closest point, and the integer closest point against the rational one.
#include <catch2/catch.hpp>

#include <random>

#include "geometry3/closest_point3.h"
#include "complex3/point_location.h"
#include "medial_complex_digest.h"
#include "test_complex3_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

bool same(const ComplexPoint& a, const ComplexPoint& b) {
  return a.kind == b.kind && a.id == b.id && a.point == b.point && a.snap_squared == b.snap_squared;
}

std::vector<ExactPoint3> queries_for(const MedialComplex& mc, std::uint32_t seed, std::size_t count) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(mc.vertex_count() - 1));
  std::uniform_int_distribution<int> offset(-8, 8), kind(0, 4);
  std::vector<ExactPoint3> out;
  for (std::size_t i = 0; i < count; ++i) {
    const ExactPoint3& a = mc.vertex(pick(rng)).exact;
    const ExactPoint3& b = mc.vertex(pick(rng)).exact;
    const mpq_class step(offset(rng), 16);
    switch (kind(rng)) {
      case 0: out.push_back(a); break;                                    // on a vertex
      case 1: out.push_back(mpq_class(1, 2) * (a + b)); break;            // midpoints: ties
      case 2: out.push_back(a + ExactPoint3{step, mpq_class(offset(rng), 16), 0}); break;
      case 3: out.push_back(mpq_class(1, 3) * (a + b) + ExactPoint3{0, 0, step}); break;
      default: out.push_back(mpq_class(offset(rng) * 4) * (a - b)); break;  // far away
    }
  }
  return out;
}

}  // namespace

TEST_CASE("ComplexLocator with its index equals the scan of every cell", "[complex3][location]") {
  std::vector<std::pair<std::string, RawComplex>> corpus;
  for (const char* name : {"board-fin", "book:5", "y-junction", "octahedron", "tetrahedron-flap", "box:4:3:1"})
    corpus.emplace_back(name, synthetic_complex(name));
  corpus.emplace_back("ma", read_ma(std::string(GF_PROJECT_DATA) + "/ma/box_4_3_1.ma"));
  corpus.emplace_back("pipe", read_ma(std::string(GF_PROJECT_DATA) + "/ma/real/pipe.ma"));
  corpus.emplace_back("refined-cube",
                      mesh_as_complex(refined_mesh(read_triangle_mesh(std::string(GF_PROJECT_DATA) + "/meshes/cube.off"), 800)));
  corpus.emplace_back("height-field", random_height_field(3, 6));
  std::size_t compared = 0, on_complex = 0;
  for (std::size_t k = 0; k < corpus.size(); ++k) {
    INFO(corpus[k].first);
    const MedialComplex mc = built(corpus[k].second);
    const ComplexLocator locator(mc);
    for (const ExactPoint3& q : queries_for(mc, static_cast<std::uint32_t>(k + 1), 150)) {
      const ComplexPoint fast = locator.locate(q), slow = locator.locate_by_scan(q);
      CHECK(same(fast, slow));
      on_complex += sgn(fast.snap_squared) == 0;
      ++compared;
    }
  }
  CHECK(compared == 150 * corpus.size());
  CHECK(on_complex > 200);
}

TEST_CASE("interval closest-point enclosures contain the exact squared distance, integer and rational closest points agree", "[complex3][location]") {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> c(-20, 20), d(1, 7);
  auto point = [&] { return ExactPoint3{mpq_class(c(rng), d(rng)), mpq_class(c(rng), d(rng)), mpq_class(c(rng), d(rng))}; };
  auto enclose = [](const ExactPoint3& p) {
    IntervalPoint3 out;
    int i = 0;
    for (const mpq_class* x : {&p.x, &p.y, &p.z}) out[i++] = enclose_coordinate(*x).value;
    return out;
  };
  std::size_t decided = 0, tries = 0;
  for (; tries < 3000; ++tries) {
    ExactPoint3 a = point(), b = point(), t = point(), p = point();
    for (ExactPoint3* x : {&a, &b, &t, &p})
      for (mpq_class* y : {&x->x, &x->y, &x->z}) y->canonicalize();
    if (collinear(a, b, t)) continue;
    if (tries % 5 == 0) p = mpq_class(1, 2) * (a + b);  // on an edge: region boundaries
    const auto w = closest_weights(a, b, t, p);
    CHECK(w == closest_weights_reference(a, b, t, p));
    const mpq_class exact = squared_distance(w[0] * a + w[1] * b + w[2] * t, p);
    if (const auto box = closest_squared_distance(enclose(a), enclose(b), enclose(t), enclose(p))) {
      ++decided;
      CHECK(mpq_class(box->lo) <= exact);
      CHECK(exact <= mpq_class(box->hi));
    }
    const mpq_class s = dot(p - a, b - a) / dot(b - a, b - a);
    const mpq_class clamped = sgn(s) < 0 ? mpq_class(0) : s > 1 ? mpq_class(1) : s;
    const mpq_class segment = squared_distance(a + clamped * (b - a), p);
    if (const auto box = closest_squared_distance(enclose(a), enclose(b), enclose(p))) {
      CHECK(mpq_class(box->lo) <= segment);
      CHECK(segment <= mpq_class(box->hi));
    }
  }
  CHECK(decided > tries / 2);
}
