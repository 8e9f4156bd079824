// The discrete burning baseline against closed forms and a brute-force reference.
#include <catch2/catch.hpp>

#include <cmath>

#include "burn3/burn3_reference.h"
#include "burn3/discrete/discrete_burning.h"
#include "complex3/synthetic_complexes.h"
#include "test_complex3_support.h"

using namespace grassfire;

using testing::built;

TEST_CASE("board and fin: error against the closed form shrinks with h", "[burn3]") {
  const MedialComplex mc = built(board_fin({10, 1}));
  auto inside = [](const Vec3d& p) { return p[0] <= 7 && p[1] <= 7 && p[2] <= 7 && p[0] >= -7; };
  double previous = 1e9;
  for (double h : {0.5, 0.25, 0.125}) {
    const DiscreteBurning d = burn_discrete(mc, {h});
    const ErrorSummary err = summarize_error(mc, d, board_fin_burning_time, inside);
    CAPTURE(h, err.max_error, err.mean_error, err.min_error, err.points);
    testing::require_compared(err, testing::graph_points_inside(mc, h, inside));
    CHECK(err.min_error >= -1e-9);     // an upper bound (Definition 9 paths)
    CHECK(err.max_error <= 0.5 * h);   // the stated bound on this case (discrete_burning.h)
    CHECK(err.max_error < previous);   // finer is better
    previous = err.max_error;
  }
}

TEST_CASE("book and Y: spine at the (k-1)-th arrival, quench inside the widest page", "[burn3]") {
  for (const BookOptions& o : {y_junction_options(2), BookOptions{4, {1, 2, 3, 5}, 0, 2}, BookOptions{2, {2, 3}, 0, 2}}) {
    const MedialComplex mc = built(book(o));
    const DiscreteBurning d = burn_discrete(mc, {0.125});
    // Every vertex lies on one page (spine: any page) at distance u from the spine.
    double worst = 0;
    for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) {
      const Vec3d& p = mc.vertex(v).approx;
      const double u = std::hypot(p[0], p[1]);
      int page = 0;
      if (u > 0) {
        double best = 1e9;
        for (int j = 0; j < o.pages; ++j) {
          const auto dir = rational_unit_direction(2 * M_PI * j / o.pages);
          const double off = std::hypot(p[0] - u * dir[0].get_d(), p[1] - u * dir[1].get_d());
          if (off < best) best = off, page = j;
        }
      }
      const double exact = book_burning_time(o, page, u, p[2]);
      worst = std::max(worst, std::abs(d.vertex_bt[v] - exact));
    }
    CAPTURE(o.pages);
    CHECK(worst <= 0.3 * 0.125);
  }
}

TEST_CASE("single planar sheet: discrete BT equals the brute-force min over border of d + f", "[burn3]") {
  for (std::uint32_t seed = 0; seed < 6; ++seed) {
    // A convex planar sheet: a fan with rim points on a circle, one rim edge never
    // igniting, linear f from random R at the rim (slope < 1).
    const MedialComplex mc = built(random_planar_fan(seed));
    for (double h : {0.25, 0.125}) {
      const DiscreteBurning d = burn_discrete(mc, {h});
      const auto everywhere = [](const Vec3d&) { return true; };
      const ErrorSummary err = summarize_error(
          mc, d, [&](const Vec3d& p) { return planar_convex_sheet_burning_time(mc, p); }, everywhere);
      CAPTURE(seed, h, err.max_error, err.min_error);
      testing::require_compared(err, testing::graph_points_inside(mc, h, everywhere));
      CHECK(err.min_error >= -1e-9);
      CHECK(err.max_error <= 0.3 * h);  // the stated bound on this case (discrete_burning.h)
    }
  }
}
