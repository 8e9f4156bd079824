#include "apps2d/axis_correspondence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace grassfire {

namespace {

double dist(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Nearest point of segment ab to q as the parameter t in [0, 1].
double segment_parameter(const Point2& a, const Point2& b, const Point2& q) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  if (len2 == 0) return 0;
  return std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / len2, 0.0, 1.0);
}

}  // namespace

AxisLocator::AxisLocator(const MedialGraph& g, double step) : g_(g), step_(step) {
  if (!(step > 0)) throw std::invalid_argument("AxisLocator: the step must be positive");
  for (std::uint32_t e = 0; e < g.edge_count(); ++e) {
    const MedialEdge& me = g.edge(e);
    const double len = me.length.mid();
    const Point2 pu = g.node(me.u).position, pv = g.node(me.v).position;
    if (me.kind == EdgeKind::Segment || len <= step) {
      pieces_.push_back({pu, pv, e, 0.0, len});
      continue;
    }
    const auto k = static_cast<std::uint32_t>(std::ceil(len / step));
    Point2 prev = pu;
    for (std::uint32_t i = 1; i <= k; ++i) {
      const double s0 = len * (i - 1) / k, s1 = len * i / k;
      const Point2 next = i == k ? pv : g.geometry().point_along(g, e, me.u, s1);
      pieces_.push_back({prev, next, e, s0, s1});
      prev = next;
    }
  }
  build_grid();
}

void AxisLocator::build_grid() {
  if (pieces_.empty()) return;
  double x1 = pieces_[0].a.x, y1 = pieces_[0].a.y;
  x0_ = x1, y0_ = y1;
  for (const Piece& p : pieces_)
    for (const Point2& q : {p.a, p.b}) x0_ = std::min(x0_, q.x), y0_ = std::min(y0_, q.y), x1 = std::max(x1, q.x), y1 = std::max(y1, q.y);
  const double extent = std::max({x1 - x0_, y1 - y0_, 1e-300});
  // About one piece per cell on average, at most 2048 cells per side.
  const double side = std::clamp(std::sqrt(static_cast<double>(pieces_.size())), 1.0, 2048.0);
  cell_ = extent / side;
  nx_ = std::max(1L, static_cast<long>(std::ceil((x1 - x0_) / cell_)) + 1);
  ny_ = std::max(1L, static_cast<long>(std::ceil((y1 - y0_) / cell_)) + 1);
  auto cell_range = [&](const Piece& p, long& ax, long& ay, long& bx, long& by) {
    ax = std::clamp(static_cast<long>((std::min(p.a.x, p.b.x) - x0_) / cell_), 0L, nx_ - 1);
    bx = std::clamp(static_cast<long>((std::max(p.a.x, p.b.x) - x0_) / cell_), 0L, nx_ - 1);
    ay = std::clamp(static_cast<long>((std::min(p.a.y, p.b.y) - y0_) / cell_), 0L, ny_ - 1);
    by = std::clamp(static_cast<long>((std::max(p.a.y, p.b.y) - y0_) / cell_), 0L, ny_ - 1);
  };
  std::vector<std::uint32_t> count(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
  for (const Piece& p : pieces_) {
    long ax, ay, bx, by;
    cell_range(p, ax, ay, bx, by);
    for (long ix = ax; ix <= bx; ++ix)
      for (long iy = ay; iy <= by; ++iy) ++count[static_cast<std::size_t>(iy * nx_ + ix) + 1];
  }
  for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
  cell_start_ = count;
  cell_items_.assign(count.back(), 0);
  for (std::uint32_t i = 0; i < pieces_.size(); ++i) {
    long ax, ay, bx, by;
    cell_range(pieces_[i], ax, ay, bx, by);
    for (long ix = ax; ix <= bx; ++ix)
      for (long iy = ay; iy <= by; ++iy) cell_items_[count[static_cast<std::size_t>(iy * nx_ + ix)]++] = i;
  }
}

void AxisLocator::scan_cell(long ix, long iy, const Point2& q, AxisPoint& best) const {
  if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) return;
  const auto c = static_cast<std::size_t>(iy * nx_ + ix);
  for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    const Piece& p = pieces_[cell_items_[k]];
    const double t = segment_parameter(p.a, p.b, q);
    const Point2 at{p.a.x + t * (p.b.x - p.a.x), p.a.y + t * (p.b.y - p.a.y)};
    const double d = dist(q, at);
    if (d < best.distance) best = {p.edge, p.sa + t * (p.sb - p.sa), at, d};
  }
}

bool AxisLocator::clip_to_disk(const Piece& p, const Point2& q, double r, double* t0, double* t1) {
  // |a + t (b - a) - q|^2 <= r^2: a quadratic in t, clipped to [0, 1].
  const double dx = p.b.x - p.a.x, dy = p.b.y - p.a.y, ex = p.a.x - q.x, ey = p.a.y - q.y;
  const double A = dx * dx + dy * dy, B = 2 * (dx * ex + dy * ey), C = ex * ex + ey * ey - r * r;
  if (A == 0) {
    *t0 = 0, *t1 = 1;
    return C <= 0;
  }
  const double disc = B * B - 4 * A * C;
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  *t0 = std::max(0.0, (-B - root) / (2 * A));
  *t1 = std::min(1.0, (-B + root) / (2 * A));
  return *t0 <= *t1;
}

AxisPoint AxisLocator::nearest(const Point2& q) const {
  AxisPoint best;
  if (pieces_.empty()) return best;
  const long cx = std::clamp(static_cast<long>(std::floor((q.x - x0_) / cell_)), 0L, nx_ - 1);
  const long cy = std::clamp(static_cast<long>(std::floor((q.y - y0_) / cell_)), 0L, ny_ - 1);
  const long rings = std::max(nx_, ny_);
  // A piece not registered in rings 0 .. r-1 around (cx, cy) lies in cells of ring >= r,
  // at least (r - 1) * cell_ away from q (also when q lies outside the grid: its cell is
  // the clamped one, and clamping only brings q closer).
  for (long r = 0; r <= rings; ++r) {
    if (r > 0 && best.distance <= (r - 1) * cell_) break;
    if (r == 0) {
      scan_cell(cx, cy, q, best);
      continue;
    }
    for (long i = -r; i <= r; ++i) {
      scan_cell(cx + i, cy - r, q, best);
      scan_cell(cx + i, cy + r, q, best);
    }
    for (long i = -r + 1; i <= r - 1; ++i) {
      scan_cell(cx - r, cy + i, q, best);
      scan_cell(cx + r, cy + i, q, best);
    }
  }
  return best;
}

std::vector<Point2> AxisLocator::dense_points() const {
  std::vector<Point2> out;
  for (const Piece& p : pieces_) {
    const double len = dist(p.a, p.b);
    const auto k = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / step_)));
    for (std::size_t i = 0; i < k; ++i)
      out.push_back({p.a.x + (p.b.x - p.a.x) * i / k, p.a.y + (p.b.y - p.a.y) * i / k});
    out.push_back(p.b);
  }
  return out;
}

double edf_at(const GrassfireResult& burning, const AxisPoint& p) {
  const MedialGraph& g = burning.times.graph();
  return burning.edf_along(p.edge, g.edge(p.edge).u, p.s).mid();
}

bool ema_position(const MedialGraph& g, const GrassfireResult& burning, Point2* out) {
  if (burning.ema.empty()) return false;
  const std::vector<std::uint32_t> comp = g.component_of_nodes();
  std::vector<std::size_t> size(burning.ema.size() + 1, 0);
  for (std::uint32_t c : comp)
    if (c < size.size()) ++size[c];
  const ExtendedMedialAxis* largest = &burning.ema.front();
  for (const ExtendedMedialAxis& e : burning.ema)
    if (e.component < size.size() && size[e.component] > size[largest->component]) largest = &e;
  if (largest->kind != ExtendedMedialAxis::Kind::Point) return false;
  *out = position_of(g, largest->point);
  return true;
}

namespace {

// The range of the EDF of B over [s0, s1] on an edge: min(Tu + s, Tv + w - s) over the
// ends that sent fire into the edge is concave, so its range is spanned by the values at
// s0, s1 and, when inside, the kink (the quench point).
void edf_range(const GrassfireResult& burning, std::uint32_t edge, double s0, double s1, double* lo, double* hi) {
  const MedialGraph& g = burning.times.graph();
  const std::uint32_t u = g.edge(edge).u;
  const double f0 = burning.edf_along(edge, u, s0).mid(), f1 = burning.edf_along(edge, u, s1).mid();
  *lo = std::min(f0, f1), *hi = std::max(f0, f1);
  const EdgeFire& fire = burning.fire[edge];
  if (fire.from_u == kNoTime || fire.from_v == kNoTime) return;
  const double w = g.edge(edge).length.mid();
  const double kink = 0.5 * (w + burning.times.approx(fire.from_v).mid() - burning.times.approx(fire.from_u).mid());
  if (kink > s0 && kink < s1) *hi = std::max(*hi, burning.edf_along(edge, u, kink).mid());
}

// min |v - EDF_B(y)| over the points y of B within r of q.
double nearest_value_error(const AxisLocator& on_b, const GrassfireResult& burning_b, const Point2& q, double r,
                           double v) {
  double best = std::numeric_limits<double>::infinity();
  on_b.for_each_within(q, r, [&](std::uint32_t edge, double s0, double s1) {
    double lo, hi;
    edf_range(burning_b, edge, s0, s1, &lo, &hi);
    best = std::min(best, std::max({0.0, lo - v, v - hi}));
  });
  return best;
}

double directed_hausdorff(const std::vector<Point2>& from, const AxisLocator& to) {
  double h = 0;
  for (const Point2& p : from) h = std::max(h, to.nearest(p).distance);
  return h;
}

}  // namespace

AxisComparison compare_axes(const MedialGraph& a, const GrassfireResult& burning_a, const MedialGraph& b,
                            const GrassfireResult& burning_b, double diameter, double step, double match_radius) {
  if (!(diameter > 0)) throw std::invalid_argument("compare_axes: the diameter must be positive");
  const AxisLocator on_b(b, step), on_a(a, step);
  AxisComparison c;
  double sum = 0;
  std::vector<double> errors;
  for (std::uint32_t v = 0; v < a.node_count(); ++v) {
    const AxisPoint y = on_b.nearest(a.node(v).position);
    c.max_node_offset = std::max(c.max_node_offset, y.distance / diameter);
    const double ea = burning_a.edf(v).mid(), eb = edf_at(burning_b, y);
    if (std::isinf(ea) || std::isinf(eb)) {
      ++c.infinite;
      continue;
    }
    const double err = std::abs(ea - eb) / diameter;
    c.max_edf_error = std::max(c.max_edf_error, err);
    // Widened by 1e-12 of the diameter so that y(x) itself is always within the radius.
    const double near =
        nearest_value_error(on_b, burning_b, a.node(v).position, y.distance + match_radius + 1e-12 * diameter, ea);
    c.max_edf_error_near = std::max(c.max_edf_error_near, std::min(near, std::abs(ea - eb)) / diameter);
    errors.push_back(err);
    sum += err;
    ++c.nodes;
  }
  if (c.nodes > 0) {
    c.mean_edf_error = sum / static_cast<double>(c.nodes);
    std::sort(errors.begin(), errors.end());
    auto rank = [&](double q) { return errors[static_cast<std::size_t>(std::ceil(q * double(errors.size()))) - 1]; };
    c.p95_edf_error = rank(0.95);
    c.p99_edf_error = rank(0.99);
  }
  Point2 pa, pb;
  if (ema_position(a, burning_a, &pa) && ema_position(b, burning_b, &pb)) c.ema_distance = dist(pa, pb) / diameter;
  c.hausdorff = std::max(directed_hausdorff(on_a.dense_points(), on_b), directed_hausdorff(on_b.dense_points(), on_a)) /
                diameter;
  return c;
}

double shape_diameter(const Shape2& shape) {
  if (shape.rings.empty()) return 0;
  std::vector<Point2> p = shape.rings.front().points;
  std::sort(p.begin(), p.end(), [](const Point2& u, const Point2& v) { return u.x < v.x || (u.x == v.x && u.y < v.y); });
  auto cross = [](const Point2& o, const Point2& u, const Point2& v) {
    return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
  };
  std::vector<Point2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // Andrew's monotone chain, lower then upper
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k);
  double d = 0;
  for (std::size_t i = 0; i < hull.size(); ++i)
    for (std::size_t j = i + 1; j < hull.size(); ++j) d = std::max(d, dist(hull[i], hull[j]));
  return d;
}

}  // namespace grassfire
