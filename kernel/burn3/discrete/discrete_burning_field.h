// discrete_burning_field.h -- the discrete baseline as a BurningField (burning_field.h).
//
// Computes, from a finished DiscreteBurning and the predecessors it records
// (arrival_from, burn_slot):
//  - at a graph point y on the boundary of triangle t, the t-side time: the first arrival
//    through t's link element at y (its sector at a vertex, its arc at a Steiner point)
//    when that came before y burned, else BT(y); and the path: through that arrival's
//    emitter, or y's own burning path;
//  - at any point p of closed t: BT_t(p) = min over the graph points y on t's boundary of
//    BT_t(y) + |p - y| (one more step of the baseline's rule: inside t the fire crossed t
//    in a straight line from its boundary; an interior point burns at its first arrival),
//    and over the points y of t's igniting border edges of f(y) + |p - y| (f is known
//    along the whole border edge, not only at its graph points: near a corner of the
//    border the graph points alone would bend the paths), `from` = the minimising y; the path p, y, then y's; the direction of travel is the
//    chord of the path's last `chord_length` (default 6 h; the whole path when shorter):
//    the discrete path zigzags through graph points about a straight one, so the last step
//    alone is off by up to 60 degrees near the triangle's boundary, a chord over 6 h by
//    about 5 (it cuts corners within 6 h after a real turn);
//  - on a dangling segment: the same from the graph points of the segment.
// Point sources (DiscreteBurningOptions::sources): a path that came straight from a source
// ends at the source's point.
// Ties between equal candidates go to the first graph point in the order: t's corners,
// then the Steiner points of t.e[0], t.e[1], t.e[2] (deterministic).
// Error: that of the baseline (discrete_burning.h): BT_t is an upper bound of the true
// t-side time, O(h) above it; directions are those of polygonal paths through graph
// points, within O(h / distance to the previous turn) of the true ones.
// Contract: `burning` was computed on `mc` and both outlive this object.
// Complexity: a sample O(graph points on t's boundary); a path O(its points).
#pragma once

#include "burn3/burning_field.h"
#include "burn3/discrete/discrete_burning.h"
#include "burn3/discrete/steiner_graph.h"

namespace grassfire {

class DiscreteBurningField final : public BurningField {
 public:
  // chord_length <= 0: 6 h.
  DiscreteBurningField(const MedialComplex& mc, const DiscreteBurning& burning, double chord_length = 0);

  const MedialComplex& complex() const override { return mc_; }
  std::string method() const override;
  double resolution() const override { return d_.spacing; }

  double vertex_burn_time(std::uint32_t v) const override { return d_.vertex_bt[v]; }
  std::uint32_t edge_points(std::uint32_t e) const override { return d_.steiner_count(e); }
  double edge_point_burn_time(std::uint32_t e, std::uint32_t i) const override { return d_.bt_on_edge(mc_, e, i); }

  FieldSample sample_in_triangle(std::uint32_t t, const Vec3d& p) const override;
  FieldSample sample_on_segment(std::uint32_t e, double s) const override;

  std::vector<Vec3d> path_in_triangle(std::uint32_t t, const Vec3d& p) const override;
  std::vector<Vec3d> path_on_segment(std::uint32_t e, double s) const override;
  std::vector<Vec3d> path_from_vertex(std::uint32_t v) const override;
  std::vector<Vec3d> path_from_edge_point(std::uint32_t e, std::uint32_t i) const override;

  const DiscreteBurning& burning() const { return d_; }
  const SteinerGraph& graph() const { return g_; }

 private:
  struct Side {
    double bt = DiscreteBurning::kInfinity;
    std::uint32_t next = kNoIndex;  // the path's next graph point (kNoIndex: it started here)
  };
  struct BorderFoot {
    double time = DiscreteBurning::kInfinity;
    Vec3d point{};
  };
  BorderFoot nearest_ignition(std::uint32_t t, const Vec3d& p) const;
  double node_bt(std::uint32_t node) const;
  // A path step is a graph point, or a point source (DiscreteBurning::kFromSource + i),
  // where the path ends.
  static bool is_source(std::uint32_t step) { return step != kNoIndex && step >= DiscreteBurning::kFromSource; }
  Vec3d position(std::uint32_t step) const;
  Side own(std::uint32_t node) const;
  Side through_triangle(std::uint32_t node, std::uint32_t t) const;
  Side through_slot(std::uint32_t node, std::uint32_t local) const;
  std::vector<std::uint32_t> boundary_nodes(std::uint32_t t) const;
  std::vector<std::uint32_t> segment_nodes(std::uint32_t e) const;
  FieldSample best_of(const Vec3d& p, const std::vector<std::uint32_t>& nodes, std::uint32_t t,
                      std::uint32_t* best_node, Side* best_side) const;
  void append_path(std::uint32_t node, std::vector<Vec3d>& path) const;
  Vec3d chord_start(Vec3d at, std::uint32_t node, double left) const;
  static Vec3d chord_step(const Vec3d& at, const Vec3d& q, double& left);

  const MedialComplex& mc_;
  const DiscreteBurning& d_;
  SteinerGraph g_;
  double chord_;
};

}  // namespace grassfire
