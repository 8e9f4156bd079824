// edge_grid.cpp -- see edge_grid.h.
#include "shapes/edge_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grassfire {

namespace {

// The power of two at or above twice the mean edge extent, at or above 2^-30 times the
// extent of the bounding box (at most 2^31 columns and rows, which the cell keys need), and
// at or above 2^-52 times the largest coordinate (|x / s| <= 2^52: every cell index and
// every cell side i * s is an exact double).
double choose_cell_size(const std::vector<Ring>& rings) {
  double largest = 0.0, mean_extent = 0.0;
  double min_x = std::numeric_limits<double>::max(), max_x = -min_x, min_y = min_x, max_y = -min_x;
  std::size_t edges = 0;
  for (const Ring& r : rings) edges += r.points.size();
  for (const Ring& r : rings) {
    const std::size_t n = r.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& a = r.points[i];
      const Point2& b = r.points[(i + 1) % n];
      largest = std::max({largest, std::fabs(a.x), std::fabs(a.y)});
      min_x = std::min(min_x, a.x);
      max_x = std::max(max_x, a.x);
      min_y = std::min(min_y, a.y);
      max_y = std::max(max_y, a.y);
      // Dividing before summing keeps the mean finite for coordinates near the double range.
      mean_extent += std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y)) / static_cast<double>(edges);
    }
  }
  const double box = std::max(max_x - min_x, max_y - min_y);
  double target = std::max({2.0 * mean_extent, std::ldexp(box, -30), std::ldexp(largest, -52)});
  if (!(target <= std::numeric_limits<double>::max())) target = largest;  // an extent overflowed
  if (target == 0.0) return 1.0;
  int exponent = 0;
  std::frexp(target, &exponent);  // target = f * 2^exponent, f in [0.5, 1)
  return std::ldexp(1.0, exponent);
}

}  // namespace

EdgeGrid::EdgeGrid(const std::vector<Ring>& rings, OrientationStats* stats) {
  for (std::uint32_t r = 0; r < rings.size(); ++r) {
    ring_start_.push_back(static_cast<std::uint32_t>(edges_.size()));
    const std::vector<Point2>& p = rings[r].points;
    for (std::size_t i = 0; i < p.size(); ++i) {
      edges_.push_back({p[i], p[(i + 1) % p.size()]});
      ring_of_edge_.push_back(r);
    }
  }
  cell_size_ = choose_cell_size(rings);
  if (edges_.empty()) return;
  min_column_ = min_row_ = std::numeric_limits<std::int64_t>::max();
  max_column_ = max_row_ = std::numeric_limits<std::int64_t>::min();
  for (const Segment& e : edges_) {
    min_column_ = std::min(min_column_, cell_of(std::min(e.a.x, e.b.x)));
    max_column_ = std::max(max_column_, cell_of(std::max(e.a.x, e.b.x)));
    min_row_ = std::min(min_row_, cell_of(std::min(e.a.y, e.b.y)));
    max_row_ = std::max(max_row_, cell_of(std::max(e.a.y, e.b.y)));
  }
  box_registered_.assign(edges_.size(), false);
  entries_.reserve(2 * edges_.size());
  for (std::uint32_t g = 0; g < edges_.size(); ++g) {
    const Segment& e = edges_[g];
    const std::int64_t columns = cell_of(std::max(e.a.x, e.b.x)) - cell_of(std::min(e.a.x, e.b.x));
    const std::int64_t rows = cell_of(std::max(e.a.y, e.b.y)) - cell_of(std::min(e.a.y, e.b.y));
    if (columns <= 1 || rows <= 1) {
      register_box(g);
    } else {
      register_by_columns(g, stats);
    }
  }
  std::sort(entries_.begin(), entries_.end(),
            [](const Entry& l, const Entry& r) { return l.key != r.key ? l.key < r.key : l.edge < r.edge; });
}

EdgeGrid::EdgeId EdgeGrid::edge(std::uint32_t g) const {
  const std::uint32_t r = ring_of_edge_[g];
  return {r, g - ring_start_[r]};
}

std::int64_t EdgeGrid::cell_of(double x) const {
  const double q = x / cell_size_;
  // An underflowed quotient is 0 (or tiny) while its floor is -1 for negative x.
  if (q == 0.0) return x < 0.0 ? -1 : 0;
  return static_cast<std::int64_t>(std::floor(q));
}

std::uint64_t EdgeGrid::key(std::int64_t column, std::int64_t row) const {
  return static_cast<std::uint64_t>(row - min_row_) << 32 | static_cast<std::uint64_t>(column - min_column_);
}

void EdgeGrid::register_box(std::uint32_t g) {
  const Segment& e = edges_[g];
  box_registered_[g] = true;
  const std::int64_t c0 = cell_of(std::min(e.a.x, e.b.x)), c1 = cell_of(std::max(e.a.x, e.b.x));
  const std::int64_t r0 = cell_of(std::min(e.a.y, e.b.y)), r1 = cell_of(std::max(e.a.y, e.b.y));
  for (std::int64_t r = r0; r <= r1; ++r)
    for (std::int64_t c = c0; c <= c1; ++c) entries_.push_back({key(c, r), g});
}

// The row of the point of edge e (with e.a.x < e.b.x) above abscissa x, within [lo, hi],
// which must contain it. A double estimate is corrected by exact comparisons of the height
// y(x) with the cell sides: c > y(x) exactly when (x, c) lies left of the edge.
std::int64_t EdgeGrid::row_at(const Segment& e, double x, std::int64_t lo, std::int64_t hi,
                              OrientationStats* stats) const {
  if (x == e.a.x) return cell_of(e.a.y);
  if (x == e.b.x) return cell_of(e.b.y);
  const double estimate = e.a.y + (x - e.a.x) * ((e.b.y - e.a.y) / (e.b.x - e.a.x));
  std::int64_t row = std::clamp(cell_of(estimate), lo, hi);
  while (row > lo && orientation(e.a, e.b, {x, static_cast<double>(row) * cell_size_}, stats) > 0) --row;
  while (row < hi && orientation(e.a, e.b, {x, static_cast<double>(row + 1) * cell_size_}, stats) <= 0) ++row;
  return row;
}

void EdgeGrid::register_by_columns(std::uint32_t g, OrientationStats* stats) {
  Segment e = edges_[g];
  if (e.b.x < e.a.x) std::swap(e.a, e.b);
  const std::int64_t c0 = cell_of(e.a.x), c1 = cell_of(e.b.x);
  const std::int64_t lo = cell_of(std::min(e.a.y, e.b.y)), hi = cell_of(std::max(e.a.y, e.b.y));
  for (std::int64_t c = c0; c <= c1; ++c) {
    // The points of e in column c have abscissae in [left, right]; y is monotone there.
    const double left = c == c0 ? e.a.x : static_cast<double>(c) * cell_size_;
    const double right = c == c1 ? e.b.x : static_cast<double>(c + 1) * cell_size_;
    const std::int64_t r_left = row_at(e, left, lo, hi, stats), r_right = row_at(e, right, lo, hi, stats);
    for (std::int64_t r = std::min(r_left, r_right); r <= std::max(r_left, r_right); ++r)
      entries_.push_back({key(c, r), g});
  }
}

// A pair of box-registered edges is reported only in the cell holding the lower-left
// corner of the intersection of their boxes, which both boxes contain.
bool EdgeGrid::counted_here(std::uint32_t g1, std::uint32_t g2, std::uint64_t cell_key) const {
  if (!box_registered_[g1] || !box_registered_[g2]) return true;
  const Segment& e = edges_[g1];
  const Segment& f = edges_[g2];
  const double x = std::max(std::min(e.a.x, e.b.x), std::min(f.a.x, f.b.x));
  const double y = std::max(std::min(e.a.y, e.b.y), std::min(f.a.y, f.b.y));
  return key(cell_of(x), cell_of(y)) == cell_key;
}

void EdgeGrid::for_each_candidate_pair(const std::function<void(std::uint32_t, std::uint32_t)>& visit) const {
  auto boxes_overlap = [this](std::uint32_t g1, std::uint32_t g2) {
    const Segment& e = edges_[g1];
    const Segment& f = edges_[g2];
    return std::max(e.a.x, e.b.x) >= std::min(f.a.x, f.b.x) && std::max(f.a.x, f.b.x) >= std::min(e.a.x, e.b.x) &&
           std::max(e.a.y, e.b.y) >= std::min(f.a.y, f.b.y) && std::max(f.a.y, f.b.y) >= std::min(e.a.y, e.b.y);
  };
  for (std::size_t begin = 0; begin < entries_.size();) {
    std::size_t end = begin + 1;
    while (end < entries_.size() && entries_[end].key == entries_[begin].key) ++end;
    for (std::size_t i = begin; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j) {
        const std::uint32_t g1 = entries_[i].edge, g2 = entries_[j].edge;
        if (boxes_overlap(g1, g2) && counted_here(g1, g2, entries_[begin].key)) visit(g1, g2);
      }
    begin = end;
  }
}

void EdgeGrid::add_ray_windings(const Point2& q, std::uint32_t skip_ring, std::vector<long>& winding,
                                OrientationStats* stats) const {
  const std::int64_t row = cell_of(q.y);
  const std::int64_t column = std::max(cell_of(q.x), min_column_);
  if (edges_.empty() || row < min_row_ || row > max_row_ || column > max_column_) return;
  // Every crossing point (x, q.y), x > q.x, lies in this row at a column >= q's column.
  auto first = std::lower_bound(entries_.begin(), entries_.end(), key(column, row),
                                [](const Entry& e, std::uint64_t k) { return e.key < k; });
  auto last = std::upper_bound(entries_.begin(), entries_.end(), key(max_column_, row),
                               [](std::uint64_t k, const Entry& e) { return k < e.key; });
  std::vector<std::uint32_t> crossing;
  for (auto it = first; it != last; ++it)
    if (ring_of_edge_[it->edge] != skip_ring) crossing.push_back(it->edge);
  std::sort(crossing.begin(), crossing.end());
  crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
  for (std::uint32_t g : crossing) winding[ring_of_edge_[g]] += winding_step(q, edges_[g].a, edges_[g].b, stats);
}

}  // namespace grassfire
