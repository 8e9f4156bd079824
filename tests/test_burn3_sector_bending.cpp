// Which fans bend a burning path (sector_geometry.h, 4.2.2): decided by certified
// arithmetic, never at a double margin. A closed fan whose angle falls short of 2 pi by far
// less than 1e-6 (the apex of a very flat pyramid) is flat enough for a double sum of atan2
// to call it 2 pi, yet it cannot bend a geodesic (Mitchell, Mount and Papadimitriou 1987).
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/exact/sector_geometry.h"
#include "burn3/exact/unfolding.h"
#include "test_complex3_support.h"

using namespace grassfire;

namespace {

// The four sides of a pyramid of height h over the square with corners (+-1, 0, 0),
// (0, +-1, 0): the apex' fan is closed, its angle 4 acos(h^2 / (1 + h^2)) = 2 pi - 4 h^2 + O(h^4).
RawComplex flat_pyramid(const mpq_class& h) {
  RawComplex raw;
  raw.source = "flat pyramid";
  raw.vertices = {ExactPoint3{0, 0, h}, ExactPoint3{1, 0, 0}, ExactPoint3{0, 1, 0}, ExactPoint3{-1, 0, 0},
                  ExactPoint3{0, -1, 0}};
  raw.radius_squared.assign(raw.vertices.size(), mpq_class(1));
  raw.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
  return raw;
}

bool apex_bends(const MedialComplex& mc, EngineMutant mutant, std::uint64_t* undecided = nullptr) {
  const Unfolding u(mc);
  const SectorGeometry g = sector_geometry(u, mutant);
  if (undecided) *undecided = g.undecided_angles;
  for (std::size_t k = 0; k < mc.sectors().size(); ++k)
    if (mc.sectors()[k].apex == 0) {
      REQUIRE(mc.sectors()[k].closed);
      return g.bends[k];
    }
  FAIL("the apex has no sector");
  return false;
}

}  // namespace

TEST_CASE("a closed fan 4e-8 short of 2 pi does not bend (a double margin of 1e-6 would call it bending)", "[exact3][bending]") {
  const MedialComplex mc = testing::built(flat_pyramid(mpq_class(1, 10000)));
  std::uint64_t undecided = 0;
  CHECK_FALSE(apex_bends(mc, EngineMutant::none, &undecided));
  CHECK(undecided == 0);
  // engine-double-bending: |Theta - 2 pi| = 4e-8 <= 1e-6, taken as bending.
  CHECK(apex_bends(mc, EngineMutant::double_bending));
}

TEST_CASE("pyramids from steep to nearly flat: the apex never bends, certified at every height", "[exact3][bending]") {
  for (long d : {2L, 10L, 1000L, 100000L, 10000000L}) {
    CAPTURE(d);
    const MedialComplex mc = testing::built(flat_pyramid(mpq_class(1, d)));
    std::uint64_t undecided = 0;
    CHECK_FALSE(apex_bends(mc, EngineMutant::none, &undecided));
    CHECK(undecided == 0);
  }
}
