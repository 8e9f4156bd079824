// The discrete burning baseline against closed forms and a brute-force reference.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "burn3/burn3_reference.h"
#include "burn3/discrete_burning.h"
#include "complex3/complex_builder.h"
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
    CHECK(err.points > 100);
    CHECK(err.min_error >= -1e-9);     // an upper bound (Definition 9 paths)
    CHECK(err.max_error <= 0.5 * h);   // the stated bound on this case
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
  std::mt19937 rng(7);
  for (int instance = 0; instance < 6; ++instance) {
    // A convex planar sheet: a fan around the origin with rim points on a circle, one rim
    // edge never igniting, linear f from random R at the rim (slope < 1).
    ComplexBuilder b("planar sheet " + std::to_string(instance));
    const std::uint32_t centre = b.vertex({0, 0, 0}, 4);
    const int k = 5 + instance;
    std::vector<std::uint32_t> rim;
    std::uniform_int_distribution<int> radius(6, 12), rr(0, 3);
    const mpq_class rho = radius(rng);
    for (int j = 0; j < k; ++j) {
      const auto d = rational_unit_direction(2 * M_PI * j / k);
      const mpq_class r = rr(rng);
      rim.push_back(b.vertex({rho * d[0], rho * d[1], 0}, r * r));
    }
    for (int j = 0; j < k; ++j) b.triangle(centre, rim[j], rim[(j + 1) % k]);
    b.rule(rim[0], rim[1], IgnitionRule::Never);
    const MedialComplex mc = built(b.raw());
    for (double h : {0.25, 0.125}) {
      const DiscreteBurning d = burn_discrete(mc, {h});
      const ErrorSummary err = summarize_error(
          mc, d, [&](const Vec3d& p) { return planar_convex_sheet_burning_time(mc, p); },
          [](const Vec3d&) { return true; });
      CAPTURE(instance, h, err.max_error, err.min_error);
      CHECK(err.min_error >= -1e-9);
      CHECK(err.max_error <= 0.3 * h);
    }
  }
}
