// shape_locator.cpp -- see shape_locator.h.
#include "geometry2/shape_locator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace grassfire {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
// Cells are widened by this fraction of their size when edges are registered, so that a
// query whose interval midpoint falls in a cell is certainly within the widened cell.
constexpr double kMargin = 1.0 / 1024.0;
}  // namespace

ShapeLocator::ShapeLocator(const Shape2& shape, std::size_t expected_queries) {
  double xmin = kInf, ymin = kInf, xmax = -kInf, ymax = -kInf;
  for (const Ring& ring : shape.rings) {
    const std::size_t n = ring.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2 a = ring.points[i], b = ring.points[(i + 1) % n];
      edges_.push_back({a, b});
      xmin = std::min(xmin, a.x);
      xmax = std::max(xmax, a.x);
      ymin = std::min(ymin, a.y);
      ymax = std::max(ymax, a.y);
    }
  }
  if (edges_.size() < 3) throw std::invalid_argument("shape locator: a shape needs at least 3 boundary edges");
  const double w = std::max(xmax - xmin, 1e-300), h = std::max(ymax - ymin, 1e-300);
  const double cells = std::min(4.0e6, std::max(static_cast<double>(edges_.size()), expected_queries / 4.0));
  const double side = std::sqrt(w * h / cells);
  nx_ = static_cast<int>(std::min(4096.0, std::max(1.0, std::ceil(w / side)))) + 2;  // one padding cell
  ny_ = static_cast<int>(std::min(4096.0, std::max(1.0, std::ceil(h / side)))) + 2;  // on each side
  dx_ = w / (nx_ - 2);
  dy_ = h / (ny_ - 2);
  x0_ = xmin - dx_;
  y0_ = ymin - dy_;
  register_edges();
  compute_reference_points();
  empty_status_.resize(reference_inside_.size());
  for (std::size_t c = 0; c < empty_status_.size(); ++c)
    empty_status_[c] = cell_start_[c] == cell_start_[c + 1] ? static_cast<std::uint8_t>(1 + reference_inside_[c]) : 0;
}

ShapeLocator::Cell ShapeLocator::cell_of(double x, double y) const {
  // Truncation instead of std::floor (a libm call without SSE4.1): the two differ only
  // below 0 (and beyond int range, where both conversions give INT_MIN), and the clamp
  // maps all of those to 0 either way, so the cell is the same.
  const int ix = static_cast<int>((x - x0_) / dx_);
  const int iy = static_cast<int>((y - y0_) / dy_);
  return {std::clamp(ix, 0, nx_ - 1), std::clamp(iy, 0, ny_ - 1)};
}

void ShapeLocator::register_edges() {
  // For each edge, the cells of every row band it passes through, widened by the margin.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (cell, edge)
  const double mx = dx_ * kMargin, my = dy_ * kMargin;
  for (std::uint32_t k = 0; k < edges_.size(); ++k) {
    const Edge& e = edges_[k];
    const double ylo = std::min(e.a.y, e.b.y) - my, yhi = std::max(e.a.y, e.b.y) + my;
    const int row0 = cell_of(0, ylo).iy, row1 = cell_of(0, yhi).iy;
    for (int iy = row0; iy <= row1; ++iy) {
      const double band_lo = std::max(ylo, y0_ + iy * dy_), band_hi = std::min(yhi, y0_ + (iy + 1) * dy_);
      double xa, xb;
      if (e.a.y == e.b.y) {
        xa = e.a.x;
        xb = e.b.x;
      } else {
        const double ta = std::clamp((band_lo - e.a.y) / (e.b.y - e.a.y), 0.0, 1.0);
        const double tb = std::clamp((band_hi - e.a.y) / (e.b.y - e.a.y), 0.0, 1.0);
        xa = e.a.x + ta * (e.b.x - e.a.x);
        xb = e.a.x + tb * (e.b.x - e.a.x);
      }
      const int c0 = cell_of(std::min(xa, xb) - mx, 0).ix, c1 = cell_of(std::max(xa, xb) + mx, 0).ix;
      for (int ix = c0; ix <= c1; ++ix) pairs.emplace_back(cell_index(ix, iy), k);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (const auto& p : pairs) ++cell_start_[p.first + 1];
  for (std::size_t i = 1; i < cell_start_.size(); ++i) cell_start_[i] += cell_start_[i - 1];
  cell_edges_.resize(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) cell_edges_[i] = pairs[i].second;  // pairs are sorted by cell
}

void ShapeLocator::compute_reference_points() {
  reference_.assign(static_cast<std::size_t>(nx_) * ny_, Point2{});
  reference_inside_.assign(reference_.size(), 0);
  std::vector<double> vertex_y;
  for (const Edge& e : edges_) vertex_y.push_back(e.a.y);
  std::sort(vertex_y.begin(), vertex_y.end());
  std::vector<std::uint32_t> stamp(edges_.size(), 0xffffffffu);
  for (int iy = 0; iy < ny_; ++iy) {
    // The row's line: the cell centre height, moved off every vertex height.
    double y = y0_ + (iy + 0.5) * dy_;
    while (std::binary_search(vertex_y.begin(), vertex_y.end(), y)) y = std::nextafter(y, kInf);
    std::vector<std::uint32_t> crossing;
    for (int ix = 0; ix < nx_; ++ix) {
      const std::uint32_t c = cell_index(ix, iy);
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t e = cell_edges_[k];
        if (stamp[e] == static_cast<std::uint32_t>(iy)) continue;
        stamp[e] = static_cast<std::uint32_t>(iy);
        if ((edges_[e].a.y > y) != (edges_[e].b.y > y)) crossing.push_back(e);
      }
    }
    std::vector<double> xs(nx_);
    for (int ix = 0; ix < nx_; ++ix) xs[ix] = x0_ + (ix + 0.5) * dx_;
    std::vector<std::uint8_t> toggle;
    for (bool settled = false; !settled;) {
      settled = true;
      toggle.assign(nx_ + 1, 0);
      for (std::uint32_t e : crossing) {
        const Point2 lo = edges_[e].a.y < edges_[e].b.y ? edges_[e].a : edges_[e].b;
        const Point2 hi = edges_[e].a.y < edges_[e].b.y ? edges_[e].b : edges_[e].a;
        const double xc = lo.x + (y - lo.y) * (hi.x - lo.x) / (hi.y - lo.y);
        const int k = cell_of(xc, y).ix;
        // Reference points right of an upward edge have negative orientation. Columns
        // beyond k + 1 are certainly right, those before k - 1 certainly left.
        int first_right = std::min(k + 2, nx_);
        for (int j = std::max(0, k - 1); j <= std::min(nx_ - 1, k + 1); ++j) {
          const int o = orientation(LazyPoint::input(lo), LazyPoint::input(hi), LazyPoint::input({xs[j], y}),
                                    &counters_);
          if (o == 0) {
            xs[j] = std::nextafter(xs[j], kInf);  // on the edge: move it and redo the row
            settled = false;
          } else if (o < 0) {
            first_right = std::min(first_right, j);
            break;
          }
        }
        toggle[first_right] ^= 1;
      }
    }
    std::uint8_t parity = 0;
    for (int ix = 0; ix < nx_; ++ix) {
      parity ^= toggle[ix];
      reference_[cell_index(ix, iy)] = {xs[ix], y};
      reference_inside_[cell_index(ix, iy)] = parity;
    }
  }
}

bool ShapeLocator::on_edge(const LazyPoint& p, const Edge& e) const {
  const LazyPoint a = LazyPoint::input(e.a), b = LazyPoint::input(e.b);
  if (orientation(a, b, p, &counters_) != 0) return false;
  // Collinear: on the closed segment iff within its bounding box (exactly).
  const ExactPoint2 q = p.exact();
  const auto within = [](const mpq_class& v, double s, double t) {
    return mpq_class(std::min(s, t)) <= v && v <= mpq_class(std::max(s, t));
  };
  return within(q.x, e.a.x, e.b.x) && within(q.y, e.a.y, e.b.y);
}

bool ShapeLocator::crosses(const LazyPoint& p, const LazyPoint& q, const Edge& e) const {
  const LazyPoint a = LazyPoint::input(e.a), b = LazyPoint::input(e.b);
  const bool left_a = orientation(p, q, a, &counters_) >= 0;
  const bool left_b = orientation(p, q, b, &counters_) >= 0;
  if (left_a == left_b) return false;
  return orientation(a, b, p, &counters_) * orientation(a, b, q, &counters_) < 0;
}

BoundedSide ShapeLocator::locate(const LazyPoint& p) const {
  const IntervalPoint2& box = p.approx();
  const Point2 lo{x0_ + dx_, y0_ + dy_}, hi{x0_ + (nx_ - 1) * dx_, y0_ + (ny_ - 1) * dy_};
  if (box.x.hi < lo.x || box.x.lo > hi.x || box.y.hi < lo.y || box.y.lo > hi.y) return BoundedSide::Outside;
  Point2 where = p.nearest();
  Cell cell = cell_of(where.x, where.y);
  // The widened cell must contain the whole enclosure; otherwise locate by exact value.
  const double mx = dx_ * kMargin, my = dy_ * kMargin;
  const double cx0 = x0_ + cell.ix * dx_ - mx, cy0 = y0_ + cell.iy * dy_ - my;
  if (box.x.lo < cx0 || box.x.hi > cx0 + dx_ + 2 * mx || box.y.lo < cy0 || box.y.hi > cy0 + dy_ + 2 * my) {
    const ExactPoint2 e = p.exact();
    cell = cell_of(e.x.get_d(), e.y.get_d());
  }
  const std::uint32_t c = cell_index(cell.ix, cell.iy);
  const LazyPoint ref = LazyPoint::input(reference_[c]);
  std::uint8_t parity = reference_inside_[c];
  for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    const Edge& e = edges_[cell_edges_[k]];
    if (on_edge(p, e)) return BoundedSide::Boundary;
    if (crosses(p, ref, e)) parity ^= 1;
  }
  return parity ? BoundedSide::Inside : BoundedSide::Outside;
}

std::optional<BoundedSide> ShapeLocator::locate_in_empty_cell(const IntervalPoint2& box) const {
  const Cell cell = cell_of(box.x.mid(), box.y.mid());
  const double mx = dx_ * kMargin, my = dy_ * kMargin;
  const double cx0 = x0_ + cell.ix * dx_ - mx, cy0 = y0_ + cell.iy * dy_ - my;
  if (box.x.lo < cx0 || box.x.hi > cx0 + dx_ + 2 * mx || box.y.lo < cy0 || box.y.hi > cy0 + dy_ + 2 * my)
    return std::nullopt;
  const std::uint8_t status = empty_status_[cell_index(cell.ix, cell.iy)];
  if (status == 0) return std::nullopt;
  return status == 2 ? BoundedSide::Inside : BoundedSide::Outside;
}

std::optional<bool> ShapeLocator::segment_meets_boundary_in_empty_cells(const IntervalPoint2& p,
                                                                        const IntervalPoint2& q) const {
  const double mx = dx_ * kMargin, my = dy_ * kMargin;
  const Interval xs = hull(p.x, q.x), ys = hull(p.y, q.y);
  const Cell c0 = cell_of(xs.lo - mx, ys.lo - my), c1 = cell_of(xs.hi + mx, ys.hi + my);
  // Cells are clamped to the grid: a hull reaching beyond it is not decided here.
  if (xs.lo - mx < x0_ || ys.lo - my < y0_ || xs.hi + mx >= x0_ + nx_ * dx_ || ys.hi + my >= y0_ + ny_ * dy_)
    return std::nullopt;
  for (int iy = c0.iy; iy <= c1.iy; ++iy)
    for (int ix = c0.ix; ix <= c1.ix; ++ix)
      if (empty_status_[cell_index(ix, iy)] == 0) return std::nullopt;
  return false;
}

bool ShapeLocator::segment_meets_edge(const LazyPoint& p, const LazyPoint& q, const Edge& e) const {
  const LazyPoint a = LazyPoint::input(e.a), b = LazyPoint::input(e.b);
  const int o1 = orientation(p, q, a, &counters_), o2 = orientation(p, q, b, &counters_);
  if (o1 * o2 > 0) return false;
  const int o3 = orientation(a, b, p, &counters_), o4 = orientation(a, b, q, &counters_);
  if (o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
  // All four collinear: the segments meet iff an endpoint of one lies on the other.
  if (on_edge(p, e) || on_edge(q, e)) return true;
  const ExactPoint2 ep = p.exact(), eq = q.exact();
  const auto between = [&](const Point2& v) {
    const mpq_class vx(v.x), vy(v.y);
    return std::min(ep.x, eq.x) <= vx && vx <= std::max(ep.x, eq.x) && std::min(ep.y, eq.y) <= vy &&
           vy <= std::max(ep.y, eq.y);
  };
  return between(e.a) || between(e.b);
}

bool ShapeLocator::segment_meets_boundary(const LazyPoint& p, const LazyPoint& q) const {
  const double mx = dx_ * kMargin, my = dy_ * kMargin;
  const Interval xs = hull(p.approx().x, q.approx().x), ys = hull(p.approx().y, q.approx().y);
  const Cell c0 = cell_of(xs.lo - mx, ys.lo - my), c1 = cell_of(xs.hi + mx, ys.hi + my);
  // An edge registered in several of these cells is tested more than once: harmless.
  for (int iy = c0.iy; iy <= c1.iy; ++iy)
    for (int ix = c0.ix; ix <= c1.ix; ++ix) {
      const std::uint32_t c = cell_index(ix, iy);
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k)
        if (segment_meets_edge(p, q, edges_[cell_edges_[k]])) return true;
    }
  return false;
}

}  // namespace grassfire
