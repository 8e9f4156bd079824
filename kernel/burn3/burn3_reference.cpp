// burn3_reference.cpp -- definition-level references for the 3D burning time.
#include "burn3/burn3_reference.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace grassfire {

SheetBurningTime planar_convex_sheet_burning(const MedialComplex& mc, const Vec3d& x) {
  if (mc.sheets().size() != 1 || !mc.sheets()[0].planar)
    throw std::invalid_argument("planar_convex_sheet_burning_time: " + mc.source() + " is not one planar sheet");
  SheetBurningTime best;
  best.time = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    if (mc.edge(e).stratum != EdgeStratum::Border || mc.edge(e).rule == IgnitionRule::Never) continue;
    auto cost = [&](double s) {
      const Vec3d y = DiscreteBurning::point_on_edge(mc, e, s);
      return std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]) + mc.ignition_on_edge(e, s);
    };
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {  // convex: ternary search
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      (cost(m1) <= cost(m2) ? hi : lo) = (cost(m1) <= cost(m2) ? m2 : m1);
    }
    for (double s : {0.0, 1.0, 0.5 * (lo + hi)})
      if (cost(s) < best.time) best = {cost(s), DiscreteBurning::point_on_edge(mc, e, s), e};
  }
  return best;
}

double planar_convex_sheet_burning_time(const MedialComplex& mc, const Vec3d& x) {
  return planar_convex_sheet_burning(mc, x).time;
}

ErrorSummary summarize_error(const MedialComplex& mc, const DiscreteBurning& d,
                             const std::function<double(const Vec3d&)>& reference,
                             const std::function<bool(const Vec3d&)>& inside) {
  ErrorSummary s;
  s.min_error = std::numeric_limits<double>::infinity();
  double sum = 0.0;
  auto visit = [&](const Vec3d& p, double bt) {
    if (!inside(p)) return;
    ++s.considered;
    const double exact = reference(p);
    if (std::isinf(exact) && std::isinf(bt) && (exact > 0) == (bt > 0)) {
      ++s.both_infinite;
      return;
    }
    if (!std::isfinite(exact) || !std::isfinite(bt)) {
      ++s.one_sided_infinite;
      return;
    }
    const double diff = bt - exact;
    ++s.points;
    sum += std::abs(diff);
    s.min_error = std::min(s.min_error, diff);
    if (std::abs(diff) > s.max_error) {
      s.max_error = std::abs(diff);
      s.worst_point = p;
    }
  };
  for (std::uint32_t v = 0; v < mc.vertex_count(); ++v) visit(mc.vertex(v).approx, d.vertex_bt[v]);
  for (std::uint32_t e = 0; e < mc.edge_count(); ++e) {
    const std::uint32_t n = d.steiner_count(e);
    for (std::uint32_t i = 1; i <= n; ++i)
      visit(DiscreteBurning::point_on_edge(mc, e, static_cast<double>(i) / (n + 1)), d.bt_on_edge(mc, e, i));
  }
  if (s.points > 0) s.mean_error = sum / static_cast<double>(s.points);
  if (s.points == 0) s.min_error = 0.0;
  return s;
}

}  // namespace grassfire
