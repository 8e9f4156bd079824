// medial_graph.h -- the medial graph M of a planar shape (3.3.2; docs/design.md 4).
//
// Computes nothing by itself: it is the data model every 2D algorithm reads. Nodes carry
// a position and R (distance to the shape boundary); edges carry their kind (straight
// segment, or parabolic arc for exact polygon axes) and their length. Positions, R and
// lengths are held as certified double enclosures for speed; the exact values behind
// them come from a MedialGeometry (sampled Voronoi axis, exact polygon axis, hand-built
// graph), so the burning code never depends on how an axis was built.
// Leaves (degree 1) are the border dM of the axis. Adjacency is a Boost.Graph
// compressed_sparse_row_graph in which every undirected edge appears as two arcs whose
// bundled property is the edge id, so BGL algorithms run on it directly.
// Contract (checked by validate()): edge ends are distinct valid nodes; R >= 0; lengths
// >= 0 and finite; the adjacency lists every edge at both of its ends.
// Complexity: construction O(n + m); every accessor O(1).
#pragma once

#include <boost/graph/compressed_sparse_row_graph.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry2/point2.h"
#include "number/exact_sum.h"
#include "number/interval.h"
#include "number/long_interval.h"

namespace grassfire {

enum class EdgeKind : std::uint8_t { Segment, ParabolicArc };
const char* to_string(EdgeKind kind);

struct MedialNode {
  Point2 position;             // a double approximation of the exact position
  Interval radius;             // encloses R, the distance to the shape boundary
  double position_error = 0;   // |position - exact| <= this, per coordinate
};

struct MedialEdge {
  std::uint32_t u = 0;
  std::uint32_t v = 0;
  EdgeKind kind = EdgeKind::Segment;
  Interval length;  // encloses the exact length
};

class MedialGraph;

// The exact values behind a medial graph. Implementations: hand-built graphs
// (ExplicitGeometry below), the sampled Voronoi axis, the exact polygon axis.
class MedialGeometry {
 public:
  virtual ~MedialGeometry() = default;
  virtual ExactSum exact_radius(std::uint32_t node) const = 0;
  virtual ExactSum exact_length(std::uint32_t edge) const = 0;
  // Enclosures [lo, hi] at the precision of lo and hi; by default from the exact values.
  // Providers override them when they can enclose faster than they can build ExactSums.
  virtual void enclose_radius(std::uint32_t node, mpfr_ptr lo, mpfr_ptr hi) const {
    exact_radius(node).enclose(lo, hi);
  }
  virtual void enclose_length(std::uint32_t edge, mpfr_ptr lo, mpfr_ptr hi) const {
    exact_length(edge).enclose(lo, hi);
  }
  // Enclosures in x87 extended precision, the second filter of burn-time comparisons;
  // by default rounded outwards from 80-bit MPFR enclosures.
  virtual LongInterval enclose_radius_long(std::uint32_t node) const;
  virtual LongInterval enclose_length_long(std::uint32_t edge) const;
  // Value classes: two nodes with the same radius_class have provably equal R, two edges
  // with the same length_class provably equal lengths (the class is the id of a member).
  // By default every atom is its own class; the exact polygon axis merges the atoms that
  // an exact symmetry of the polygon maps onto each other (medial2/polygon/polygon_axis_symmetry.h).
  virtual std::uint32_t radius_class(std::uint32_t node) const { return node; }
  virtual std::uint32_t length_class(std::uint32_t edge) const { return edge; }
  // For two edges that meet at a degree-2 node and are pieces of one curve (the same
  // bisector), a length class (same id space as length_class) of their summed length;
  // 0xffffffff otherwise (the default).
  virtual std::uint32_t joined_length_class(std::uint32_t, std::uint32_t) const { return 0xffffffffu; }
  // The point at arc length s (0 <= s <= length) from end `from` along the edge, for
  // drawing and reporting; straight segments by default.
  virtual Point2 point_along(const MedialGraph& g, std::uint32_t edge, std::uint32_t from, double s) const;
  // A polyline that follows the edge from u to v (two points for a segment).
  virtual std::vector<Point2> polyline(const MedialGraph& g, std::uint32_t edge) const;
  virtual std::string description() const = 0;
};

// Exact values given explicitly per node and edge (tests, synthetic graphs).
class ExplicitGeometry : public MedialGeometry {
 public:
  ExplicitGeometry(std::vector<ExactSum> radii, std::vector<ExactSum> lengths)
      : radii_(std::move(radii)), lengths_(std::move(lengths)) {}
  ExactSum exact_radius(std::uint32_t node) const override { return radii_.at(node); }
  ExactSum exact_length(std::uint32_t edge) const override { return lengths_.at(edge); }
  std::string description() const override { return "explicit exact values"; }

 private:
  std::vector<ExactSum> radii_;
  std::vector<ExactSum> lengths_;
};

class MedialGraph {
 public:
  using Adjacency = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, std::uint32_t,
                                                        boost::no_property, std::uint32_t, std::uint32_t>;

  MedialGraph() = default;
  MedialGraph(std::vector<MedialNode> nodes, std::vector<MedialEdge> edges,
              std::shared_ptr<const MedialGeometry> geometry);

  // A graph whose exact R and lengths are the given ExactSums (enclosures derived).
  static MedialGraph from_exact(std::vector<Point2> positions, std::vector<ExactSum> radii,
                                std::vector<std::pair<std::uint32_t, std::uint32_t>> ends,
                                std::vector<ExactSum> lengths);

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(nodes_.size()); }
  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edges_.size()); }
  const MedialNode& node(std::uint32_t i) const { return nodes_[i]; }
  const MedialEdge& edge(std::uint32_t e) const { return edges_[e]; }
  const std::vector<MedialNode>& nodes() const { return nodes_; }
  const std::vector<MedialEdge>& edges() const { return edges_; }
  std::uint32_t degree(std::uint32_t v) const {
    return static_cast<std::uint32_t>(boost::out_degree(v, adjacency_));
  }
  bool is_leaf(std::uint32_t v) const { return degree(v) == 1; }
  // Calls f(edge id) for every edge incident to v.
  template <class F>
  void for_each_incident(std::uint32_t v, F&& f) const {
    auto range = boost::out_edges(v, adjacency_);
    for (auto it = range.first; it != range.second; ++it) f(adjacency_[*it]);
  }
  std::uint32_t other_end(std::uint32_t e, std::uint32_t v) const {
    return edges_[e].u == v ? edges_[e].v : edges_[e].u;
  }
  const Adjacency& adjacency() const { return adjacency_; }
  const MedialGeometry& geometry() const { return *geometry_; }
  std::shared_ptr<const MedialGeometry> geometry_ptr() const { return geometry_; }

  // Betti numbers of the graph as a 1-complex: components and independent cycles.
  std::uint32_t component_count() const;
  std::vector<std::uint32_t> component_of_nodes() const;
  std::uint64_t cycle_rank() const { return edge_count() + std::uint64_t{component_count()} - node_count(); }

  // Throws std::logic_error naming the first violation of the contract above.
  void validate() const;

 private:
  std::vector<MedialNode> nodes_;
  std::vector<MedialEdge> edges_;
  Adjacency adjacency_;
  std::shared_ptr<const MedialGeometry> geometry_;
};

// The 2-core: nodes and edges left after repeatedly peeling leaves and isolated nodes
// (docs/design.md 4: the part with infinite EDF). O(n + m).
struct TwoCore {
  std::vector<bool> node_in_core;
  std::vector<bool> edge_in_core;
  std::uint32_t core_nodes = 0;
};
TwoCore two_core(const MedialGraph& g);

}  // namespace grassfire
