// disk_union_axis.cpp -- see disk_union_axis.h. CGAL stays in disk_union_triangulations.cpp.
#include "medial2/disks/disk_union_axis.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "medial2/disks/disk_union_geometry.h"
#include "medial2/disks/disk_union_triangulations.h"
#include "support/union_find.h"
#include "number/sqrt_field.h"
#include "support/cpu_clock.h"

namespace grassfire {

namespace {

using Clock = std::chrono::steady_clock;

// pi_d(x, y) = |(x, y) - c|^2 - r^2, the power of a point with respect to a disk.
mpq_class power(const Disk& d, const mpq_class& x, const mpq_class& y) {
  const mpq_class dx = x - d.x, dy = y - d.y;
  return dx * dx + dy * dy - d.r * d.r;
}

// Exact sign of the power of a corner m + sqrt(sigma) v: A + 2 sqrt(sigma) v.(m - c).
int corner_power_sign(const Disk& d, const UnionCorner& c, NumberStats* stats) {
  const mpq_class ux = c.mx - d.x, uy = c.my - d.y;
  ExactSum p = ExactSum::rational(ux * ux + uy * uy + c.sigma * (c.vx * c.vx + c.vy * c.vy) - d.r * d.r);
  ExactSum cross = ExactSum::sqrt_of(c.sigma);
  p += cross.scale(2 * (c.vx * ux + c.vy * uy));
  return sign(p, stats);
}

// Joins the sets of a and b; true when they were apart.
bool join(UnionFind& sets, std::uint32_t a, std::uint32_t b) {
  if (sets.find(a) == sets.find(b)) return false;
  sets.unite(a, b);
  return true;
}

// A Voronoi edge of the corners: the bisector of corners a and b between the Voronoi
// vertices (merged groups) `left` and `right` of a -> b (kNoId: at infinity). Disk centres
// inside it cut it into pieces, ordered from left to right.
struct VoronoiEdge {
  std::uint32_t a = 0, b = 0, left = kNoId, right = kNoId;
  std::vector<std::uint32_t> centers;    // disks
  std::vector<bool> center_inward_right;  // per centre: is its medial side to the right?
  std::vector<std::int8_t> status;        // per piece: 1 medial, -1 not, 0 unknown
};

class DiskUnionBuilder {
 public:
  DiskUnionBuilder(const DiskList& list, DiskUnionAxisReport& report)
      : list_(list), d_(list.disks), report_(report), predicates_(corners_) {}

  MedialGraph build() {
    auto t = Clock::now();
    build_dual();
    build_arcs();
    report_.dual_seconds = wall_seconds_since(t);
    t = Clock::now();
    build_voronoi();
    report_.voronoi_seconds = wall_seconds_since(t);
    t = Clock::now();
    seed_centers();
    propagate();
    MedialGraph g = assemble();
    report_.axis_seconds = wall_seconds_since(t);
    report_.predicates = predicates_.stats();
    report_.predicates.merge(stats_);
    return g;
  }

 private:
  std::string where(std::uint32_t i) const {
    return d_[i].line ? "line " + std::to_string(d_[i].line) : "disk " + std::to_string(i);
  }
  [[noreturn]] void reject(const std::string& what) const { throw DiskListError(list_.name + ": " + what); }
  [[noreturn]] static void inconsistent(const std::string& what) {
    throw std::logic_error("disk union axis: " + what + " (a bug or an unhandled degeneracy)");
  }

  // ---- 1. the dual complex K and the corners ------------------------------------------
  void build_dual() {
    const RegularTriangulationData rt = regular_triangulation(d_);
    report_.disks = d_.size();
    neighbours_.assign(d_.size(), {});
    for (const RegularTriangulationData::Edge& e : rt.edges) {
      neighbours_[e.i].push_back(e.j);
      neighbours_[e.j].push_back(e.i);
    }
    std::vector<bool> face_in_k(rt.faces.size(), false);
    for (std::size_t f = 0; f < rt.faces.size(); ++f) face_in_k[f] = classify_face(rt.faces[f]);
    report_.dual_triangles = std::count(face_in_k.begin(), face_in_k.end(), true);
    has_k_edge_.assign(d_.size(), false);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> k_edges;
    for (const RegularTriangulationData::Edge& e : rt.edges) {
      const bool adjacent_triangle = (e.face[0] != kNoId && face_in_k[e.face[0]]) ||
                                     (e.face[1] != kNoId && face_in_k[e.face[1]]);
      if (!classify_edge(e, adjacent_triangle)) continue;
      k_edges.emplace_back(e.i, e.j);
      has_k_edge_[e.i] = has_k_edge_[e.j] = true;
    }
    isolated_.assign(d_.size(), false);
    for (std::uint32_t i : rt.vertices)
      if (!has_k_edge_[i]) isolated_[i] = center_in_own_cell(i, neighbours_[i]);
    std::uint64_t k_vertices = 0;
    for (std::uint32_t i = 0; i < d_.size(); ++i) k_vertices += has_k_edge_[i] || isolated_[i];
    report_.isolated_disks = std::count(isolated_.begin(), isolated_.end(), true);
    report_.covered_disks = d_.size() - k_vertices;
    report_.dual_vertices = k_vertices;
    report_.dual_edges = k_edges.size();
    UnionFind components(d_.size());
    std::uint64_t merges = 0;
    for (const auto& [i, j] : k_edges) merges += join(components, i, j);
    report_.union_components = k_vertices - merges;
    // Euler: V - E + T = b0 - b1 (K is planar, b2 = 0).
    const std::int64_t holes = std::int64_t(report_.dual_edges + report_.union_components) -
                               std::int64_t(k_vertices + report_.dual_triangles);
    if (holes < 0) inconsistent("the dual complex has a negative first Betti number");
    report_.union_holes = static_cast<std::uint64_t>(holes);
    report_.corners = corners_.size();
  }

  // A triangle ijk is in K iff its power vertex lies inside the three disks.
  bool classify_face(const std::array<std::uint32_t, 3>& f) {
    const Disk &a = d_[f[0]], &b = d_[f[1]], &c = d_[f[2]];
    // 2 (c_b - c_a) . p = w_b - w_a, likewise for c, with w = |c|^2 - r^2.
    const mpq_class wa = a.x * a.x + a.y * a.y - a.r * a.r;
    const mpq_class e1x = 2 * (b.x - a.x), e1y = 2 * (b.y - a.y), r1 = b.x * b.x + b.y * b.y - b.r * b.r - wa;
    const mpq_class e2x = 2 * (c.x - a.x), e2y = 2 * (c.y - a.y), r2 = c.x * c.x + c.y * c.y - c.r * c.r - wa;
    const mpq_class det = e1x * e2y - e1y * e2x;
    const mpq_class px = (r1 * e2y - r2 * e1y) / det, py = (e1x * r2 - e2x * r1) / det;
    const int s = sgn(power(a, px, py));
    if (s == 0) {  // the power vertex is on the three circles: in K iff inside the union
      std::vector<std::uint32_t> through{f[0], f[1], f[2]};
      for (std::uint32_t k : neighbours_[f[0]])
        if (sgn(power(d_[k], px, py)) == 0) through.push_back(k);
      require_interior({ExactSum::rational(px), ExactSum::rational(py)}, through);
      return true;
    }
    return s < 0;
  }

  // A point q on the circles of the disks `through` and in no other disk is inside the
  // union iff the directions from q to their centres leave no angular gap of pi or more
  // (the disks then cover a neighbourhood of q); otherwise it is a boundary point on three
  // or more circles, or where two circles touch: a degenerate union.
  void require_interior(const std::array<ExactSum, 2>& q, std::vector<std::uint32_t> through) {
    std::sort(through.begin(), through.end());
    through.erase(std::unique(through.begin(), through.end()), through.end());
    std::vector<std::array<ExactSum, 2>> dir;
    for (std::uint32_t k : through) dir.push_back({ExactSum::rational(d_[k].x) - q[0], ExactSum::rational(d_[k].y) - q[1]});
    auto half = [&](const std::array<ExactSum, 2>& v) {
      const int sy = sign(v[1], &stats_);
      return sy > 0 || (sy == 0 && sign(v[0], &stats_) > 0) ? 0 : 1;
    };
    auto cross = [&](const std::array<ExactSum, 2>& a, const std::array<ExactSum, 2>& b) {
      return sign(multiply(a[0], b[1]) - multiply(a[1], b[0]), &stats_);
    };
    std::sort(dir.begin(), dir.end(), [&](const auto& a, const auto& b) {
      return half(a) != half(b) ? half(a) < half(b) : cross(a, b) > 0;
    });
    bool interior = dir.size() >= 3;
    for (std::size_t k = 0; interior && k < dir.size(); ++k) {
      const auto &a = dir[k], &b = dir[(k + 1) % dir.size()];
      const int c = cross(a, b);
      interior = c > 0 || (c == 0 && sign(multiply(a[0], b[0]) + multiply(a[1], b[1]), &stats_) > 0);
    }
    if (interior) return;
    std::string names;
    for (std::size_t k = 0; k < through.size(); ++k) names += (k ? ", " : "") + where(through[k]);
    reject("the circles of the disks on " + names + " meet at one point of the union's boundary (" +
           (through.size() == 2 ? "the disks touch there" : "a corner on three or more circles") +
           "); the union is degenerate there, perturb one of them");
  }

  // An edge ij is in K iff the power edge meets the lens B_i and B_j; records its corners.
  bool classify_edge(const RegularTriangulationData::Edge& e, bool adjacent_triangle) {
    bool tangent = false;
    const std::optional<UnionCorner> plus = circle_crossing(d_, e.i, e.j, +1, &tangent);
    if (!plus) {
      if (tangent) check_tangency(e);
      return false;
    }
    // m, the middle of the chord, minimises pi_i on the radical line; it lies on the power
    // edge iff no apex has a smaller power there.
    bool in_k = adjacent_triangle;
    if (!in_k) {
      const mpq_class pm = power(d_[e.i], plus->mx, plus->my);
      in_k = true;
      for (std::uint32_t k : e.apex)
        if (k != kNoId && power(d_[k], plus->mx, plus->my) < pm) in_k = false;
    }
    if (!in_k) return false;
    for (int s : {+1, -1}) {
      const UnionCorner c = s > 0 ? *plus : *circle_crossing(d_, e.i, e.j, -1);
      bool on_boundary = true, on_third_circle = false;
      for (std::uint32_t k : e.apex) {
        if (k == kNoId) continue;
        const int p = corner_power_sign(d_[k], c, &stats_);
        on_third_circle = on_third_circle || p == 0;
        if (p < 0) on_boundary = false;
      }
      if (on_boundary && on_third_circle) {  // inside the union, or a degenerate corner
        std::vector<std::uint32_t> through{e.i, e.j};
        for (std::uint32_t k : neighbours_[e.i])
          if (corner_power_sign(d_[k], c, &stats_) == 0) through.push_back(k);
        require_interior({corner_x(c), corner_y(c)}, through);
        on_boundary = false;
      }
      if (on_boundary) corners_.push_back(c);
    }
    return true;
  }

  // Tangent circles: harmless inside another disk or when one disk contains the other;
  // a single touching point on the boundary makes the union non-manifold.
  void check_tangency(const RegularTriangulationData::Edge& e) {
    const Disk &a = d_[e.i], &b = d_[e.j];
    const mpq_class dx = b.x - a.x, dy = b.y - a.y, dr = a.r - b.r;
    if (dx * dx + dy * dy == dr * dr) return;  // internally tangent: one disk covers the other
    const mpq_class t = a.r / (a.r + b.r);
    const mpq_class px = a.x + t * dx, py = a.y + t * dy;
    for (std::uint32_t k : e.apex)
      if (k != kNoId && sgn(power(d_[k], px, py)) < 0) return;  // inside a third disk
    std::vector<std::uint32_t> through{e.i, e.j};
    for (std::uint32_t k : neighbours_[e.i])
      if (sgn(power(d_[k], px, py)) == 0) through.push_back(k);
    require_interior({ExactSum::rational(px), ExactSum::rational(py)}, through);
  }

  // A disk without K edges is isolated iff its centre lies in its own power cell.
  bool center_in_own_cell(std::uint32_t i, const std::vector<std::uint32_t>& neighbours) const {
    for (std::uint32_t k : neighbours)
      if (power(d_[k], d_[i].x, d_[i].y) < -d_[i].r * d_[i].r) return false;
    return true;
  }

  // ---- 2. arcs ----------------------------------------------------------------------
  void build_arcs() {
    on_circle_.assign(d_.size(), {});
    for (std::uint32_t c = 0; c < corners_.size(); ++c)
      for (std::uint32_t k : corners_[c].disk) on_circle_[k].push_back(c);
    arc_count_.assign(d_.size(), 0);
    for (std::uint32_t i = 0; i < d_.size(); ++i) {
      std::vector<std::uint32_t>& around = on_circle_[i];
      std::sort(around.begin(), around.end(), [&](std::uint32_t a, std::uint32_t b) {
        return predicates_.compare_angle(d_[i], a, b) < 0;
      });
      const std::size_t n = around.size();
      std::size_t first = 0;
      while (first < n && role(around[first], i) < 0) ++first;
      for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t cur = around[(first + k) % n], next = around[(first + k + 1) % n];
        if (role(cur, i) == role(next, i)) inconsistent("arcs on the circle of " + where(i) + " do not alternate");
        if (role(cur, i) > 0) arcs_.push_back({i, cur, next});
      }
      arc_count_[i] = static_cast<std::uint32_t>(n / 2);
      std::sort(around.begin(), around.end());
    }
    report_.arcs = arcs_.size();
  }

  int role(std::uint32_t corner, std::uint32_t disk) const {
    const UnionCorner& c = corners_[corner];
    return c.disk[0] == disk ? c.role[0] : c.role[1];
  }

  // ---- 3. the Voronoi diagram of the corners -----------------------------------------
  void build_voronoi() {
    if (corners_.empty()) return;
    if (corners_.size() < 2) inconsistent("a single corner");
    const CornerTriangulationData dt = corner_delaunay(corners_, predicates_);
    UnionFind faces(dt.faces.size());
    for (const CornerTriangulationData::Edge& e : dt.edges) {
      if (e.left == kNoId || e.right == kNoId) continue;
      const std::array<std::uint32_t, 3>& f = dt.faces[e.left];
      if (predicates_.in_circle(f[0], f[1], f[2], opposite(dt.faces[e.right], e.a, e.b)) == 0)
        report_.cocircular_merges += join(faces, e.left, e.right);
    }
    std::vector<std::uint32_t> group_of_face(dt.faces.size(), kNoId);
    for (std::uint32_t f = 0; f < dt.faces.size(); ++f) {
      const std::uint32_t root = faces.find(f);
      if (group_of_face[root] == kNoId) {
        group_of_face[root] = static_cast<std::uint32_t>(groups_.size());
        groups_.emplace_back();
      }
      group_of_face[f] = group_of_face[root];
      for (std::uint32_t c : dt.faces[f]) groups_[group_of_face[f]].push_back(c);
    }
    for (std::vector<std::uint32_t>& g : groups_) {
      std::sort(g.begin(), g.end());
      g.erase(std::unique(g.begin(), g.end()), g.end());
    }
    report_.voronoi_vertices = groups_.size();
    group_center_.assign(groups_.size(), kNoId);
    for (std::uint32_t g = 0; g < groups_.size(); ++g) group_center_[g] = common_circle(groups_[g]);
    incident_.assign(groups_.size(), {});
    for (const CornerTriangulationData::Edge& e : dt.edges) {
      const std::uint32_t gl = e.left == kNoId ? kNoId : group_of_face[e.left];
      const std::uint32_t gr = e.right == kNoId ? kNoId : group_of_face[e.right];
      if (gl == gr && gl != kNoId) continue;  // inside a cocircular group: zero length
      const std::uint32_t id = static_cast<std::uint32_t>(vedges_.size());
      vedges_.push_back({e.a, e.b, gl, gr, {}, {}, {}});
      edge_of_pair_[{std::min(e.a, e.b), std::max(e.a, e.b)}] = id;
      if (gl != kNoId) incident_[gl].push_back(id);
      if (gr != kNoId) incident_[gr].push_back(id);
    }
  }

  static std::uint32_t opposite(const std::array<std::uint32_t, 3>& f, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t c : f)
      if (c != a && c != b) return c;
    inconsistent("a Delaunay face without a third corner");
  }

  // The disk whose circle carries every corner of a group, if any: that group is its centre.
  std::uint32_t common_circle(const std::vector<std::uint32_t>& group) const {
    for (std::uint32_t disk : corners_[group[0]].disk) {
      const bool all = std::all_of(group.begin(), group.end(), [&](std::uint32_t c) {
        return corners_[c].disk[0] == disk || corners_[c].disk[1] == disk;
      });
      if (!all) continue;
      if (group != on_circle_[disk] || arc_count_[disk] < 2)
        inconsistent("a cocircular group on the circle of " + where(disk) + " is not its set of corners");
      return disk;
    }
    return kNoId;
  }

  // ---- 4. medial pieces ----------------------------------------------------------------
  void set_status(VoronoiEdge& v, std::size_t piece, std::int8_t s) {
    if (v.status[piece] == -s) inconsistent("a Voronoi piece is both medial and not medial");
    v.status[piece] = s;
  }

  void seed_centers() {
    // One-arc disks: the centre lies inside the Voronoi edge of its gap.
    for (std::uint32_t i = 0; i < d_.size(); ++i) {
      if (arc_count_[i] != 1) continue;
      const UnionArc& arc = *std::find_if(arcs_.begin(), arcs_.end(), [&](const UnionArc& a) { return a.disk == i; });
      VoronoiEdge& v = edge_of(arc.end, arc.start);
      v.centers.push_back(i);
      v.center_inward_right.push_back(v.a == arc.end);  // the gap is to the right of end -> start
    }
    for (VoronoiEdge& v : vedges_) order_centers(v);
    // Centres with k >= 2 arcs are Voronoi vertices: gaps medial, arcs not.
    for (std::uint32_t g = 0; g < groups_.size(); ++g) {
      const std::uint32_t disk = group_center_[g];
      if (disk == kNoId) continue;
      std::uint32_t gaps = 0;
      for (std::uint32_t id : incident_[g]) {
        VoronoiEdge& v = vedges_[id];
        const bool left = v.left == g;
        const std::uint32_t p = left ? v.a : v.b, q = left ? v.b : v.a;  // counter-clockwise on the circle
        const bool gap = role(p, disk) < 0 && role(q, disk) > 0;
        if (!gap && !(role(p, disk) > 0 && role(q, disk) < 0)) inconsistent("a centre's Voronoi edge is no arc or gap");
        gaps += gap;
        set_status(v, left ? 0 : v.status.size() - 1, gap ? 1 : -1);
      }
      if (gaps != arc_count_[disk]) inconsistent("the centre of " + where(disk) + " does not see one edge per gap");
    }
  }

  VoronoiEdge& edge_of(std::uint32_t a, std::uint32_t b) {
    const auto it = edge_of_pair_.find({std::min(a, b), std::max(a, b)});
    if (it == edge_of_pair_.end()) inconsistent("the corners of a gap are not Delaunay neighbours");
    return vedges_[it->second];
  }

  // Sorts the centres inside an edge from left to right and seeds their pieces.
  void order_centers(VoronoiEdge& v) {
    v.status.assign(v.centers.size() + 1, 0);
    if (v.centers.size() > 2) inconsistent("more than two disk centres on one Voronoi edge");
    if (v.centers.size() == 2) {
      // Direction from the left to the right vertex: (a -> b) turned clockwise.
      const ExactSum ex = corner_y(corners_[v.b]) - corner_y(corners_[v.a]);
      const ExactSum ey = corner_x(corners_[v.a]) - corner_x(corners_[v.b]);
      const Disk &p = d_[v.centers[0]], &q = d_[v.centers[1]];
      ExactSum ax = ex, ay = ey;
      if (sign(ax.scale(q.x - p.x) + ay.scale(q.y - p.y), &stats_) < 0) {
        std::swap(v.centers[0], v.centers[1]);
        const bool first = v.center_inward_right[0];
        v.center_inward_right[0] = v.center_inward_right[1];
        v.center_inward_right[1] = first;
      }
    }
    for (std::size_t k = 0; k < v.centers.size(); ++k) {
      set_status(v, v.center_inward_right[k] ? k + 1 : k, 1);
      set_status(v, v.center_inward_right[k] ? k : k + 1, -1);
    }
  }

  // The group at one end of a piece, or kNoId when that end is a centre inside the edge.
  static std::uint32_t end_group(const VoronoiEdge& v, std::size_t piece, bool right, bool* at_infinity) {
    const bool at_end = right ? piece + 1 == v.status.size() : piece == 0;
    const std::uint32_t g = at_end ? (right ? v.right : v.left) : kNoId;
    *at_infinity = at_end && g == kNoId;
    return g;
  }

  void propagate() {
    medial_group_.assign(groups_.size(), false);
    std::vector<std::uint32_t> queue;
    auto reach = [&](const VoronoiEdge& v, std::size_t piece, bool right) {
      bool infinite = false;
      const std::uint32_t g = end_group(v, piece, right, &infinite);
      if (infinite) inconsistent("a medial Voronoi piece runs to infinity");
      if (g != kNoId && group_center_[g] == kNoId && !medial_group_[g]) {
        medial_group_[g] = true;
        queue.push_back(g);
      }
    };
    for (const VoronoiEdge& v : vedges_)
      for (std::size_t p = 0; p < v.status.size(); ++p)
        if (v.status[p] == 1) reach(v, p, false), reach(v, p, true);
    for (std::size_t next = 0; next < queue.size(); ++next) {
      const std::uint32_t g = queue[next];
      for (std::uint32_t id : incident_[g]) {
        VoronoiEdge& v = vedges_[id];
        const bool left = v.left == g;
        const std::size_t piece = left ? 0 : v.status.size() - 1;
        set_status(v, piece, 1);
        reach(v, piece, left);
      }
    }
  }

  // ---- assembly ------------------------------------------------------------------------
  MedialGraph assemble() {
    std::vector<UnionNodeData> nodes;
    std::vector<std::uint32_t> node_of_disk(d_.size(), kNoId), node_of_group(groups_.size(), kNoId);
    for (std::uint32_t i = 0; i < d_.size(); ++i) {
      if (arc_count_[i] == 0 && !isolated_[i]) continue;
      node_of_disk[i] = static_cast<std::uint32_t>(nodes.size());
      nodes.push_back({UnionNodeKind::Center, i, on_circle_[i]});
    }
    for (std::uint32_t g = 0; g < groups_.size(); ++g) {
      if (group_center_[g] != kNoId) {
        node_of_group[g] = node_of_disk[group_center_[g]];
      } else if (medial_group_[g]) {
        node_of_group[g] = static_cast<std::uint32_t>(nodes.size());
        nodes.push_back({UnionNodeKind::Vertex, 0, groups_[g]});
      }
    }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
    std::vector<UnionEdgeData> edge_data;
    for (const VoronoiEdge& v : vedges_) {
      for (std::size_t p = 0; p < v.status.size(); ++p) {
        if (v.status[p] != 1) continue;
        const std::uint32_t u = p == 0 ? node_of_group[v.left] : node_of_disk[v.centers[p - 1]];
        const std::uint32_t w = p + 1 == v.status.size() ? node_of_group[v.right] : node_of_disk[v.centers[p]];
        ends.emplace_back(u, w);
        edge_data.push_back({v.a, v.b});
      }
    }
    auto geometry = std::make_shared<DiskUnionGeometry>(list_, corners_, arcs_, std::move(nodes), ends,
                                                        std::move(edge_data));
    std::vector<MedialNode> graph_nodes(geometry->node_count());
    for (std::uint32_t n = 0; n < graph_nodes.size(); ++n) {
      const IntervalPoint2 p = geometry->position_enclosure(n);
      graph_nodes[n] = {{p.x.mid(), p.y.mid()}, geometry->radius_enclosure(n), std::max(p.x.radius(), p.y.radius())};
    }
    std::vector<MedialEdge> graph_edges;
    for (std::uint32_t e = 0; e < ends.size(); ++e)
      graph_edges.push_back({ends[e].first, ends[e].second, EdgeKind::Segment, geometry->length_enclosure(e)});
    MedialGraph g(std::move(graph_nodes), std::move(graph_edges), std::move(geometry));
    report_.nodes = g.node_count();
    report_.edges = g.edge_count();
    for (std::uint32_t v = 0; v < g.node_count(); ++v) report_.leaves += g.degree(v) == 1;
    return g;
  }

  const DiskList& list_;
  const std::vector<Disk>& d_;
  DiskUnionAxisReport& report_;
  std::vector<UnionCorner> corners_;
  CornerPredicates predicates_;
  NumberStats stats_;
  std::vector<bool> has_k_edge_, isolated_;
  std::vector<std::vector<std::uint32_t>> neighbours_;  // in the regular triangulation
  std::vector<std::vector<std::uint32_t>> on_circle_;  // corners on each circle, sorted by id
  std::vector<std::uint32_t> arc_count_;
  std::vector<UnionArc> arcs_;
  std::vector<std::vector<std::uint32_t>> groups_;     // corners of each Voronoi vertex
  std::vector<std::uint32_t> group_center_;            // disk whose centre the group is, or kNoId
  std::vector<std::vector<std::uint32_t>> incident_;   // Voronoi edges at each group
  std::vector<VoronoiEdge> vedges_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_of_pair_;
  std::vector<bool> medial_group_;
};

}  // namespace

MedialGraph disk_union_axis(const DiskList& disks, DiskUnionAxisReport* report) {
  if (disks.disks.empty()) throw DiskListError(disks.name + ": no disks");
  DiskUnionAxisReport local;
  DiskUnionBuilder builder(disks, report ? *report : local);
  return builder.build();
}

}  // namespace grassfire
