// union_tet_axis.cpp -- see union_tet_axis.h.
#include "medial3/balls/union_tet_axis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "geometry3/exact_predicates3.h"

namespace grassfire {

namespace {

using Box = std::array<Interval, 3>;

Interval squared_distance(const Box& a, const Box& b) {
  Interval s(0.0);
  for (int k = 0; k < 3; ++k) s += square(a[k] - b[k]);
  return s;
}

Box enclose_point(const ExactPoint3& p) { return {enclose(p.x), enclose(p.y), enclose(p.z)}; }

// A uniform grid over the boundary vertices, for box queries.
class PointGrid {
 public:
  explicit PointGrid(const std::vector<BoundaryVertex>& points) {
    lo_ = {INFINITY, INFINITY, INFINITY};
    std::array<double, 3> hi{-INFINITY, -INFINITY, -INFINITY};
    for (const BoundaryVertex& v : points)
      for (int k = 0; k < 3; ++k) {
        lo_[k] = std::min(lo_[k], v.approx[k].lo);
        hi[k] = std::max(hi[k], v.approx[k].hi);
      }
    double extent = 0;
    for (int k = 0; k < 3; ++k) extent = std::max(extent, hi[k] - lo_[k]);
    h_ = std::max(extent / std::max(1.0, std::cbrt(static_cast<double>(points.size()))), 1e-300);
    for (int k = 0; k < 3; ++k) dims_[k] = static_cast<long>((hi[k] - lo_[k]) / h_) + 1;
    // Compressed rows: the points of cell c are points_[first_[c] .. first_[c + 1]), in
    // increasing order.
    first_.assign(static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
    std::vector<std::size_t> cell(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) ++first_[(cell[i] = cell_of(points[i].approx)) + 1];
    for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
    points_.resize(points.size());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (std::uint32_t i = 0; i < points.size(); ++i) points_[next[cell[i]]++] = i;
  }

  template <class F>
  void visit(const std::array<double, 3>& lo, const std::array<double, 3>& hi, F f) const {
    std::array<long, 3> a, b;
    for (int k = 0; k < 3; ++k) {
      a[k] = clamp_index(k, std::floor((lo[k] - lo_[k]) / h_) - 1);
      b[k] = clamp_index(k, std::floor((hi[k] - lo_[k]) / h_) + 1);
    }
    for (long x = a[0]; x <= b[0]; ++x)
      for (long y = a[1]; y <= b[1]; ++y)
        for (long z = a[2]; z <= b[2]; ++z)
          for (std::size_t c = static_cast<std::size_t>((x * dims_[1] + y) * dims_[2] + z), i = first_[c]; i < first_[c + 1]; ++i)
            f(points_[i]);
  }
  double spacing() const { return h_; }

 private:
  long clamp_index(int k, double i) const { return static_cast<long>(std::clamp(i, 0.0, static_cast<double>(dims_[k] - 1))); }
  std::size_t cell_of(const Box& p) const {
    long i[3];
    for (int k = 0; k < 3; ++k) i[k] = clamp_index(k, std::floor((p[k].mid() - lo_[k]) / h_));
    return static_cast<std::size_t>((i[0] * dims_[1] + i[1]) * dims_[2] + i[2]);
  }
  std::array<double, 3> lo_;
  double h_ = 1;
  std::array<long, 3> dims_{1, 1, 1};
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> points_;
};

struct PlaneInfo {
  bool bisector = false;
  std::array<std::uint32_t, 3> face{};  // balls of a tetrahedron face
  std::uint32_t v = 0, u = 0;           // bisector of boundary vertices v (kept side) and u
};

struct VertexKey {
  std::vector<std::uint32_t> feature, equidistant;
  std::uint32_t collision = 0;
  bool operator<(const VertexKey& o) const {
    return std::tie(feature, equidistant, collision) < std::tie(o.feature, o.equidistant, o.collision);
  }
};

bool contains(const std::array<std::uint32_t, 3>& set, std::uint32_t x) {
  return std::find(set.begin(), set.end(), x) != set.end();
}

bool boxes_overlap(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k)
    if (a[k].hi < b[k].lo || b[k].hi < a[k].lo) return false;
  return true;
}

// The exact bisector planes of boundary vertices, made on first use: most planes are only
// ever evaluated by the interval filter, and the axis vertices keep their planes beyond
// the builder's life (LazyPoint3), so the field is shared. Not thread-safe.
class BisectorField {
 public:
  BisectorField(const std::vector<BoundaryVertex>& boundary, const RadicalTable& table)
      : boundary_(boundary), table_(&table), made_(boundary.size()) {}

  // |x - v|^2 <= |x - u|^2  <=>  2 (u - v) . x + |v|^2 - |u|^2 <= 0.
  CellPlane::Coefficients bisector(std::uint32_t v, std::uint32_t u) const {
    const Entry& p = entry(v);
    const Entry& q = entry(u);
    return {(q.x[0] - p.x[0]) * mpq_class(2), (q.x[1] - p.x[1]) * mpq_class(2), (q.x[2] - p.x[2]) * mpq_class(2),
            p.norm2 - q.norm2};
  }

 private:
  struct Entry {
    std::array<RadicalNumber, 3> x;
    RadicalNumber norm2;
  };
  const Entry& entry(std::uint32_t i) const {
    if (!made_[i]) {
      const BoundaryVertex& v = boundary_[i];
      // |v|^2 = |z|^2 + s |n|^2 + 2 side sqrt(s) z . n
      made_[i] = std::make_unique<Entry>(Entry{
          v.coordinates(*table_), v.rational ? RadicalNumber(dot(v.point, v.point))
                                             : RadicalNumber(dot(v.z, v.z) + v.s * dot(v.n, v.n)) +
                                                   RadicalNumber::root(*table_, v.radical, 2 * v.side * dot(v.z, v.n))});
    }
    return *made_[i];
  }
  std::vector<BoundaryVertex> boundary_;
  const RadicalTable* table_;
  mutable std::vector<std::unique_ptr<Entry>> made_;
};

// The per-run state: boundary vertices, the global vertex table and the polygons.
class Builder {
 public:
  Builder(const BallSet& balls, const AlphaComplex& k, const std::vector<BoundaryVertex>& boundary,
          const RadicalTable& table, bool reach)
      : balls_(balls), k_(k), boundary_(boundary), approx_(boundary.size()), grid_(boundary),
        field_(std::make_shared<const BisectorField>(boundary, table)), reach_(reach) {
    for (std::size_t i = 0; i < boundary.size(); ++i) approx_[i] = boundary[i].approx;
  }

  TetAxis run() {
    for (std::uint32_t t : k_.of_dimension(3))
      if (k_.in_complex(t)) process_tetrahedron(k_.simplices()[t]);
    merge_coincident();
    drop_duplicate_polygons();
    return std::move(out_);
  }

 private:
  // The balls of the smallest face of tau containing x: the intersection of the balls of
  // the tetrahedron faces through it (0 to 3 balls; none inside tau), without the heap.
  struct Feature {
    std::array<std::uint32_t, 3> balls{};
    std::size_t size = 0;
  };
  Feature smallest_face(const CellVertex& x) const {
    bool first = true;
    Feature f;
    for (std::uint32_t p : x.support) {
      const PlaneInfo& info = info_[p];
      if (info.bisector) continue;
      if (first) {
        f.balls = info.face;
        f.size = 3;
        first = false;
      } else {
        std::size_t m = 0;
        for (std::size_t i = 0; i < f.size; ++i)
          if (contains(info.face, f.balls[i])) f.balls[m++] = f.balls[i];
        f.size = m;
      }
    }
    return f;
  }
  std::vector<std::uint32_t> feature_of(const CellVertex& x) const {
    const Feature f = smallest_face(x);
    return {f.balls.begin(), f.balls.begin() + static_cast<std::ptrdiff_t>(f.size)};
  }

  // The bisector of v and u contains the face through x when every ball of that face has
  // both v and u on its sphere (its centre is then equidistant from them).
  bool structural(const std::uint32_t* feature, std::size_t size, std::uint32_t v, std::uint32_t u) const {
    if (size == 0) return false;
    for (std::size_t i = 0; i < size; ++i)
      if (!contains(boundary_[v].balls, feature[i]) || !contains(boundary_[u].balls, feature[i])) return false;
    return true;
  }

  VertexKey key_of(const CellVertex& x) const {
    VertexKey key;
    key.feature = feature_of(x);
    if (key.feature.size() == 1) return key;  // a ball centre
    for (std::uint32_t p : x.support) {
      const PlaneInfo& info = info_[p];
      if (!info.bisector || structural(key.feature.data(), key.feature.size(), info.v, info.u)) continue;
      key.equidistant.push_back(info.v);
      key.equidistant.push_back(info.u);
    }
    std::sort(key.equidistant.begin(), key.equidistant.end());
    key.equidistant.erase(std::unique(key.equidistant.begin(), key.equidistant.end()), key.equidistant.end());
    return key;
  }

  // The plane of the bisector of v and u (kept side: v's), added to this tetrahedron's set;
  // each ordered pair is asked once per tetrahedron (one cell per v, one clip per u).
  std::uint32_t bisector(PlaneSet& planes, std::uint32_t v, std::uint32_t u) {
    // |x - v|^2 <= |x - u|^2  <=>  2 (u - v) . x + |v|^2 - |u|^2 <= 0.
    const Box& a = approx_[v];
    const Box& b = approx_[u];
    // In local coordinates x - o: d + n . o = |v - o|^2 - |u - o|^2 = (v - u) . (v + u - 2 o).
    std::array<Interval, 4> approx;
    approx[3] = Interval(0.0);
    for (int k = 0; k < 3; ++k) {
      approx[k] = Interval(2) * (b[k] - a[k]);
      approx[3] += (a[k] - b[k]) * (a[k] + b[k] - Interval(2 * origin_[k]));
    }
    auto make = [field = field_, v, u]() { return field->bisector(v, u); };
    const std::uint32_t id = planes.add(CellPlane(make, approx, 0));
    info_.push_back({true, {}, v, u});
    return id;
  }

  ConvexCell tetrahedron_cell(PlaneSet& planes, const PowerSimplex& tau) {
    std::array<ExactPoint3, 4> c;
    for (int k = 0; k < 4; ++k) c[k] = balls_.centers[tau.balls[k]];
    std::vector<CellFace> faces;
    std::vector<std::vector<std::uint32_t>> support(4);
    for (int omit = 0; omit < 4; ++omit) {
      std::array<int, 3> f;
      for (int k = 0, m = 0; k < 4; ++k)
        if (k != omit) f[m++] = k;
      // Outward order: swapping f[1] and f[2] when the omitted corner lies on the positive
      // side of (f[0], f[1], f[2]) negates the normal, which is done on the one cross product.
      ExactPoint3 n = cross(c[f[1]] - c[f[0]], c[f[2]] - c[f[0]]);
      if (sgn(dot(n, c[omit] - c[f[0]])) > 0) {
        std::swap(f[1], f[2]);
        n = {-n.x, -n.y, -n.z};
      }
      const mpq_class d = -dot(n, c[f[0]]);
      const Interval a = enclose(n.x), b = enclose(n.y), cz = enclose(n.z);
      const std::array<Interval, 4> local{a, b, cz, enclose(d) + a * origin_[0] + b * origin_[1] + cz * origin_[2]};
      const std::uint32_t id =
          planes.add(CellPlane({RadicalNumber(n.x), RadicalNumber(n.y), RadicalNumber(n.z), RadicalNumber(d)}, local, 0));
      std::array<std::uint32_t, 3> fb{tau.balls[f[0]], tau.balls[f[1]], tau.balls[f[2]]};
      std::sort(fb.begin(), fb.end());
      info_.push_back({false, fb, 0, 0});
      faces.push_back({{static_cast<std::uint32_t>(f[0]), static_cast<std::uint32_t>(f[1]), static_cast<std::uint32_t>(f[2])}, {id}});
      for (int k : f) support[k].push_back(id);
    }
    std::vector<CellVertex> corners;
    for (int k = 0; k < 4; ++k) corners.push_back(rational_vertex(c[k], support[k], origin_));
    return ConvexCell(planes, std::move(corners), std::move(faces));
  }

  std::vector<std::uint32_t> candidates(const std::array<Box, 4>& corners) const {
    std::array<double, 3> lo, hi, centre;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min({corners[0][k].lo, corners[1][k].lo, corners[2][k].lo, corners[3][k].lo});
      hi[k] = std::max({corners[0][k].hi, corners[1][k].hi, corners[2][k].hi, corners[3][k].hi});
      centre[k] = 0.5 * (lo[k] + hi[k]);
    }
    // B^2: the smallest max-corner squared distance among a few vertices near the centre.
    double b2 = INFINITY;
    for (double r = grid_.spacing(); !std::isfinite(b2) && r < 1e300; r *= 2) {
      grid_.visit({centre[0] - r, centre[1] - r, centre[2] - r}, {centre[0] + r, centre[1] + r, centre[2] + r},
                  [&](std::uint32_t u) {
                    double worst = 0;
                    for (const Box& c : corners) worst = std::max(worst, squared_distance(c, approx_[u]).hi);
                    b2 = std::min(b2, worst);
                  });
    }
    const double b = round_up(std::sqrt(b2));
    std::vector<std::pair<double, std::uint32_t>> found;
    grid_.visit({lo[0] - b, lo[1] - b, lo[2] - b}, {hi[0] + b, hi[1] + b, hi[2] + b}, [&](std::uint32_t v) {
      Interval d2(0.0);
      for (int k = 0; k < 3; ++k) {
        const Box& p = approx_[v];
        const double gap = std::max({0.0, (Interval(lo[k]) - p[k]).lo, (p[k] - Interval(hi[k])).lo});
        d2 += square(Interval(gap));
      }
      if (d2.lo <= b2) found.push_back({d2.lo, v});
    });
    std::sort(found.begin(), found.end());
    std::vector<std::uint32_t> out;
    for (const auto& f : found) out.push_back(f.second);
    return out;
  }

  // Candidate i owns no point of tau when some other candidate is certainly closer at all
  // four corners (then everywhere in tau: the half-space nearer to it is convex), given the
  // squared distances from each candidate to each corner. The definition-level path asks
  // only the first 8 candidates; the cell such a test spares would be emptied by clipping,
  // so asking all of them changes no output.
  bool excluded(std::size_t i, const std::vector<std::array<Interval, 4>>& corner_d2) const {
    const std::size_t n = reach_ ? corner_d2.size() : std::min<std::size_t>(corner_d2.size(), 8);
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      bool closer = true;
      for (int c = 0; c < 4 && closer; ++c) closer = corner_d2[j][c].hi < corner_d2[i][c].lo;
      if (closer) return true;
    }
    return false;
  }

  // The finer test of the fast path: tau split into eight tetrahedra at its edge midpoints
  // (four at the corners, four around the diagonal m01 m23 of the middle octahedron);
  // candidate i owns no interior point of tau when each piece has some other candidate j
  // with f = |x - j|^2 - |x - i|^2 <= 0 at its four corners and < 0 at one of them (f is
  // affine: then f < 0 on the piece off a proper face, and the cell of i meets the piece
  // in no interior point; finitely many such pieces cover tau, so i's cell is empty, as
  // clipping would find). f < 0 is certified by intervals; f = 0 structurally, where
  // interval tests never succeed: at corner k of tau when i and j are both on the sphere
  // of ball k (both at distance r_k from its centre), at a midpoint when both are on the
  // spheres of the edge's two balls. Without the ties, no piece at a corner would ever be
  // covered for the many candidates on that corner's sphere.
  // `d2[j][p]` encloses the squared distance from point p (corners 0-3, then the midpoints
  // m01 m02 m03 m12 m13 m23) to candidate j; `spheres[j]` has bit k when candidate j lies
  // on the sphere of tau's ball k.
  struct PieceDistances {
    std::vector<std::array<Interval, 10>> d2;
    std::vector<unsigned> spheres;
  };
  static constexpr int kPieces[8][4] = {{0, 4, 5, 6}, {1, 4, 7, 8}, {2, 5, 7, 9}, {3, 6, 8, 9},
                                        {4, 9, 5, 6}, {4, 9, 6, 8}, {4, 9, 8, 7}, {4, 9, 7, 5}};
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  PieceDistances piece_distances(const PowerSimplex& tau, const std::array<Box, 4>& corners,
                                 const std::vector<std::uint32_t>& cand) const {
    std::array<Box, 10> points;
    for (int k = 0; k < 4; ++k) points[k] = corners[k];
    for (int e = 0; e < 6; ++e)
      for (int k = 0; k < 3; ++k) points[4 + e][k] = half(corners[kEdges[e][0]][k] + corners[kEdges[e][1]][k]);
    PieceDistances out;
    out.d2.resize(cand.size());
    out.spheres.assign(cand.size(), 0);
    for (std::size_t j = 0; j < cand.size(); ++j) {
      for (int p = 0; p < 10; ++p) out.d2[j][p] = squared_distance(points[p], approx_[cand[j]]);
      for (int k = 0; k < 4; ++k)
        if (contains(boundary_[cand[j]].balls, tau.balls[k])) out.spheres[j] |= 1u << k;
    }
    return out;
  }
  bool excluded_by_pieces(std::size_t i, const PieceDistances& pd) const {
    for (const auto& piece : kPieces) {
      bool covered = false;
      for (std::size_t j = 0; j < pd.d2.size() && !covered; ++j) {
        if (j == i) continue;
        const unsigned both = pd.spheres[i] & pd.spheres[j];
        bool strict = false;
        covered = true;
        for (int q = 0; q < 4 && covered; ++q) {
          const int p = piece[q];
          if (pd.d2[j][p].hi < pd.d2[i][p].lo) {
            strict = true;
            continue;
          }
          const unsigned need = p < 4 ? 1u << p : (1u << kEdges[p - 4][0]) | (1u << kEdges[p - 4][1]);
          covered = (both & need) == need;
        }
        covered = covered && strict;
      }
      if (!covered) return false;
    }
    return true;
  }

  void process_tetrahedron(const PowerSimplex& tau) {
    ++out_.tetrahedra;
    PlaneSet planes;
    info_.clear();
    const ExactPoint3& first = balls_.centers[tau.balls[0]];
    origin_ = {first.x.get_d(), first.y.get_d(), first.z.get_d()};
    const ConvexCell tet = tetrahedron_cell(planes, tau);
    planes.set_structural_zero([this](std::uint32_t p, const CellVertex& x) {
      if (!info_[p].bisector) return false;
      const Feature f = smallest_face(x);
      return structural(f.balls.data(), f.size, info_[p].v, info_[p].u);
    });
    std::array<Box, 4> corners;
    for (int k = 0; k < 4; ++k) corners[k] = enclose_point(balls_.centers[tau.balls[k]]);
    const std::vector<std::uint32_t> cand = candidates(corners);
    out_.candidates += cand.size();
    std::vector<std::array<Interval, 4>> corner_d2(cand.size());
    for (std::size_t i = 0; i < cand.size(); ++i)
      for (int c = 0; c < 4; ++c) corner_d2[i][c] = squared_distance(corners[c], approx_[cand[i]]);
    struct Neighbour {
      double mid, lo;  // |u - v|^2
      std::uint32_t u;
      bool operator<(const Neighbour& o) const { return mid < o.mid || (mid == o.mid && u < o.u); }
    };
    std::vector<Neighbour> order;
    const PieceDistances pieces = reach_ ? piece_distances(tau, corners, cand) : PieceDistances{};
    for (std::size_t i = 0; i < cand.size(); ++i) {
      const std::uint32_t v = cand[i];
      if (excluded(i, corner_d2) || (reach_ && excluded_by_pieces(i, pieces))) continue;
      ++out_.cells_clipped;
      order.clear();
      for (std::uint32_t u : cand)
        if (u != v) {
          const Interval d = squared_distance(approx_[u], approx_[v]);
          order.push_back({d.mid(), d.lo, u});
        }
      // Nearest first; a heap, since most cells are emptied after a few clips.
      auto later = [](const Neighbour& a, const Neighbour& b) { return b < a; };
      std::make_heap(order.begin(), order.end(), later);
      ConvexCell cell = tet;
      Reach reach = reach_ ? reach_of(cell, v) : Reach{};
      for (auto end = order.end(); end != order.begin(); --end) {
        std::pop_heap(order.begin(), end, later);
        const auto [d, d_lo, u] = *(end - 1);
        if (d_lo > reach.squared || (reach_ && beyond_ball(cell, &reach, v, u))) {
          ++out_.beyond_reach;
          continue;
        }
        ++out_.clips;
        const ConvexCell::Clip c = cell.clip(bisector(planes, v, u));
        if (c == ConvexCell::Clip::Emptied) break;
        if (c == ConvexCell::Clip::Cut && reach_) reach = reach_of(cell, v);
      }
      record_faces(cell, planes, v);
    }
    out_.stats.merge(planes.stats);
  }

  // Two certified reasons why the bisector of boundary vertices v and u cannot touch the
  // current cell of v (every point of it strictly nearer to v, so the clip would change
  // nothing, not even a support): (1) `squared` = (2 R)^2 rounded up, R the largest
  // distance from v to a vertex of the cell: |u - v|^2 > (2 R)^2 gives, for x in the cell,
  // |x - u| >= |u - v| - |x - v| > R >= |x - v|; (2) a ball B(m, r) around the cell lies
  // strictly on v's side: for x in it, |x - u|^2 - |x - v|^2 = (v - u) . (2 x - u - v)
  // >= (v - u) . (2 m - u - v) - 2 r |u - v| > 0. The ball is centred at the middle of the
  // cell's bounding box, so (2) holds for most far candidates that (1) keeps.
  struct Reach {
    double squared = INFINITY;
    bool ball = false;  // centre and radius computed (on first need, after each cut)
    Box centre;         // m, global coordinates
    double radius = INFINITY;
  };
  Reach reach_of(const ConvexCell& cell, std::uint32_t v) const {
    Box local;
    for (int k = 0; k < 3; ++k) local[k] = approx_[v][k] - Interval(origin_[k]);
    double r2 = 0;
    for (const CellFace& f : cell.faces())
      for (std::uint32_t x : f.vertices) r2 = std::max(r2, squared_distance(cell.vertex(x).approx, local).hi);
    Reach r;
    r.squared = std::isfinite(r2) ? 4 * r2 : INFINITY;  // x 4 is exact
    return r;
  }
  void bounding_ball(const ConvexCell& cell, Reach* r) const {
    r->ball = true;
    std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const CellFace& f : cell.faces())
      for (std::uint32_t x : f.vertices)
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], cell.vertex(x).approx[k].lo);
          hi[k] = std::max(hi[k], cell.vertex(x).approx[k].hi);
        }
    Box m;
    for (int k = 0; k < 3; ++k) m[k] = Interval(0.5 * (lo[k] + hi[k]));
    double rho2 = 0;
    for (const CellFace& f : cell.faces())
      for (std::uint32_t x : f.vertices) rho2 = std::max(rho2, squared_distance(cell.vertex(x).approx, m).hi);
    if (!std::isfinite(rho2)) return;
    r->radius = sqrt(Interval(rho2)).hi;
    for (int k = 0; k < 3; ++k) r->centre[k] = m[k] + Interval(origin_[k]);
  }
  bool beyond_ball(const ConvexCell& cell, Reach* r, std::uint32_t v, std::uint32_t u) const {
    if (!r->ball) bounding_ball(cell, r);
    if (!std::isfinite(r->radius)) return false;
    const Box& a = approx_[v];
    const Box& b = approx_[u];
    Interval g(0.0), d2(0.0);
    for (int k = 0; k < 3; ++k) {
      const Interval e = a[k] - b[k];
      g += e * (Interval(2) * r->centre[k] - a[k] - b[k]);
      d2 += square(e);
    }
    const Interval margin = g - Interval(2) * Interval(r->radius) * sqrt(d2);
    return std::isfinite(margin.lo) && margin.lo > 0;
  }

  void record_faces(const ConvexCell& cell, PlaneSet& planes, std::uint32_t v) {
    for (const CellFace& f : cell.faces()) {
      auto b = std::find_if(f.planes.begin(), f.planes.end(), [&](std::uint32_t p) { return info_[p].bisector; });
      if (b == f.planes.end()) continue;
      TetAxisPolygon poly;
      poly.v = info_[*b].v;
      poly.u = info_[*b].u;
      poly.plane = std::make_shared<const CellPlane>(planes[*b]);
      for (std::uint32_t x : f.vertices) poly.vertices.push_back(global_vertex(cell.vertex(x), planes, v));
      out_.polygons.push_back(std::move(poly));
    }
  }

  std::uint32_t global_vertex(const CellVertex& x, PlaneSet& planes, std::uint32_t owner) {
    VertexKey key = key_of(x);
    for (;;) {
      auto it = ids_.find(key);
      if (it == ids_.end()) break;
      const Box global{x.approx[0] + origin_[0], x.approx[1] + origin_[1], x.approx[2] + origin_[2]};
      if (boxes_overlap(out_.vertices[it->second].point->approx(), global)) return it->second;
      ++key.collision;  // equal keys, certainly different points: a degenerate key
      ++out_.key_collisions;
    }
    TetAxisVertex g;
    g.feature = key.feature;
    const Box global{x.approx[0] + origin_[0], x.approx[1] + origin_[1], x.approx[2] + origin_[2]};
    if (x.exact)
      g.point = std::make_shared<LazyPoint3>(x.exact, global);
    else
      g.point = std::make_shared<LazyPoint3>(
          std::array<CellPlane, 3>{planes[x.defining[0]], planes[x.defining[1]], planes[x.defining[2]]}, global);
    g.nearest = owner;
    const auto id = static_cast<std::uint32_t>(out_.vertices.size());
    ids_.emplace(std::move(key), id);
    out_.vertices.push_back(std::move(g));
    return id;
  }

  // Points with different keys whose boxes overlap are compared exactly (degenerate input).
  void merge_coincident() {
    std::vector<std::uint32_t> order(out_.vertices.size()), parent(out_.vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    std::iota(parent.begin(), parent.end(), 0u);
    auto& vs = out_.vertices;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return vs[a].point->approx()[0].lo < vs[b].point->approx()[0].lo; });
    auto find = [&](std::uint32_t a) {
      while (parent[a] != a) a = parent[a] = parent[parent[a]];
      return a;
    };
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = i + 1; j < order.size() && vs[order[j]].point->approx()[0].lo <= vs[order[i]].point->approx()[0].hi; ++j) {
        const std::uint32_t a = find(order[i]), b = find(order[j]);
        if (a == b || !boxes_overlap(vs[order[i]].point->approx(), vs[order[j]].point->approx())) continue;
        if (!same_point(vs[order[i]].point->exact(), vs[order[j]].point->exact(), &out_.stats.number)) continue;
        // Keep the most specific feature (a ball centre over an edge point, ...).
        const bool a_first = !vs[a].feature.empty() && (vs[b].feature.empty() || vs[a].feature.size() <= vs[b].feature.size());
        parent[a_first ? b : a] = a_first ? a : b;
        ++out_.merged_by_position;
      }
    if (out_.merged_by_position == 0) return;
    std::vector<TetAxisPolygon> kept;
    for (TetAxisPolygon& p : out_.polygons) {
      std::vector<std::uint32_t> ring;
      for (std::uint32_t v : p.vertices) {
        const std::uint32_t r = find(v);
        if (ring.empty() || ring.back() != r) ring.push_back(r);
      }
      while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
      if (ring.size() < 3) continue;
      p.vertices = std::move(ring);
      kept.push_back(std::move(p));
    }
    out_.polygons = std::move(kept);
  }

  // A face between the cells of v and u is found from both cells, and a face on a
  // triangle shared by two tetrahedra from both; keep one of each.
  void drop_duplicate_polygons() {
    std::map<std::vector<std::uint32_t>, bool> seen;
    std::vector<TetAxisPolygon> kept;
    for (TetAxisPolygon& p : out_.polygons) {
      std::vector<std::uint32_t> s = p.vertices;
      std::sort(s.begin(), s.end());
      if (seen.emplace(std::move(s), true).second) kept.push_back(std::move(p));
    }
    out_.polygons = std::move(kept);
  }

  const BallSet& balls_;
  const AlphaComplex& k_;
  const std::vector<BoundaryVertex>& boundary_;
  std::vector<Box> approx_;  // the boundary vertices' enclosures, contiguous (the hot loops read them)
  PointGrid grid_;
  std::shared_ptr<const BisectorField> field_;
  bool reach_;
  std::vector<PlaneInfo> info_;  // per tetrahedron, indexed by plane id
  std::array<double, 3> origin_{0, 0, 0};  // per tetrahedron: local coordinates of the enclosures
  std::map<VertexKey, std::uint32_t> ids_;
  TetAxis out_;
};

}  // namespace

bool same_point(const HomogeneousPoint& a, const HomogeneousPoint& b, NumberStats* stats) {
  for (int k = 0; k < 3; ++k)
    if (sign(a.c[k] * b.c[3] - b.c[k] * a.c[3], stats) != 0) return false;
  return true;
}

TetAxis tet_axis(const BallSet& balls, const AlphaComplex& k, const std::vector<BoundaryVertex>& boundary,
                 const RadicalTable& table, bool reach) {
  if (boundary.empty()) return {};
  return Builder(balls, k, boundary, table, reach).run();
}

}  // namespace grassfire
