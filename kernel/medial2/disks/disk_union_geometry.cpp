// disk_union_geometry.cpp -- see disk_union_geometry.h.
#include "medial2/disks/disk_union_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "number/ball.h"
#include "number/multiquadratic.h"
#include "number/sqrt_field.h"

namespace grassfire {

namespace {

ExactSum rational(const mpq_class& q) { return ExactSum::rational(q); }

// q + c sqrt(s)
ExactSum with_root(const mpq_class& q, const mpq_class& c, const mpq_class& s) {
  ExactSum r = ExactSum::sqrt_of(s);
  r.scale(c);
  r += rational(q);
  return r;
}

// Tight enough that the graph's enclosures need no exact refinement.
bool tight(const Interval& x) {
  return x.radius() <= 1e-12 * std::max(1.0, std::fmax(std::fabs(x.lo), std::fabs(x.hi)));
}

Interval squared_distance(const IntervalPoint2& a, const IntervalPoint2& b) {
  return square(a.x - b.x) + square(a.y - b.y);
}

// Circumcentre of three interval points (nullopt when the orientation is not certified).
std::optional<IntervalPoint2> interval_circumcenter(const IntervalPoint2& a, const IntervalPoint2& b,
                                                    const IntervalPoint2& c) {
  const Interval bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const Interval d = Interval(2.0) * (bx * cy - by * cx);
  if (certified_sign(d) == kUndecided || certified_sign(d) == 0) return std::nullopt;
  const Interval b2 = square(bx) + square(by), c2 = square(cx) + square(cy);
  return IntervalPoint2{a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

BallPoint corner_ball(const UnionCorner& c) {
  const Ball root = sqrt(ball_of(c.sigma));
  return {ball_of(c.mx) + ball_of(c.vx) * root, ball_of(c.my) + ball_of(c.vy) * root};
}

// The second filter for Voronoi vertices: the circumcentre at 128 bits.
constexpr long kBallBits = 128;

Interval ball_distance(const BallPoint& p, const BallPoint& q) {
  return sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y)).to_interval();
}

BallPoint ball_circumcenter(const BallPoint& a, const BallPoint& b, const BallPoint& c) {
  const Ball bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const Ball d = Ball(2.0) * (bx * cy - by * cx);
  const Ball b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

}  // namespace

std::optional<UnionCorner> circle_crossing(const std::vector<Disk>& disks, std::uint32_t i, std::uint32_t j, int s,
                                           bool* tangent) {
  const Disk& di = disks[i];
  const Disk& dj = disks[j];
  const mpq_class dx = dj.x - di.x, dy = dj.y - di.y;
  const mpq_class D = dx * dx + dy * dy;
  if (tangent) *tangent = false;
  if (sgn(D) == 0) return std::nullopt;
  const mpq_class a = (D + di.r * di.r - dj.r * dj.r) / (2 * D);
  const mpq_class sigma = (di.r * di.r - a * a * D) / D;  // (half chord)^2 / D
  if (sgn(sigma) <= 0) {
    if (tangent) *tangent = sgn(sigma) == 0;
    return std::nullopt;
  }
  UnionCorner c;
  c.disk = {i, j};
  c.mx = di.x + a * dx;
  c.my = di.y + a * dy;
  c.vx = -s * dy;
  c.vy = s * dx;
  c.sigma = sigma;
  c.role = {s, -s};
  const Interval root = sqrt(enclose(sigma));
  c.approx = {enclose(c.mx) + enclose(c.vx) * root, enclose(c.my) + enclose(c.vy) * root};
  return c;
}

ExactSum corner_x(const UnionCorner& c) { return with_root(c.mx, c.vx, c.sigma); }
ExactSum corner_y(const UnionCorner& c) { return with_root(c.my, c.vy, c.sigma); }

int CornerPredicates::orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
  const IntervalPoint2 &pa = (*c_)[a].approx, &pb = (*c_)[b].approx, &pc = (*c_)[c].approx;
  const int quick = certified_sign((pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x));
  if (quick != kUndecided) {
    ++stats_.filter_decided;
    return quick;
  }
  const UnionCorner &ca = (*c_)[a], &cb = (*c_)[b], &cc = (*c_)[c];
  const ExactSum ax = corner_x(ca), ay = corner_y(ca);
  const ExactSum det =
      multiply(corner_x(cb) - ax, corner_y(cc) - ay) - multiply(corner_y(cb) - ay, corner_x(cc) - ax);
  return sign(det, &stats_);
}

int CornerPredicates::in_circle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
  const std::uint32_t ids[3] = {a, b, c};
  // Corners are exact intersections of their two circles: four corners on one common
  // circle are cocircular by construction (the centre of a circle with several arcs).
  for (std::uint32_t disk : (*c_)[d].disk) {
    auto on = [&](std::uint32_t k) { return (*c_)[k].disk[0] == disk || (*c_)[k].disk[1] == disk; };
    if (on(a) && on(b) && on(c)) {
      ++stats_.exact_zero;
      return 0;
    }
  }
  const IntervalPoint2& pd = (*c_)[d].approx;
  Interval m[3][3];
  for (int k = 0; k < 3; ++k) {
    const IntervalPoint2& p = (*c_)[ids[k]].approx;
    m[k][0] = p.x - pd.x;
    m[k][1] = p.y - pd.y;
    m[k][2] = square(m[k][0]) + square(m[k][1]);
  }
  auto det3 = [](auto& e) {
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  const int quick = certified_sign(det3(m));
  if (quick != kUndecided) {
    ++stats_.filter_decided;
    return quick;
  }
  const ExactSum dx = corner_x((*c_)[d]), dy = corner_y((*c_)[d]);
  ExactSum e[3][3];
  for (int k = 0; k < 3; ++k) {
    e[k][0] = corner_x((*c_)[ids[k]]) - dx;
    e[k][1] = corner_y((*c_)[ids[k]]) - dy;
    e[k][2] = multiply(e[k][0], e[k][0]) + multiply(e[k][1], e[k][1]);
  }
  auto m2 = [&](int r0, int c0, int r1, int c1) {
    return multiply(e[r0][c0], e[r1][c1]) - multiply(e[r0][c1], e[r1][c0]);
  };
  const ExactSum det = multiply(e[0][0], m2(1, 1, 2, 2)) - multiply(e[0][1], m2(1, 0, 2, 2)) +
                       multiply(e[0][2], m2(1, 0, 2, 1));
  return sign(det, &stats_);
}

int CornerPredicates::compare_x(std::uint32_t a, std::uint32_t b) const {
  const int quick = certified_sign((*c_)[a].approx.x - (*c_)[b].approx.x);
  if (quick != kUndecided) {
    ++stats_.filter_decided;
    return quick;
  }
  return sign(corner_x((*c_)[a]) - corner_x((*c_)[b]), &stats_);
}

int CornerPredicates::compare_y(std::uint32_t a, std::uint32_t b) const {
  const int quick = certified_sign((*c_)[a].approx.y - (*c_)[b].approx.y);
  if (quick != kUndecided) {
    ++stats_.filter_decided;
    return quick;
  }
  return sign(corner_y((*c_)[a]) - corner_y((*c_)[b]), &stats_);
}

int CornerPredicates::compare_angle(const Disk& disk, std::uint32_t a, std::uint32_t b) const {
  const IntervalPoint2 c{enclose(disk.x), enclose(disk.y)};
  const UnionCorner &ca = (*c_)[a], &cb = (*c_)[b];
  const IntervalPoint2 ua{ca.approx.x - c.x, ca.approx.y - c.y}, ub{cb.approx.x - c.x, cb.approx.y - c.y};
  auto decided = [&](const Interval& quick, const ExactSum& exact) {
    const int s = certified_sign(quick);
    if (s != kUndecided) {
      ++stats_.filter_decided;
      return s;
    }
    return sign(exact, &stats_);
  };
  // Half-plane of the direction (upper half, with +x, first), then the cross product.
  auto half = [&](const UnionCorner& p, const IntervalPoint2& u) {
    const int sy = decided(u.y, corner_y(p) - rational(disk.y));
    if (sy != 0) return sy > 0 ? 0 : 1;
    return decided(u.x, corner_x(p) - rational(disk.x)) > 0 ? 0 : 1;
  };
  const int ha = half(ca, ua), hb = half(cb, ub);
  if (ha != hb) return ha < hb ? -1 : 1;
  const ExactSum ax = corner_x(ca) - rational(disk.x), ay = corner_y(ca) - rational(disk.y);
  const ExactSum bx = corner_x(cb) - rational(disk.x), by = corner_y(cb) - rational(disk.y);
  return -decided(ua.x * ub.y - ua.y * ub.x, multiply(ax, by) - multiply(ay, bx));
}

DiskUnionGeometry::DiskUnionGeometry(DiskList disks, std::vector<UnionCorner> corners, std::vector<UnionArc> arcs,
                                     std::vector<UnionNodeData> nodes,
                                     std::vector<std::pair<std::uint32_t, std::uint32_t>> ends,
                                     std::vector<UnionEdgeData> edges)
    : disks_(std::move(disks)),
      corners_(std::move(corners)),
      arcs_(std::move(arcs)),
      nodes_(std::move(nodes)),
      ends_(std::move(ends)),
      edges_(std::move(edges)),
      positions_(nodes_.size()),
      squared_radii_(nodes_.size()),
      radii_(nodes_.size()),
      lengths_(edges_.size()) {}

void DiskUnionGeometry::solve_vertex(std::uint32_t node) const {
  // The circumcentre of three of its cocircular corners, in Q(sqrt sigma_a, sigma_b, sigma_c);
  // generators are adjoined in increasing order, so equal inputs give equal texts.
  const UnionNodeData& n = nodes_[node];
  const UnionCorner* k[3] = {&corners_[n.corners[0]], &corners_[n.corners[1]], &corners_[n.corners[2]]};
  std::vector<mpq_class> radicands = {k[0]->sigma, k[1]->sigma, k[2]->sigma};
  std::sort(radicands.begin(), radicands.end());
  QuadraticBasis basis;
  for (const mpq_class& s : radicands) basis.adjoin(s);
  auto coordinate = [&](const mpq_class& m, const mpq_class& v, const mpq_class& sigma) {
    QuadraticBasis::Root r = basis.adjoin(sigma);
    r.coef *= v;
    return Multiquadratic(basis, m) + Multiquadratic::root(basis, r);
  };
  std::vector<Multiquadratic> x, y;
  for (const UnionCorner* c : k) {
    x.push_back(coordinate(c->mx, c->vx, c->sigma));
    y.push_back(coordinate(c->my, c->vy, c->sigma));
  }
  const Multiquadratic bx = x[1] - x[0], by = y[1] - y[0], cx = x[2] - x[0], cy = y[2] - y[0];
  const Multiquadratic inv = (Multiquadratic(basis, 2) * (bx * cy - by * cx)).inverse();
  const Multiquadratic b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const Multiquadratic ox = (cy * b2 - by * c2) * inv, oy = (bx * c2 - cx * b2) * inv;  // o - corner 0
  positions_[node] = std::array<ExactSum, 2>{(x[0] + ox).to_exact_sum(), (y[0] + oy).to_exact_sum()};
  squared_radii_[node] = (ox * ox + oy * oy).to_exact_sum();
}

const std::array<ExactSum, 2>& DiskUnionGeometry::exact_position(std::uint32_t node) const {
  if (positions_[node]) return *positions_[node];
  const UnionNodeData& n = nodes_[node];
  if (n.kind == UnionNodeKind::Vertex) {
    solve_vertex(node);
  } else {
    const Disk& d = disks_.disks[n.disk];
    positions_[node] = std::array<ExactSum, 2>{rational(d.x), rational(d.y)};
  }
  return *positions_[node];
}

ExactSum DiskUnionGeometry::exact_squared_radius(std::uint32_t node) const {
  const UnionNodeData& n = nodes_[node];
  if (n.kind == UnionNodeKind::Center) {
    const mpq_class& r = disks_.disks[n.disk].r;
    return rational(r * r);
  }
  if (!squared_radii_[node]) solve_vertex(node);
  return *squared_radii_[node];
}

ExactSum DiskUnionGeometry::exact_radius(std::uint32_t node) const {
  if (!radii_[node]) {
    const UnionNodeData& n = nodes_[node];
    radii_[node] = n.kind == UnionNodeKind::Center ? rational(disks_.disks[n.disk].r)
                                                   : root_of_sum(exact_squared_radius(node));
  }
  return *radii_[node];
}

ExactSum DiskUnionGeometry::exact_length(std::uint32_t edge) const {
  if (!lengths_[edge]) {
    const std::array<ExactSum, 2>& p = exact_position(ends_[edge].first);
    const std::array<ExactSum, 2>& q = exact_position(ends_[edge].second);
    const ExactSum dx = p[0] - q[0], dy = p[1] - q[1];
    lengths_[edge] = root_of_sum(multiply(dx, dx) + multiply(dy, dy));
  }
  return *lengths_[edge];
}

BallPoint DiskUnionGeometry::ball_position(std::uint32_t node) const {
  const UnionNodeData& n = nodes_[node];
  if (n.kind == UnionNodeKind::Center) {
    const Disk& d = disks_.disks[n.disk];
    return {ball_of(d.x), ball_of(d.y)};
  }
  return ball_circumcenter(corner_ball(corners_[n.corners[0]]), corner_ball(corners_[n.corners[1]]),
                           corner_ball(corners_[n.corners[2]]));
}

// Each enclosure: double intervals, then 128-bit balls, then the exact value.
IntervalPoint2 DiskUnionGeometry::position_enclosure(std::uint32_t node) const {
  const UnionNodeData& n = nodes_[node];
  if (n.kind == UnionNodeKind::Center) {
    const Disk& d = disks_.disks[n.disk];
    return {enclose(d.x), enclose(d.y)};
  }
  const std::optional<IntervalPoint2> quick = interval_circumcenter(
      corners_[n.corners[0]].approx, corners_[n.corners[1]].approx, corners_[n.corners[2]].approx);
  if (quick && tight(quick->x) && tight(quick->y)) return *quick;
  BallPrecision guard(kBallBits);
  const BallPoint o = ball_position(node);
  const IntervalPoint2 refined{o.x.to_interval(), o.y.to_interval()};
  if (tight(refined.x) && tight(refined.y)) return refined;
  const std::array<ExactSum, 2>& p = exact_position(node);
  return {p[0].approx(), p[1].approx()};
}

Interval DiskUnionGeometry::radius_enclosure(std::uint32_t node) const {
  const UnionNodeData& n = nodes_[node];
  if (n.kind == UnionNodeKind::Center) return enclose(disks_.disks[n.disk].r);
  const Interval quick = sqrt(squared_distance(position_enclosure(node), corners_[n.corners[0]].approx));
  if (tight(quick)) return quick;
  BallPrecision guard(kBallBits);
  const Interval refined = ball_distance(corner_ball(corners_[n.corners[0]]), ball_position(node));
  if (tight(refined)) return refined;
  return exact_radius(node).approx();
}

Interval DiskUnionGeometry::length_enclosure(std::uint32_t edge) const {
  const Interval quick =
      sqrt(squared_distance(position_enclosure(ends_[edge].first), position_enclosure(ends_[edge].second)));
  if (tight(quick)) return quick;
  BallPrecision guard(kBallBits);
  const Interval refined = ball_distance(ball_position(ends_[edge].first), ball_position(ends_[edge].second));
  if (tight(refined)) return refined;
  return exact_length(edge).approx();
}

}  // namespace grassfire
