// Exact burning engine on graphs (segments: the link rule and the 2D rule) and on every
// complex the project builds or reads (docs/exact-engine.md; docs/exact-engine.md for the bound).
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/discrete/discrete_burning.h"
#include "burn3/exact/exact_burning.h"
#include "pipeline/medial_axis_input.h"
#include "complex3/synthetic_complexes.h"
#include "io/complex_ma.h"
#include "test_burn3_exact_support.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

struct Run {
  std::unique_ptr<MedialComplex> mc;
  std::unique_ptr<ExactBurning> eb;
};

Run burn(const RawComplex& raw) {
  Run r;
  r.mc = std::make_unique<MedialComplex>(raw);
  r.mc->validate();
  r.eb = std::make_unique<ExactBurning>(*r.mc);
  r.eb->add_border_ignition();
  r.eb->run();
  return r;
}

}  // namespace

TEST_CASE("a Y of segments burns by the 2D rule: the centre at its second arrival", "[exact3]") {
  // Leaves at distance 3 from the centre with R = 1, 2, 4: arrivals 4, 5, 7 at the centre,
  // which burns at 5 and sends fire up the third branch, where it meets the fire from the
  // leaf (burning at 4) at distance (3 + 4 - 5) / 2 = 1 from the centre, at time 6.
  ComplexBuilder b("Y graph");
  const std::uint32_t c = b.vertex({0, 0, 0}, 16);
  const std::uint32_t l1 = b.vertex({3, 0, 0}, 1), l2 = b.vertex({0, 3, 0}, 4), l3 = b.vertex({0, 0, 3}, 16);
  b.segment(c, l1), b.segment(c, l2), b.segment(c, l3);
  const Run r = burn(b.raw());
  const auto bt = [&](std::uint32_t v) { return r.eb->vertex_burn_time(v); };
  CHECK(encloses(bt(l1), 1.0));
  CHECK(encloses(bt(l2), 2.0));
  CHECK(encloses(bt(l3), 4.0));
  CHECK(encloses(bt(c), 5.0));
  CHECK(bt(c).hi - bt(c).lo < 1e-12);
  const std::uint32_t e3 = r.mc->find_edge(c, l3);
  const bool from_centre = r.mc->edge(e3).v[0] == c;
  const Interval quench = r.eb->segment_burn_time(e3, from_centre ? mpq_class(1, 3) : mpq_class(2, 3));
  CHECK(encloses(quench, 6.0));
  CHECK(r.eb->propagation().stats().vertex_burns == 4);
}

TEST_CASE("caffeine's axis (a graph with two cycles): equal to the discrete baseline, cycles never burn", "[exact3]") {
  const MedialAxisBuild a = build_medial_axis(std::string(GF_PROJECT_DATA) + "/balls/caffeine.cin", MedialInputKind::Auto);
  const Run r = burn(a.complex);
  // On a graph every move of the baseline is exact: the two agree to double rounding.
  const DiscreteBurning d = burn_discrete(*r.mc, {0.5});
  int finite = 0, infinite = 0;
  for (std::uint32_t v = 0; v < r.mc->vertex_count(); ++v) {
    const Interval e = r.eb->vertex_burn_time(v);
    CAPTURE(v, e.lo, e.hi, d.vertex_bt[v]);
    if (std::isinf(d.vertex_bt[v])) {
      CHECK(e.is_infinite());
      ++infinite;
      continue;
    }
    ++finite;
    CHECK(encloses(e, d.vertex_bt[v], 1e-9));
  }
  CHECK(finite > 0);
  CHECK(infinite > 0);  // the 2-core (the two rings) never burns
  CHECK(r.eb->certification().uncertified == 0);
}

TEST_CASE("every complex the project builds or reads burns by Definition 9, below the discrete baseline", "[exact3]") {
  std::vector<RawComplex> corpus;
  for (const std::string& name : synthetic_complex_names()) {
    if (name == "book:K") corpus.push_back(synthetic_complex("book:4"));
    else if (name == "box:A:B:C") corpus.push_back(synthetic_complex("box:4:3:1"));
    else corpus.push_back(synthetic_complex(name));
  }
  for (const char* f : {"/ma/box_4_3_1.ma", "/ma/box_5_3_2.ma"}) corpus.push_back(read_ma(std::string(GF_PROJECT_DATA) + f));
  for (const char* f : {"/meshes/cube.off", "/meshes/octahedron.off", "/meshes/tripod.off", "/balls/caffeine.cin"})
    corpus.push_back(build_medial_axis(std::string(GF_PROJECT_DATA) + f, MedialInputKind::Auto).complex);
  for (const RawComplex& raw : corpus) {
    const Run r = burn(raw);
    CAPTURE(raw.source, r.mc->triangle_count(), r.eb->propagation().stats().windows);
    // Without singular edges every decision is proved. On medial axes of meshes (huge
    // rational coordinates, singular edges down to 1e-17 long) crossings and orders along
    // singular edges that no stage settles are counted (tripod.off's axis: 212), never
    // tie-broken in silence; the bound guards that count against growth.
    if (r.mc->count(EdgeStratum::Singular) == 0) CHECK(r.eb->certification().uncertified == 0);
    CHECK(r.eb->certification().uncertified <= 250);
    // The discrete baseline over-estimates BT (its paths are real burning paths through the
    // junctions too): an upper bound, with or without singular edges.
    const DiscreteBurning d = burn_discrete(*r.mc, {0.25});
    for (std::uint32_t v = 0; v < r.mc->vertex_count(); ++v) CHECK(d.vertex_bt[v] >= r.eb->vertex_burn_time(v).lo - 1e-9);
  }
}
