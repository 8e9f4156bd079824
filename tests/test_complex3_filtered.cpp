// The filtered MedialComplex against the rational implementation it replaced: the digest of
// every derived structure (tests/medial_complex_digest.h) on the corpus, compared with the
// hashes that the all-rational code (commit 84237b0) computed, recorded in
// tests/data/medial_complex_digests.txt (refusals compared by their message); and the
// filtered predicates against the rational ones of exact_predicates3.h on seeded random
// and degenerate points.
#include <catch2/catch.hpp>

#include <fstream>
#include <random>
#include <sstream>

#include "geometry3/filtered_predicates3.h"
#include "medial_complex_digest.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

struct RecordedDigest {
  std::string name, hash;
  std::size_t size = 0;
};

std::vector<RecordedDigest> recorded_digests() {
  std::ifstream in(std::string(GF_TEST_DATA) + "/medial_complex_digests.txt");
  REQUIRE(in);
  std::vector<RecordedDigest> out;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::size_t index = 0;
    RecordedDigest d;
    row >> index >> d.name >> d.hash >> d.size;
    REQUIRE(index == out.size());
    out.push_back(d);
  }
  return out;
}

std::string hash_text(const std::string& text) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(fnv1a(text)));
  return buf;
}

}  // namespace

TEST_CASE("filtered MedialComplex digests equal those of the rational implementation", "[complex3][filtered]") {
  const auto corpus = digest_corpus(GF_PROJECT_DATA);
  const std::vector<RecordedDigest> recorded = recorded_digests();
  REQUIRE(corpus.size() == recorded.size());
  std::size_t refused = 0, exact_decisions = 0;
  for (std::size_t i = 0; i < corpus.size(); ++i) {
    INFO("corpus entry " << i << " " << corpus[i].first);
    REQUIRE(corpus[i].first == recorded[i].name);
    const std::string text = digest_text(corpus[i].second);
    if (text.rfind("refused", 0) == 0) ++refused;
    INFO(text.substr(0, 200));
    CHECK(text.size() == recorded[i].size);
    CHECK(hash_text(text) == recorded[i].hash);
    if (text.rfind("refused", 0) != 0) exact_decisions += MedialComplex(corpus[i].second).filter_counts().exact;
  }
  // The corpus reaches the refusals (overlaps, coincident vertices, intersections) and the
  // exact stage (ties the filter cannot decide), not only the filter's easy cases.
  CHECK(refused >= 10);
  CHECK(refused + 50 <= corpus.size());
  CHECK(exact_decisions > 100);
}

TEST_CASE("filtered predicates equal the rational ones on random and degenerate points", "[complex3][filtered]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> small(-2, 2), denominator(1, 3), big(-1000000, 1000000);
  std::vector<ExactPoint3> pts;
  for (int i = 0; i < 60; ++i) {
    if (i % 2) pts.push_back({mpq_class(small(rng), denominator(rng)), mpq_class(small(rng), denominator(rng)),
                              mpq_class(small(rng), denominator(rng))});
    else pts.push_back({mpq_class(big(rng), 3) / 7, mpq_class(1, 10) * small(rng), mpq_class(big(rng), 1 << 20)});
    for (mpq_class* c : {&pts.back().x, &pts.back().y, &pts.back().z}) c->canonicalize();
  }
  pts.push_back(pts[1] + pts[3]);  // sums and midpoints: collinear and coplanar quadruples
  pts.push_back(mpq_class(1, 2) * (pts[1] + pts[3]));
  const FilteredPoints fp(pts);
  const std::uint32_t n = static_cast<std::uint32_t>(pts.size());
  std::size_t compared = 0;
  for (std::uint32_t a = 0; a < n; a += 3)
    for (std::uint32_t b = 1; b < n; b += 5) {
      CHECK(fp.compare_lex(a, b) == compare_lex(pts[a], pts[b]));
      if (pts[a] == pts[b]) continue;
      const EdgeAngularOrder exact(pts[a], pts[b]);
      const FilteredEdgeOrder filtered(fp, a, b);
      for (std::uint32_t c = 0; c < n; c += 7) {
        CHECK(fp.collinear(a, b, c) == collinear(pts[a], pts[b], pts[c]));
        for (std::uint32_t d = 2; d < n; d += 11) {
          CHECK(fp.orientation(a, b, c, d) == orientation(pts[a], pts[b], pts[c], pts[d]));
          if (collinear(pts[a], pts[b], pts[c]) || collinear(pts[a], pts[b], pts[d])) continue;
          for (std::uint32_t w : {c, d, n - 1, n - 2}) {
            if (collinear(pts[a], pts[b], pts[w])) continue;
            CHECK(filtered.compare(c, d, w) ==
                  exact.compare(exact.direction(pts[c]), exact.direction(pts[d]), exact.direction(pts[w])));
            ++compared;
          }
        }
      }
    }
  CHECK(compared > 1000);
  CHECK(fp.counts().exact > 0);
  CHECK(fp.counts().filtered > fp.counts().exact);
}
