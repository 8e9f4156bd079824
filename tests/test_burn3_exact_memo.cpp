// The certifier's memo of decisions (window_certify.h): a comparison asked again is
// answered from the memo, keyed by the identity of the fronts (front_id), of the point and
// of the precision cap. Checked against a fresh Certifier (empty memo) on the same store:
// every repeated answer equals the fresh decision, and equal front ids never compare
// unequal (they name one expression). Instances: the junction questions of tripod-s2.ma
// (the points of its singular edges where the realising record is decided) and the vertex
// comparisons of its windows.
#include <catch2/catch.hpp>

#include <random>

#include "burn3/exact/exact_burning.h"
#include "burn3/exact/window_propagation.h"
#include "io/complex_ma.h"
#include "test_complex3_support.h"

using namespace grassfire;
using testing::built;

TEST_CASE("the certifier's memo repeats what a fresh certifier decides, and equal front ids are one expression",
          "[exact3][memo]") {
  const MedialComplex mc = built(read_ma(std::string(GF_PROJECT_DATA) + "/ma/real/tripod-s2.ma"));
  ExactBurning eb(mc);
  eb.add_border_ignition();
  eb.run();
  const WindowStore& s = eb.propagation().store();
  Certifier& used = eb.certifier();
  Certifier fresh(eb.unfolding(), s, 512);
  CHECK(used.counts.memo > 0);  // the run itself repeated questions

  // Windows per triangle (dead ones too: the junction rule compares records of any age).
  std::vector<std::vector<std::uint32_t>> in(mc.triangle_count());
  for (std::uint32_t w = 0; w < s.windows.size(); ++w) in[s.windows[w].triangle].push_back(w);
  std::mt19937 rng(9);
  std::size_t asked = 0, repeated = 0, same_front = 0;
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Singular) continue;
    std::vector<std::uint32_t> ws;
    for (std::uint32_t t : mc.edge_triangles(e)) ws.insert(ws.end(), in[t].begin(), in[t].end());
    std::shuffle(ws.begin(), ws.end(), rng);
    if (ws.size() > 12) ws.resize(12);
    for (const double at : {0.25, 0.5}) {
      const ExactPoint3& a = mc.vertex(mc.edge(e).v[0]).exact;
      const ExactPoint3 p = a + mpq_class(at) * (mc.vertex(mc.edge(e).v[1]).exact - a);
      const Target x{kNoIndex, &p, used.point_key(e, at)}, plain{kNoIndex, &p};
      for (std::size_t i = 0; i < ws.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
          const std::uint32_t w1 = ws[i], w2 = ws[j];
          const int first = used.compare_times(w1, x, w2, x);
          const std::uint64_t before = used.counts.memo;
          const int again = used.compare_times(w2, x, w1, x);  // the other order: the negated answer
          const int reference = fresh.compare_times(w1, plain, w2, plain);
          CAPTURE(e, at, w1, w2, first, again, reference);
          CHECK(first == reference);
          CHECK(again == (reference == kUndecided ? kUndecided : -reference));
          repeated += used.counts.memo > before;
          ++asked;
          if (used.front_id(w1) == used.front_id(w2)) {
            ++same_front;
            CHECK((reference == 0 || reference == kUndecided));
          }
        }
    }
  }
  CAPTURE(asked, repeated, same_front);
  CHECK(asked > 1000);
  CHECK(repeated > 0);
  // Points without a key are never memoised.
  CHECK(fresh.counts.memo == 0);
}
