// mesh_solid.cpp -- see mesh_solid.h.
#include "medial3/mesh/mesh_solid.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "medial3/mesh/mesh_checks.h"
#include "geometry3/exact_predicates3.h"
#include "number/exact_sum.h"

namespace grassfire {

namespace {

using P3 = std::array<double, 3>;

// Sign of the (y, z) orientation of a, b, q: (b.y - a.y)(q.z - a.z) - (b.z - a.z)(q.y - a.y),
// for q perturbed to (q.y + eps, q.z + eps^2): when the determinant is zero its sign is
// that of -(b.z - a.z) eps, then of (b.y - a.y) eps^2. Swapping a and b negates every term,
// so the two triangles of an edge see the perturbed point on opposite sides.
template <class Exact>
int perturbed_side(const P3& a, const P3& b, const Interval& qy, const Interval& qz, Exact& exact) {
  const Interval d = (Interval(b[1]) - Interval(a[1])) * (qz - Interval(a[2])) -
                     (Interval(b[2]) - Interval(a[2])) * (qy - Interval(a[1]));
  int s = certified_sign(d);
  if (s == kUndecided || s == 0) {
    const ExactPoint3& q = exact();
    s = sgn((mpq_class(b[1]) - a[1]) * (q.z - a[2]) - (mpq_class(b[2]) - a[2]) * (q.y - a[1]));
  }
  if (s != 0) return s;
  if (b[2] != a[2]) return b[2] > a[2] ? -1 : 1;
  if (b[1] != a[1]) return b[1] > a[1] ? 1 : -1;
  return 0;
}

// Sign of det[b - a, c - a, q - a].
template <class Exact>
int side_of_plane(const std::array<P3, 3>& t, const std::array<Interval, 3>& q, Exact& exact) {
  std::array<Interval, 3> u, v, w;
  for (int k = 0; k < 3; ++k) {
    u[k] = Interval(t[1][k]) - Interval(t[0][k]);
    v[k] = Interval(t[2][k]) - Interval(t[0][k]);
    w[k] = q[k] - Interval(t[0][k]);
  }
  const Interval det = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                       w[2] * (u[0] * v[1] - u[1] * v[0]);
  const int s = certified_sign(det);
  if (s != kUndecided) return s;
  const ExactPoint3 a = exact_point(t[0]);
  return orientation(a, exact_point(t[1]), exact_point(t[2]), exact());
}

// A point of the plane of triangle t lies in the closed triangle: in a coordinate
// projection along which the triangle is not degenerate, the three orientations of q
// against the edges do not have opposite signs.
bool in_closed_triangle(const std::array<P3, 3>& t, const ExactPoint3& q) {
  const ExactPoint3 a = exact_point(t[0]), b = exact_point(t[1]), c = exact_point(t[2]);
  const ExactPoint3 n = cross(b - a, c - a);
  const int drop = sgn(n.x) != 0 ? 0 : sgn(n.y) != 0 ? 1 : 2;
  auto coord = [&](const ExactPoint3& p, int k) -> const mpq_class& { return k == 0 ? p.x : k == 1 ? p.y : p.z; };
  const int i = (drop + 1) % 3, j = (drop + 2) % 3;
  auto orient = [&](const ExactPoint3& u, const ExactPoint3& v) {
    return sgn((coord(v, i) - coord(u, i)) * (coord(q, j) - coord(u, j)) -
               (coord(v, j) - coord(u, j)) * (coord(q, i) - coord(u, i)));
  };
  const int s0 = orient(a, b), s1 = orient(b, c), s2 = orient(c, a);
  return !((s0 > 0 || s1 > 0 || s2 > 0) && (s0 < 0 || s1 < 0 || s2 < 0));
}

// The exact point of a query, made on first use.
class LazyQuery {
 public:
  LazyQuery(const std::function<ExactPoint3()>& make, std::uint64_t* count) : make_(make), count_(count) {}
  const ExactPoint3& operator()() {
    if (!q_) {
      q_ = make_();
      ++*count_;
    }
    return *q_;
  }

 private:
  const std::function<ExactPoint3()>& make_;
  std::uint64_t* count_;
  std::optional<ExactPoint3> q_;
};

long grid_index(double x, double x0, double h, long n) {
  const double i = std::floor((x - x0) / h);
  if (!(i >= 0)) return 0;
  return static_cast<long>(std::min(i, static_cast<double>(n - 1)));
}

}  // namespace

SolidLocator::SolidLocator(const TriangleMesh3& mesh, std::vector<std::uint32_t> triangles) {
  if (triangles.empty()) {
    triangles.resize(mesh.triangles.size());
    std::iota(triangles.begin(), triangles.end(), 0u);
  }
  lo_ = {INFINITY, INFINITY, INFINITY};
  hi_ = {-INFINITY, -INFINITY, -INFINITY};
  for (std::uint32_t t : triangles) {
    Tri tri;
    for (int c = 0; c < 3; ++c) tri.v[c] = mesh.vertices[mesh.triangles[t][c]];
    for (int k = 0; k < 3; ++k) {
      tri.lo[k] = std::min({tri.v[0][k], tri.v[1][k], tri.v[2][k]});
      tri.hi[k] = std::max({tri.v[0][k], tri.v[1][k], tri.v[2][k]});
      lo_[k] = std::min(lo_[k], tri.lo[k]);
      hi_[k] = std::max(hi_[k], tri.hi[k]);
    }
    tris_.push_back(tri);
  }
  if (tris_.empty()) return;
  const double ey = std::max(hi_[1] - lo_[1], 1e-300), ez = std::max(hi_[2] - lo_[2], 1e-300);
  const double cells = std::max(1.0, static_cast<double>(tris_.size()));
  const double h = std::sqrt(ey * ez / cells);
  ny_ = std::clamp(static_cast<long>(ey / h), 1L, 4096L);
  nz_ = std::clamp(static_cast<long>(ez / h), 1L, 4096L);
  y0_ = lo_[1];
  z0_ = lo_[2];
  hy_ = ey / static_cast<double>(ny_);
  hz_ = ez / static_cast<double>(nz_);
  cells_.assign(static_cast<std::size_t>(ny_ * nz_), {});
  for (std::uint32_t i = 0; i < tris_.size(); ++i) {
    const Tri& t = tris_[i];
    for (long y = grid_index(t.lo[1], y0_, hy_, ny_); y <= grid_index(t.hi[1], y0_, hy_, ny_); ++y)
      for (long z = grid_index(t.lo[2], z0_, hz_, nz_); z <= grid_index(t.hi[2], z0_, hz_, nz_); ++z)
        cells_[static_cast<std::size_t>(y * nz_ + z)].push_back(i);
  }
}

// The same rounded map from coordinate to cell is used for triangles and queries; it is
// monotone, so a triangle whose range meets the query's range shares a visited cell.
template <class F>
void SolidLocator::visit_cells(const Interval& y, const Interval& z, F f) const {
  const long y1 = grid_index(y.lo, y0_, hy_, ny_), y2 = grid_index(y.hi, y0_, hy_, ny_);
  const long z1 = grid_index(z.lo, z0_, hz_, nz_), z2 = grid_index(z.hi, z0_, hz_, nz_);
  if (y1 == y2 && z1 == z2) {
    for (std::uint32_t t : cells_[static_cast<std::size_t>(y1 * nz_ + z1)]) f(t);
    return;
  }
  std::vector<std::uint32_t> seen;
  for (long a = y1; a <= y2; ++a)
    for (long b = z1; b <= z2; ++b) {
      const auto& c = cells_[static_cast<std::size_t>(a * nz_ + b)];
      seen.insert(seen.end(), c.begin(), c.end());
    }
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  for (std::uint32_t t : seen) f(t);
}

int SolidLocator::locate(const ExactPoint3& p) const {
  return locate({enclose(p.x), enclose(p.y), enclose(p.z)}, [&p] { return p; });
}

int SolidLocator::locate(const std::array<Interval, 3>& box, const std::function<ExactPoint3()>& exact) const {
  ++stats_.queries;
  for (int k = 0; k < 3; ++k)
    if (box[k].lo > hi_[k] || box[k].hi < lo_[k]) return -1;
  return locate_in(box, exact);
}

int SolidLocator::locate_in(const std::array<Interval, 3>& box, const std::function<ExactPoint3()>& exact) const {
  LazyQuery point(exact, &stats_.exact_tests);
  bool odd = false, on_boundary = false;
  visit_cells(box[1], box[2], [&](std::uint32_t i) {
    const Tri& t = tris_[i];
    if (on_boundary || box[0].lo > t.hi[0]) return;
    if (box[1].lo > t.hi[1] || box[1].hi < t.lo[1] || box[2].lo > t.hi[2] || box[2].hi < t.lo[2]) return;
    ++stats_.triangle_tests;
    const int s0 = perturbed_side(t.v[0], t.v[1], box[1], box[2], point);
    const int s1 = perturbed_side(t.v[1], t.v[2], box[1], box[2], point);
    const int s2 = perturbed_side(t.v[2], t.v[0], box[1], box[2], point);
    const bool crossing = s0 != 0 && s0 == s1 && s1 == s2;
    const bool may_touch = box[0].hi >= t.lo[0];
    if (!crossing && !may_touch) return;
    if (crossing && !may_touch) {
      odd = !odd;  // the whole triangle lies beyond the point
      return;
    }
    const int d = side_of_plane(t.v, box, point);
    if (d == 0 && in_closed_triangle(t.v, point())) {
      on_boundary = true;
      return;
    }
    // The ray q + s e_x meets the plane at s = -det / n_x, and sign(n_x) = s0.
    if (crossing && -d == s0) odd = !odd;
  });
  if (on_boundary) return 0;
  return odd ? 1 : -1;
}

namespace {

std::vector<std::vector<std::uint32_t>> shells_of(const TriangleMesh3& mesh) {
  std::vector<std::uint32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : mesh.triangles) {
    parent[find(t[0])] = find(t[1]);
    parent[find(t[1])] = find(t[2]);
  }
  std::vector<std::uint32_t> shell_of(mesh.vertices.size(), UINT32_MAX);
  std::vector<std::vector<std::uint32_t>> shells;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t r = find(mesh.triangles[t][0]);
    if (shell_of[r] == UINT32_MAX) {
      shell_of[r] = static_cast<std::uint32_t>(shells.size());
      shells.emplace_back();
    }
    shells[shell_of[r]].push_back(t);
  }
  return shells;
}

}  // namespace

SolidTopology solid_topology(const TriangleMesh3& mesh) {
  SolidTopology out;
  for (std::vector<std::uint32_t>& tris : shells_of(mesh)) {
    MeshShell s;
    std::vector<std::uint32_t> vs;
    for (std::uint32_t t : tris) vs.insert(vs.end(), mesh.triangles[t].begin(), mesh.triangles[t].end());
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    s.vertices = vs.size();
    s.edges = 3 * tris.size() / 2;  // closed 2-manifold: every edge in two triangles
    const long chi = static_cast<long>(s.vertices) - static_cast<long>(s.edges) + static_cast<long>(tris.size());
    if (chi > 2 || chi % 2 != 0)
      throw std::invalid_argument(mesh.source + ": a shell has Euler characteristic " + std::to_string(chi) +
                                  " (not a closed orientable surface)");
    s.genus = (2 - chi) / 2;
    s.triangles = std::move(tris);
    out.shells.push_back(std::move(s));
  }
  std::vector<SolidLocator> locators;
  for (const MeshShell& s : out.shells) locators.emplace_back(mesh, s.triangles);
  for (std::size_t a = 0; a < out.shells.size(); ++a) {
    const ExactPoint3 p = exact_point(mesh.vertices[mesh.triangles[out.shells[a].triangles[0]][0]]);
    for (std::size_t b = 0; b < out.shells.size(); ++b) {
      if (a == b) continue;
      const int where = locators[b].locate(p);
      if (where == 0)
        throw std::invalid_argument(mesh.source + ": two shells touch (a vertex of shell " + std::to_string(a) +
                                    " lies on shell " + std::to_string(b) + ")");
      out.shells[a].depth += where > 0;
    }
  }
  for (const MeshShell& s : out.shells) {
    (s.depth % 2 == 0 ? out.betti.b0 : out.betti.b2) += 1;
    out.betti.b1 += s.genus;
  }
  return out;
}

}  // namespace grassfire
