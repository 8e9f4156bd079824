// feature_size.cpp -- see feature_size.h.
#include "burn2/feature_size.h"

#include <algorithm>
#include <cmath>

#include "number/ball.h"

namespace grassfire {

namespace {

Interval hull_of(const Interval& a, const Interval& b) { return {std::fmin(a.lo, b.lo), std::fmax(a.hi, b.hi)}; }

// Is x surely inside (+1), surely outside (-1) the convex hull of the directions, or too
// close to call (0)? Inside iff no angular gap between consecutive directions reaches pi.
int surrounds(const std::vector<IntervalPoint2>& dirs) {
  if (dirs.size() < 3) return -1;
  const double pi = std::acos(-1.0);
  std::vector<double> angle;
  double err = 0;  // bound on the error of each angle: enclosure radius over length, plus atan2's
  for (const IntervalPoint2& d : dirs) {
    angle.push_back(std::atan2(d.y.mid(), d.x.mid()));
    const double len = std::hypot(d.x.mid(), d.y.mid());
    err = std::max(err, len > 0 ? 2 * std::fmax(d.x.radius(), d.y.radius()) / len + 1e-15 : pi);
  }
  std::sort(angle.begin(), angle.end());
  double gap = angle.front() + 2 * pi - angle.back();
  for (std::size_t i = 1; i < angle.size(); ++i) gap = std::max(gap, angle[i] - angle[i - 1]);
  const double margin = 4 * err + 1e-12;  // within it, both cases are taken
  if (gap < pi - margin) return 1;
  if (gap > pi + margin) return -1;
  return 0;
}

}  // namespace

LocalFeatureMeasures local_feature_measures(const MedialGraph& g, const ClosestPoints& cp) {
  LocalFeatureMeasures out;
  for (std::uint32_t v = 0; v < g.node_count(); ++v) {
    const std::vector<BoundaryPoint>& pts = cp.node[v];
    const Interval radius = g.node(v).radius;
    const Point2 x = g.node(v).position;
    const Interval ex(-g.node(v).position_error, g.node(v).position_error);
    Interval chord(0.0);
    std::vector<IntervalPoint2> dirs;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      dirs.push_back({pts[i].position.x - Interval(x.x) + ex, pts[i].position.y - Interval(x.y) + ex});
      for (std::size_t j = i + 1; j < pts.size(); ++j) {
        const Interval c = sqrt(square(pts[i].position.x - pts[j].position.x) +
                                square(pts[i].position.y - pts[j].position.y));
        chord = Interval(std::fmax(chord.lo, c.lo), std::fmax(chord.hi, c.hi));
      }
    }
    if (radius.hi <= 0.0 || pts.size() < 2) {
      out.separation_angle.push_back(Interval(0.0));
      out.feature_size.push_back(Interval(0.0));
      continue;
    }
    // theta = 2 asin(c / 2R), asin increasing: enclose it from the ends of the ratio's
    // enclosure clamped to [0, 1] (c <= 2R holds exactly; the enclosure may pass 1).
    const Interval ratio = chord / (Interval(2.0) * radius);
    auto angle = [](double x, bool upper) {
      BallPrecision guard(64);
      Ball theta;
      arb_asin(theta.get(), Ball(std::fmin(1.0, std::fmax(0.0, x))).get(), 64);
      const Interval t = (Ball(2.0) * theta).to_interval();
      return upper ? t.hi : t.lo;
    };
    out.separation_angle.push_back({angle(ratio.lo, false), angle(ratio.hi, true)});
    const Interval half_chord = half(chord);
    const int inside = surrounds(dirs);
    out.feature_size.push_back(inside > 0 ? radius : inside < 0 ? half_chord : hull_of(radius, half_chord));
  }
  return out;
}

}  // namespace grassfire
