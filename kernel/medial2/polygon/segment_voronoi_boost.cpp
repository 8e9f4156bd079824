// segment_voronoi_boost.cpp -- the interior segment Voronoi topology by Boost.Polygon
// (see segment_voronoi.h). Boost.Polygon is used in this file only (its wide coordinate
// traits in boost_wide_traits.h).
#include <boost/polygon/point_data.hpp>
#include <boost/polygon/segment_data.hpp>
#include <boost/polygon/voronoi.hpp>

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "medial2/polygon/boost_voronoi_events.h"
#include "medial2/polygon/boost_wide_traits.h"
#include "medial2/polygon/segment_voronoi.h"
#include "number/interval.h"

namespace grassfire {

namespace bp = boost::polygon;

namespace {

using Diagram = bp::voronoi_diagram<double, NoMergeTraits<double>>;

std::int32_t to_int32(double x) {
  if (!(std::fabs(x) <= 2147483647.0) || x != std::floor(x))
    throw std::invalid_argument("boost_segment_voronoi: frame coordinate " + std::to_string(x) +
                                " is not an int32 integer");
  return static_cast<std::int32_t>(x);
}

// The frame's integers translated by the midpoint of their bounding box (exact in 128-bit
// integers; translation does not change the diagram), or nothing when one exceeds 62 bits.
std::optional<std::vector<std::int64_t>> wide_integers(const PolygonSites& sites) {
  constexpr double kLimit = 0x1p126;
  __int128 lo[2], hi[2];
  std::vector<__int128> v;
  v.reserve(2 * sites.vertex.size());
  for (const Point2& p : sites.vertex)
    for (double x : {p.x, p.y}) {
      if (!(std::fabs(x) < kLimit) || x != std::floor(x)) return std::nullopt;
      v.push_back(static_cast<__int128>(x));
    }
  for (int axis = 0; axis < 2; ++axis) lo[axis] = hi[axis] = v.empty() ? 0 : v[axis];
  for (std::size_t i = 0; i < v.size(); ++i) {
    lo[i % 2] = std::min(lo[i % 2], v[i]);
    hi[i % 2] = std::max(hi[i % 2], v[i]);
  }
  std::vector<std::int64_t> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    const __int128 t = v[i] - (lo[i % 2] + hi[i % 2]) / 2;
    if (t > boost_wide::kMaxMagnitude || t < -boost_wide::kMaxMagnitude) return std::nullopt;
    out[i] = static_cast<std::int64_t>(t);
  }
  return out;
}

}  // namespace

VoronoiTopology boost_segment_voronoi(const PolygonSites& sites, BoostReader reader) {
  std::vector<bp::segment_data<std::int32_t>> segments;
  segments.reserve(sites.vertex_count());
  for (std::uint32_t i = 0; i < sites.vertex_count(); ++i) {
    const Point2 a = sites.vertex[i], b = sites.vertex[sites.next[i]];
    segments.emplace_back(bp::point_data<std::int32_t>(to_int32(a.x), to_int32(a.y)),
                          bp::point_data<std::int32_t>(to_int32(b.x), to_int32(b.y)));
  }
  return boost_interior_topology<Diagram>(
      sites,
      [&](auto* output) {
        bp::voronoi_builder<std::int32_t> builder;
        bp::insert(segments.begin(), segments.end(), &builder);
        builder.construct(output);
      },
      reader == BoostReader::Diagram);
}

bool fits_wide_boost(const PolygonSites& sites) { return wide_integers(sites).has_value(); }

VoronoiTopology boost_segment_voronoi_wide(const PolygonSites& sites, BoostReader reader) {
  const std::optional<std::vector<std::int64_t>> v = wide_integers(sites);
  if (!v) throw std::invalid_argument("boost_segment_voronoi_wide: a frame coordinate is not an integer within 2^62 of the frame's centre");
  return boost_interior_topology<Diagram>(
      sites,
      [&](auto* output) {
        bp::voronoi_builder<std::int64_t, boost_wide::CtypeTraits> builder;
        for (std::uint32_t i = 0; i < sites.vertex_count(); ++i) {
          const std::uint32_t j = sites.next[i];
          builder.insert_segment((*v)[2 * i], (*v)[2 * i + 1], (*v)[2 * j], (*v)[2 * j + 1]);
        }
        builder.construct(output);
      },
      reader == BoostReader::Diagram);
}

}  // namespace grassfire
