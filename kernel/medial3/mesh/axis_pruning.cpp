// axis_pruning.cpp -- see axis_pruning.h.
#include "medial3/mesh/axis_pruning.h"

#include <algorithm>
#include <stdexcept>

namespace grassfire {

namespace {

// Compressed rows: row r is item[start[r] .. start[r + 1]).
struct Rows {
  std::vector<std::uint32_t> start, item;
  template <class Pairs>
  void build(std::size_t rows, const Pairs& pairs) {  // pairs: (row, item)
    start.assign(rows + 1, 0);
    for (const auto& [r, x] : pairs) ++start[r + 1];
    for (std::size_t r = 0; r < rows; ++r) start[r + 1] += start[r];
    item.resize(pairs.size());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& [r, x] : pairs) item[fill[r]++] = x;
  }
};

// The cells and their incidences, with live counts.
class Collapser {
 public:
  Collapser(const PolygonalComplex& c, const std::function<bool(std::uint32_t)>& keep_polygon,
            const std::function<bool(const EdgeOrigin&)>& keep_edge)
      : c_(c), keep_polygon_(keep_polygon), keep_edge_(keep_edge) {
    build_edges();
    polygon_alive_.assign(c.polygons.size(), true);
    vertex_alive_.assign(c.vertex_count, true);
    polygon_verdict_.assign(c.polygons.size(), -1);
    edge_verdict_.assign(edge_count(), -1);
  }

  PrunedComplex run() {
    for (std::uint32_t p = 0; p < c_.polygons.size(); ++p) queue_.push_back(p);
    for (std::uint32_t e = 0; e < edge_count(); ++e) queue_.push_back(kEdge | e);
    const std::size_t bound = 4 * (c_.polygons.size() + edge_count()) + 16;
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      if (head > bound) throw std::logic_error("axis_pruning: the collapse did not terminate");
      const std::uint32_t item = queue_[head];
      if (item & kEdge) collapse_edge(item & ~kEdge);
      else collapse_polygon(item);
    }
    return result();
  }

 private:
  static constexpr std::uint32_t kEdge = 1u << 31;

  std::size_t edge_count() const { return edge_a_.size(); }

  // Edges are the distinct vertex pairs of the polygon sides (slots offset[i] + k) and of
  // the segments (slots after them); the first slot of each is its origin.
  void build_edges() {
    const std::size_t sides = c_.polygons.vertex.size();
    if (c_.polygons.size() + c_.segments.size() + sides >= kEdge) throw std::length_error("axis_pruning: complex too large");
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
    keys.reserve(sides + c_.segments.size());
    side_polygon_.resize(sides);
    for (std::uint32_t i = 0; i < c_.polygons.size(); ++i)
      for (std::uint32_t k = 0; k < c_.polygons.ring_size(i); ++k) {
        const auto [a, b] = c_.polygons.side(i, k);
        keys.push_back({key(a, b), c_.polygons.offset[i] + k});
        side_polygon_[c_.polygons.offset[i] + k] = i;
      }
    for (std::uint32_t s = 0; s < c_.segments.size(); ++s)
      keys.push_back({key(c_.segments[s][0], c_.segments[s][1]), static_cast<std::uint32_t>(sides + s)});
    std::sort(keys.begin(), keys.end());
    slot_edge_.resize(keys.size());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edge_polygon, vertex_edge;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (i == 0 || keys[i].first != keys[i - 1].first) {
        edge_a_.push_back(static_cast<std::uint32_t>(keys[i].first >> 32));
        edge_b_.push_back(static_cast<std::uint32_t>(keys[i].first));
        edge_origin_.push_back(keys[i].second);
        edge_live_polygons_.push_back(0);
      }
      const auto e = static_cast<std::uint32_t>(edge_a_.size() - 1);
      slot_edge_[keys[i].second] = e;
      if (keys[i].second < sides) {
        ++edge_live_polygons_[e];
        edge_polygon.push_back({e, side_polygon_[keys[i].second]});
      }
    }
    edge_alive_.assign(edge_count(), true);
    edge_polygons_.build(edge_count(), edge_polygon);
    for (std::uint32_t e = 0; e < edge_count(); ++e) {
      vertex_edge.push_back({edge_a_[e], e});
      vertex_edge.push_back({edge_b_[e], e});
    }
    vertex_edges_.build(c_.vertex_count, vertex_edge);
    vertex_degree_.resize(c_.vertex_count);
    for (std::size_t v = 0; v < c_.vertex_count; ++v) vertex_degree_[v] = vertex_edges_.start[v + 1] - vertex_edges_.start[v];
  }

  static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  }

  EdgeOrigin origin(std::uint32_t e) const {
    const std::uint32_t slot = edge_origin_[e];
    if (slot >= side_polygon_.size()) return {true, static_cast<std::uint32_t>(slot - side_polygon_.size()), 0};
    const std::uint32_t p = side_polygon_[slot];
    return {false, p, slot - c_.polygons.offset[p]};
  }

  bool keeps_polygon(std::uint32_t p) {
    if (polygon_verdict_[p] < 0) polygon_verdict_[p] = keep_polygon_(p) ? 1 : 0;
    return polygon_verdict_[p] == 1;
  }
  bool keeps_edge(std::uint32_t e) {
    if (edge_verdict_[e] < 0) edge_verdict_[e] = keep_edge_(origin(e)) ? 1 : 0;
    return edge_verdict_[e] == 1;
  }

  // A free side: an edge of p that no other live polygon has.
  std::uint32_t free_side(std::uint32_t p) const {
    for (std::uint32_t s = c_.polygons.offset[p]; s < c_.polygons.offset[p + 1]; ++s) {
      const std::uint32_t e = slot_edge_[s];
      if (edge_alive_[e] && edge_live_polygons_[e] == 1) return e;
    }
    return UINT32_MAX;
  }

  void collapse_polygon(std::uint32_t p) {
    if (!polygon_alive_[p]) return;
    const std::uint32_t free = free_side(p);
    if (free == UINT32_MAX || keeps_polygon(p)) return;
    polygon_alive_[p] = false;
    ++collapsed_polygons_;
    remove_edge(free);
    for (std::uint32_t s = c_.polygons.offset[p]; s < c_.polygons.offset[p + 1]; ++s) {
      const std::uint32_t e = slot_edge_[s];
      if (e == free) continue;
      --edge_live_polygons_[e];
      if (edge_live_polygons_[e] == 0) queue_.push_back(kEdge | e);
      if (edge_live_polygons_[e] == 1)
        for (std::uint32_t i = edge_polygons_.start[e]; i < edge_polygons_.start[e + 1]; ++i)
          if (polygon_alive_[edge_polygons_.item[i]]) queue_.push_back(edge_polygons_.item[i]);
    }
  }

  void collapse_edge(std::uint32_t e) {
    if (!edge_alive_[e] || edge_live_polygons_[e] != 0) return;
    const std::uint32_t a = edge_a_[e], b = edge_b_[e];
    const std::uint32_t end = vertex_degree_[a] == 1 ? a : vertex_degree_[b] == 1 ? b : UINT32_MAX;
    if (end == UINT32_MAX || keeps_edge(e)) return;
    vertex_alive_[end] = false;
    remove_edge(e);
  }

  void remove_edge(std::uint32_t e) {
    edge_alive_[e] = false;
    edge_live_polygons_[e] = 0;
    ++collapsed_edges_;
    for (std::uint32_t v : {edge_a_[e], edge_b_[e]}) {
      --vertex_degree_[v];
      if (vertex_degree_[v] == 1 && vertex_alive_[v])
        for (std::uint32_t i = vertex_edges_.start[v]; i < vertex_edges_.start[v + 1]; ++i)
          if (edge_alive_[vertex_edges_.item[i]]) queue_.push_back(kEdge | vertex_edges_.item[i]);
    }
  }

  PrunedComplex result() const {
    PrunedComplex out;
    out.polygon_kept = polygon_alive_;
    out.vertex_kept = vertex_alive_;
    for (std::uint32_t e = 0; e < edge_count(); ++e)
      if (edge_alive_[e] && edge_live_polygons_[e] == 0) {
        out.bare_edges.push_back({edge_a_[e], edge_b_[e]});
        out.bare_origins.push_back(origin(e));
      }
    out.collapsed_polygons = collapsed_polygons_;
    out.collapsed_edges = collapsed_edges_;
    return out;
  }

  const PolygonalComplex& c_;
  const std::function<bool(std::uint32_t)>& keep_polygon_;
  const std::function<bool(const EdgeOrigin&)>& keep_edge_;
  std::vector<std::uint32_t> side_polygon_, slot_edge_;
  std::vector<std::uint32_t> edge_a_, edge_b_, edge_origin_, edge_live_polygons_;
  std::vector<bool> edge_alive_;
  Rows edge_polygons_, vertex_edges_;
  std::vector<std::uint32_t> vertex_degree_;
  std::vector<bool> polygon_alive_, vertex_alive_;
  std::vector<int> polygon_verdict_, edge_verdict_;
  std::vector<std::uint32_t> queue_;
  std::size_t collapsed_polygons_ = 0, collapsed_edges_ = 0;
};

}  // namespace

PrunedComplex prune_by_collapse(const PolygonalComplex& complex, const std::function<bool(std::uint32_t polygon)>& keep_polygon,
                                const std::function<bool(const EdgeOrigin& edge)>& keep_edge) {
  for (std::size_t i = 0; i < complex.polygons.size(); ++i) {
    if (complex.polygons.ring_size(i) < 3) throw std::invalid_argument("prune_by_collapse: a polygon with fewer than 3 sides");
    for (std::uint32_t k = 0; k < complex.polygons.ring_size(i); ++k)
      if (complex.polygons.ring(i)[k] >= complex.vertex_count) throw std::invalid_argument("prune_by_collapse: vertex out of range");
  }
  return Collapser(complex, keep_polygon, keep_edge).run();
}

}  // namespace grassfire
