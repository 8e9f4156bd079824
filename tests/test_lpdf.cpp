// The largest-plate distance (4.1, Definition 7) by resolutions of the singular curves:
// against the closed form on the board and fin, equal to BT on books and on manifolds,
// refused where it is not tractable.
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/discrete/discrete_burning.h"
#include "curves3/lpdf.h"
#include "complex3/synthetic_complexes.h"
#include "complex3/synthetic_tubes.h"
#include "test_complex3_support.h"

using namespace grassfire;
using testing::built;

TEST_CASE("LPDF of the board and fin: the three zones of Fig. 4.3, converging as h^2", "[lpdf]") {
  const MedialComplex mc = built(board_fin({10, 1}));
  double previous = 1e9;
  for (double h : {0.25, 0.125}) {
    const LpdfResult r = largest_plate_distance(mc, {h});
    CHECK(r.singular_curves == 1);
    CHECK(r.resolutions == 3);
    double worst = 0;
    int zones[4] = {0, 0, 0, 0};
    for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
      const Vec3d& p = mc.vertex(v).approx;
      if (p[0] < -6 || p[0] > 7 || p[1] > 7 || p[2] > 6) continue;  // away from the truncation
      const double e = r.vertex_lpdf[v] - board_fin_lpdf(p);
      CHECK(e >= -1e-9);  // graph distances over-estimate
      worst = std::max(worst, e);
      ++zones[board_fin_lpdf_zone(p)];
    }
    CAPTURE(h, worst);
    CHECK(zones[1] > 10);
    CHECK(zones[2] >= 3);
    CHECK(zones[3] > 50);
    CHECK(worst <= 0.5 * h * h);
    CHECK(worst < previous);
    previous = worst;
  }
}

TEST_CASE("LPDF equals BT on books (derived) and on a manifold (no singular curve)", "[lpdf]") {
  for (const BookOptions& o : {y_junction_options(2), BookOptions{4, {1, 2, 3, 2}, 0, 2}}) {
    const MedialComplex mc = built(book(o));
    const double h = 0.125;
    const LpdfResult r = largest_plate_distance(mc, {h});
    CHECK(r.resolutions == 3);
    const DiscreteBurning d = burn_discrete(mc, {h});
    double worst = 0;
    for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) worst = std::max(worst, std::abs(r.vertex_lpdf[v] - d.vertex_bt[v]));
    CAPTURE(o.pages, worst);
    CHECK(worst <= 1e-9);
  }
  const MedialComplex tube_mc = built(tube({8, 4, 2, 6}));
  const LpdfResult r = largest_plate_distance(tube_mc, {0.25});
  CHECK(r.singular_curves == 0);
  CHECK(r.resolutions == 1);
  const DiscreteBurning d = burn_discrete(tube_mc, {0.25});
  for (std::uint32_t v = 0; v < tube_mc.vertex_count(); ++v) CHECK(r.vertex_lpdf[v] == Approx(d.vertex_bt[v]).margin(1e-12));
}

TEST_CASE("LPDF refuses where the resolutions are too many", "[lpdf]") {
  const MedialComplex box = built(box_medial_axis(4, 3, 1, 1));
  CHECK_THROWS_WITH(largest_plate_distance(box, {0.5, 1000}), Catch::Contains("531441 resolutions of its 12 singular curves"));
  const MedialComplex closed = built(tetrahedron_with_flap());
  const LpdfResult r = largest_plate_distance(closed, {0.2});
  CHECK(r.resolutions == 3);
  // The closed tetrahedron glued to itself has no boundary: plates of any size.
  std::size_t infinite = 0;
  for (double x : r.vertex_lpdf) infinite += std::isinf(x) ? 1 : 0;
  CHECK(infinite >= 3);
}
