// curve_distance.cpp -- Hausdorff distance between curve graphs (see header).
#include "burn3/curve_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

#include "complex3/vec3.h"

namespace grassfire {
namespace {

double segment_distance(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = v3::sub(b, a);
  const double len2 = v3::dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(v3::dot(v3::sub(p, a), ab) / len2, 0.0, 1.0) : 0.0;
  return v3::dist(p, v3::lerp(a, b, t));
}

// B's segments (a node alone is a segment of length 0) in a uniform grid: each segment is
// listed in every cell its bounding box meets.
class SegmentGrid {
 public:
  explicit SegmentGrid(const MedialCurves& b) {
    for (const CurveEdge& e : b.edges) segments_.push_back({b.nodes[e.u].position, b.nodes[e.v].position});
    if (b.edges.empty())
      for (const CurveNode& n : b.nodes) segments_.push_back({n.position, n.position});
    double total = 0;
    lo_ = hi_ = segments_.front()[0];
    for (const auto& s : segments_) {
      total += v3::dist(s[0], s[1]);
      for (const Vec3d& p : s)
        for (int i = 0; i < 3; ++i) lo_[i] = std::min(lo_[i], p[i]), hi_[i] = std::max(hi_[i], p[i]);
    }
    cell_ = std::max({total / segments_.size(), v3::dist(lo_, hi_) / 200, 1e-12});
    for (std::uint32_t i = 0; i < segments_.size(); ++i) {
      std::array<long, 3> a = cell_of(segments_[i][0]), c = cell_of(segments_[i][1]);
      for (long x = std::min(a[0], c[0]); x <= std::max(a[0], c[0]); ++x)
        for (long y = std::min(a[1], c[1]); y <= std::max(a[1], c[1]); ++y)
          for (long z = std::min(a[2], c[2]); z <= std::max(a[2], c[2]); ++z) cells_[key(x, y, z)].push_back(i);
    }
  }

  // Distance from p to the nearest segment: rings of cells around p's cell until the
  // nearest found is closer than the next ring could be; past 16 rings, all segments.
  double nearest(const Vec3d& p) const {
    const std::array<long, 3> c = cell_of(p);
    double best = std::numeric_limits<double>::infinity();
    for (long r = 0; r <= 16; ++r) {
      if (best <= (r - 1) * cell_) return best;
      for (long x = c[0] - r; x <= c[0] + r; ++x)
        for (long y = c[1] - r; y <= c[1] + r; ++y)
          for (long z = c[2] - r; z <= c[2] + r; ++z) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != r) continue;
            const auto it = cells_.find(key(x, y, z));
            if (it == cells_.end()) continue;
            for (std::uint32_t i : it->second) best = std::min(best, segment_distance(p, segments_[i][0], segments_[i][1]));
          }
    }
    if (best <= 16 * cell_) return best;
    for (const auto& s : segments_) best = std::min(best, segment_distance(p, s[0], s[1]));
    return best;
  }

 private:
  std::array<long, 3> cell_of(const Vec3d& p) const {
    return {static_cast<long>(std::floor(p[0] / cell_)), static_cast<long>(std::floor(p[1] / cell_)),
            static_cast<long>(std::floor(p[2] / cell_))};
  }
  static std::int64_t key(long x, long y, long z) {
    return ((static_cast<std::int64_t>(x) & 0x1FFFFF) << 42) | ((static_cast<std::int64_t>(y) & 0x1FFFFF) << 21) |
           (static_cast<std::int64_t>(z) & 0x1FFFFF);
  }
  std::vector<std::array<Vec3d, 2>> segments_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
  Vec3d lo_{}, hi_{};
  double cell_ = 1;
};

}  // namespace

double directed_curve_distance(const MedialCurves& a, const MedialCurves& b, double step) {
  if (a.nodes.empty() || b.nodes.empty() || !(step > 0))
    throw std::invalid_argument("curve distance: both graphs need a node, and step > 0");
  const SegmentGrid grid(b);
  double worst = 0;
  for (const CurveNode& n : a.nodes) worst = std::max(worst, grid.nearest(n.position));
  for (const CurveEdge& e : a.edges) {
    const Vec3d p = a.nodes[e.u].position, q = a.nodes[e.v].position;
    const int n = static_cast<int>(std::ceil(e.length / step));
    for (int i = 1; i < n; ++i) worst = std::max(worst, grid.nearest(v3::lerp(p, q, static_cast<double>(i) / n)));
  }
  return worst;
}

double curve_hausdorff(const MedialCurves& a, const MedialCurves& b, double step) {
  return std::max(directed_curve_distance(a, b, step), directed_curve_distance(b, a, step));
}

}  // namespace grassfire
