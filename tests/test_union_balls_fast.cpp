// The fast union-of-balls axis equals (1) the axis of main bad0ea7, before the fast path,
// on the corpus of union_axis_digest.h (hashes in tests/data/union_axis_digests.txt), and
// (2) the definition-level path (UnionOfBallsOptions::reference: no interval shortcut) on
// many seeded ball sets, random and degenerate; in both cases everything the builder
// returns, vertex for vertex (exact coordinates and R^2), face for face, in order.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "union_axis_digest.h"

using namespace grassfire;
using namespace grassfire::testing;

namespace {

std::string fast_text(const BallSet& b) { return union_axis_text(union_of_balls_axis(b)); }

std::string reference_text(const BallSet& b) {
  UnionOfBallsOptions o;
  o.reference = true;
  return union_axis_text(union_of_balls_axis(b, o));
}

}  // namespace

TEST_CASE("union-of-balls axis: identical to main's on the digest corpus", "[builders3]") {
  const std::string data = GF_PROJECT_DATA;
  const std::vector<BallSet> corpus = union_digest_corpus(data);
  std::ifstream in(std::string(GF_TEST_DATA) + "/union_axis_digests.txt");
  REQUIRE(in);
  std::string line;
  std::size_t checked = 0;
  while (std::getline(in, line)) {
    std::istringstream is(line);
    std::size_t index = 0;
    is >> index;
    const std::size_t hash_at = line.rfind(' ', line.rfind(' ') - 1) + 1;
    std::uint64_t hash = 0;
    std::size_t size = 0;
    std::istringstream hs(line.substr(hash_at));
    hs >> std::hex >> hash >> std::dec >> size;
    REQUIRE(index < corpus.size());
    const std::string text = fast_text(corpus[index]);
    INFO(corpus[index].source);
    CHECK(text.size() == size);
    CHECK(union_fnv1a(text) == hash);
    ++checked;
  }
  CHECK(checked == corpus.size());
}

TEST_CASE("union-of-balls axis: fast path equals the definition-level path", "[builders3]") {
  std::size_t compared = 0;
  auto same = [&](const BallSet& b) {
    INFO(b.source);
    CHECK(fast_text(b) == reference_text(b));
    ++compared;
  };
  for (unsigned seed = 101; seed <= 112; ++seed) same(random_ball_set(30 + 7 * seed % 50, seed));
  for (unsigned seed = 1; seed <= 6; ++seed) same(union_random_balls(40, seed, 3.0, 0.6, 0.8));
  for (unsigned seed = 7; seed <= 12; ++seed) same(union_coarse_balls(25, seed));
  same(union_grid_balls(3, 2));
  same(union_grid_balls(2, 1));
  same(union_grid_balls(3, mpq_class(1, 2)));
  same(union_cospherical_balls(1, 0));
  same(union_cospherical_balls(2, 3));
  CHECK(compared == 29);
}
