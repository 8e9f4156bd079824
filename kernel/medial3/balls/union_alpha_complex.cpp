// union_alpha_complex.cpp -- see union_alpha_complex.h.
#include "medial3/balls/union_alpha_complex.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <random>
#include <string>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "geometry3/exact_predicates3.h"
#include "number/exact_sum.h"
#include "number/interval.h"

namespace grassfire {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::optional<mpq_class> rational_root(const mpq_class& q) {
  mpz_class n = q.get_num(), d = q.get_den();
  if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t())) return std::nullopt;
  mpz_sqrt(n.get_mpz_t(), n.get_mpz_t());
  mpz_sqrt(d.get_mpz_t(), d.get_mpz_t());
  return make_rational(n, d);
}

}  // namespace

mpq_class power(const BallSet& b, std::uint32_t i, const ExactPoint3& x) {
  return squared_distance(x, b.centers[i]) - b.squared_radii[i];
}

namespace {
// An enclosure of a value whose double x came from get_d() (truncation, < 1 ulp) or from
// std::sqrt of such a double (< 2 ulps): x widened by 2^-50 |x| (8 ulps) and the
// smallest normal double.
Interval around(double x) {
  const double r = std::fabs(x) * 0x1p-50 + std::numeric_limits<double>::min();
  const double inf = std::numeric_limits<double>::infinity();
  Interval i;  // one ulp outwards covers the rounding of x -+ r
  i.lo = std::nextafter(x - r, -inf);
  i.hi = std::nextafter(x + r, inf);
  return i;
}
}  // namespace

bool interior_of_union(const BallSet& b, const ExactPoint3& p) {
  const Interval px = enclose(p.x), py = enclose(p.y), pz = enclose(p.z);
  const bool approximated = b.approx_centers.size() == b.centers.size() && b.approx_radii.size() == b.centers.size();
  std::vector<ExactPoint3> q;
  for (std::uint32_t i = 0; i < b.centers.size(); ++i) {
    if (!approximated) {
      if (sgn(power(b, i, p)) == 0) q.push_back(b.centers[i] - p);
      continue;
    }
    // Filter: balls whose sphere certainly misses p need no exact power.
    const auto& c = b.approx_centers[i];
    const Interval r = around(b.approx_radii[i]);
    const Interval pow = square(px - around(c[0])) + square(py - around(c[1])) + square(pz - around(c[2])) - square(r);
    if (pow.lo > 0 || pow.hi < 0) continue;
    if (sgn(power(b, i, p)) == 0) q.push_back(b.centers[i] - p);
  }
  bool full_rank = false;
  for (std::size_t i = 0; i < q.size() && !full_rank; ++i)
    for (std::size_t j = i + 1; j < q.size() && !full_rank; ++j)
      for (std::size_t k = j + 1; k < q.size() && !full_rank; ++k) full_rank = sgn(dot(cross(q[i], q[j]), q[k])) != 0;
  if (!full_rank) return false;
  // Not surrounded iff the polar cone {d : d . q <= 0 for all q} has an extreme ray, which
  // is orthogonal to two of the q (the cone is pointed since the q span R^3).
  for (std::size_t i = 0; i < q.size(); ++i)
    for (std::size_t j = i + 1; j < q.size(); ++j) {
      const ExactPoint3 d = cross(q[i], q[j]);
      if (is_zero(d)) continue;
      bool all_nonpositive = true, all_nonnegative = true;
      for (const ExactPoint3& x : q) {
        const int s = sgn(dot(d, x));
        all_nonpositive &= s <= 0;
        all_nonnegative &= s >= 0;
      }
      if (all_nonpositive || all_nonnegative) return false;
    }
  return true;
}

int sign_with_root(const mpq_class& a, int side, const mpq_class& b, const mpq_class& s) {
  const int sa = sgn(a), sb = side * sgn(b);
  if (sgn(s) == 0 || sb == 0) return sa;
  if (sa == 0 || sa == sb) return sb;
  const int d = sgn(a * a - b * b * s);  // opposite signs: the larger magnitude wins
  return d == 0 ? 0 : (d > 0 ? sa : sb);
}

AlphaComplex::AlphaComplex(const BallSet& balls, const RegularTriangulation& rt)
    : balls_(&balls), ball_count_(balls.centers.size()), dimension_(rt.dimension) {
  auto canonical = [](const mpq_class& q) {
    if (sgn(q.get_den()) <= 0) return false;
    mpz_class g;
    mpz_gcd(g.get_mpz_t(), mpq_numref(q.get_mpq_t()), mpq_denref(q.get_mpq_t()));
    return g == 1;
  };
  for (std::size_t i = 0; i < ball_count_; ++i) {
    approx_ball_.push_back({enclose(balls.centers[i].x), enclose(balls.centers[i].y), enclose(balls.centers[i].z)});
    approx_weight_.push_back(enclose(balls.squared_radii[i]));
    const ExactPoint3& c = balls.centers[i];
    canonical_ball_.push_back(canonical(c.x) && canonical(c.y) && canonical(c.z) && canonical(balls.squared_radii[i]));
  }
  const std::size_t total = rt.vertices.size() + rt.edges.size() + rt.triangles.size() + rt.tetrahedra.size();
  simplices_.reserve(total);
  add_simplices(rt);
  hidden_ = ball_count_ - rt.vertices.size();
  // The cofaces of each face, in increasing simplex order: every (facet, simplex) pair of
  // dimension d, sorted, walked against the sorted faces of dimension d - 1.
  std::vector<std::pair<std::array<std::uint32_t, 4>, std::uint32_t>> facets;
  for (int dim = 1; dim <= 3; ++dim) {
    facets.clear();
    facets.reserve(by_dim_[dim].size() * static_cast<std::size_t>(dim + 1));
    for (std::uint32_t s : by_dim_[dim]) {
      const PowerSimplex& p = simplices_[s];
      for (int drop = 0; drop <= dim; ++drop) {
        std::array<std::uint32_t, 4> face{kNone, kNone, kNone, kNone};
        for (int k = 0, m = 0; k <= dim; ++k)
          if (k != drop) face[m++] = p.balls[k];
        facets.push_back({face, s});
      }
    }
    std::sort(facets.begin(), facets.end());
    const auto& faces = index_[dim - 1];
    std::size_t f = 0;
    for (std::size_t i = 0; i < facets.size();) {
      while (f < faces.size() && faces[f].first < facets[i].first) ++f;
      if (f == faces.size() || faces[f].first != facets[i].first)
        throw std::logic_error("union alpha complex: a face is missing from the triangulation");
      std::size_t j = i;
      while (j < facets.size() && facets[j].first == facets[i].first) ++j;
      std::vector<std::uint32_t>& cofaces = simplices_[faces[f].second].cofaces;
      cofaces.reserve(j - i);
      for (; i < j; ++i) cofaces.push_back(facets[i].second);
    }
  }
  approximate_centres();
  compute_rho();
}

// The simplices of each dimension in the triangulation's order, a repeated one kept once
// (its first occurrence), and the sorted index of each dimension.
void AlphaComplex::add_simplices(const RegularTriangulation& rt) {
  std::array<std::vector<std::array<std::uint32_t, 4>>, 4> lists;
  for (std::uint32_t v : rt.vertices) lists[0].push_back({v, kNone, kNone, kNone});
  for (const auto& e : rt.edges) lists[1].push_back({e[0], e[1], kNone, kNone});
  for (const auto& t : rt.triangles) lists[2].push_back({t[0], t[1], t[2], kNone});
  for (const auto& t : rt.tetrahedra) lists[3].push_back(t);
  for (int dim = 0; dim <= 3; ++dim) {
    std::vector<std::pair<std::array<std::uint32_t, 4>, std::uint32_t>> order;  // (balls, position)
    order.reserve(lists[dim].size());
    for (std::uint32_t i = 0; i < lists[dim].size(); ++i) {
      std::sort(lists[dim][i].begin(), lists[dim][i].begin() + dim + 1);
      order.push_back({lists[dim][i], i});
    }
    std::sort(order.begin(), order.end());
    std::vector<bool> repeated(lists[dim].size(), false);
    for (std::size_t i = 1; i < order.size(); ++i)
      if (order[i].first == order[i - 1].first) repeated[order[i].second] = true;
    std::vector<std::uint32_t> id_of(lists[dim].size(), kNone);
    for (std::uint32_t i = 0; i < lists[dim].size(); ++i) {
      if (repeated[i]) continue;
      PowerSimplex p;
      p.balls = lists[dim][i];
      p.dim = dim;
      id_of[i] = static_cast<std::uint32_t>(simplices_.size());
      simplices_.push_back(std::move(p));
      by_dim_[dim].push_back(id_of[i]);
    }
    auto& index = index_[dim];
    index.reserve(by_dim_[dim].size());
    for (const auto& [balls, i] : order)
      if (!repeated[i]) index.push_back({balls, id_of[i]});
  }
}

std::uint32_t AlphaComplex::find(const std::array<std::uint32_t, 4>& balls, int dim) const {
  std::array<std::uint32_t, 4> key{kNone, kNone, kNone, kNone};
  std::copy(balls.begin(), balls.begin() + dim + 1, key.begin());
  const auto& index = index_[dim];
  auto it = std::lower_bound(index.begin(), index.end(), key,
                             [](const std::pair<std::array<std::uint32_t, 4>, std::uint32_t>& e,
                                const std::array<std::uint32_t, 4>& k) { return e.first < k; });
  return it == index.end() || it->first != key ? kNone : it->second;
}

// z = c_0 + sum_l lambda_l d_l with 2 (z - c_0) . d_m = |d_m|^2 + w_0 - w_m (equal powers),
// solved by Cramer's rule in T (Interval: the filter; the exact values come from
// integer_power_centre below, or from T = mpq_class for rationals not in canonical form);
// false when a pivot is not certainly nonzero.
template <class T, class P, class W>
bool solve_power_centre(const std::array<const P*, 4>& c, const std::array<const W*, 4>& w, int dim, std::array<T, 3>* z,
                        T* power) {
  std::array<std::array<T, 3>, 3> d;
  for (int m = 0; m < dim; ++m)
    for (int k = 0; k < 3; ++k) d[m][k] = T((*c[m + 1])[k]) - T((*c[0])[k]);
  auto dot = [](const std::array<T, 3>& a, const std::array<T, 3>& b) -> T { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  std::array<std::array<T, 3>, 3> g;
  std::array<T, 3> rhs;
  for (int l = 0; l < dim; ++l) {
    for (int m = 0; m < dim; ++m) g[l][m] = T(2) * dot(d[l], d[m]);
    rhs[l] = dot(d[l], d[l]) + T(*w[0]) - T(*w[l + 1]);
  }
  std::array<T, 3> lambda;
  auto nonzero = [](const T& x) {
    if constexpr (std::is_same_v<T, Interval>) return x.lo > 0 || x.hi < 0;
    else return sgn(x) != 0;
  };
  if (dim == 1) {
    if (!nonzero(g[0][0])) return false;
    lambda[0] = rhs[0] / g[0][0];
  } else if (dim == 2) {
    const T det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
    if (!nonzero(det)) return false;
    lambda[0] = (rhs[0] * g[1][1] - g[0][1] * rhs[1]) / det;
    lambda[1] = (g[0][0] * rhs[1] - rhs[0] * g[1][0]) / det;
  } else if (dim == 3) {
    auto det3 = [](const std::array<std::array<T, 3>, 3>& a) -> T {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const T det = det3(g);
    if (!nonzero(det)) return false;
    for (int k = 0; k < 3; ++k) {
      auto gk = g;
      for (int r = 0; r < 3; ++r) gk[r][k] = rhs[r];
      lambda[k] = det3(gk) / det;
    }
  }
  for (int k = 0; k < 3; ++k) {
    (*z)[k] = T((*c[0])[k]);
    for (int l = 0; l < dim; ++l) (*z)[k] = (*z)[k] + lambda[l] * d[l][k];
  }
  std::array<T, 3> r;
  for (int k = 0; k < 3; ++k) r[k] = (*z)[k] - T((*c[0])[k]);
  *power = dot(r, r) - T(*w[0]);
  return true;
}

namespace {

// The same exact power centre and power as solve_power_centre<mpq_class>, computed over
// the integers: centres scaled by the common denominator D of their coordinates, the
// weights' differences by a common denominator F, Cramer's rule in integers, and one
// canonicalisation per output value instead of one per rational operation (the gcds were
// most of the boundary vertices' time). false for a singular system, as there.
// With X_i = D c_i, e_l = X_{l+1} - X_0, G = (2 e_l . e_m), R_l = F (|e_l|^2 + D^2 (w_0 - w_{l+1})):
// lambda = G^-1 R / F, z = (X_0 + sum_l lambda_l e_l) / D, w = |z - c_0|^2 - w_0.
bool integer_power_centre(const std::array<const ExactPoint3*, 4>& c, const std::array<const mpq_class*, 4>& w, int dim,
                          std::array<mpq_class, 3>* z, mpq_class* power) {
  auto coord = [](const ExactPoint3& p, int k) -> const mpq_class& { return k == 0 ? p.x : k == 1 ? p.y : p.z; };
  mpz_class d = 1;
  for (int i = 0; i <= dim; ++i)
    for (int k = 0; k < 3; ++k) mpz_lcm(d.get_mpz_t(), d.get_mpz_t(), mpq_denref(coord(*c[i], k).get_mpq_t()));
  std::array<std::array<mpz_class, 3>, 4> x;
  for (int i = 0; i <= dim; ++i)
    for (int k = 0; k < 3; ++k) {
      const mpq_class& q = coord(*c[i], k);
      mpz_divexact(x[i][k].get_mpz_t(), d.get_mpz_t(), mpq_denref(q.get_mpq_t()));
      x[i][k] *= mpz_class(mpq_numref(q.get_mpq_t()));
    }
  std::array<std::array<mpz_class, 3>, 3> e;
  for (int l = 0; l < dim; ++l)
    for (int k = 0; k < 3; ++k) e[l][k] = x[l + 1][k] - x[0][k];
  auto dot = [](const std::array<mpz_class, 3>& a, const std::array<mpz_class, 3>& b) -> mpz_class {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  const mpz_class d2 = d * d;
  std::array<mpq_class, 3> q;
  mpz_class f = 1;
  for (int l = 0; l < dim; ++l) {
    q[l] = (*w[0] - *w[l + 1]) * mpq_class(d2);
    mpz_lcm(f.get_mpz_t(), f.get_mpz_t(), mpq_denref(q[l].get_mpq_t()));
  }
  std::array<std::array<mpz_class, 3>, 3> g;
  std::array<mpz_class, 3> r;
  for (int l = 0; l < dim; ++l) {
    for (int m = 0; m < dim; ++m) g[l][m] = 2 * dot(e[l], e[m]);
    mpz_class scaled;
    mpz_divexact(scaled.get_mpz_t(), f.get_mpz_t(), mpq_denref(q[l].get_mpq_t()));
    r[l] = f * dot(e[l], e[l]) + scaled * mpz_class(mpq_numref(q[l].get_mpq_t()));
  }
  mpz_class det;
  std::array<mpz_class, 3> n;  // lambda_l = n_l / (det f)
  if (dim == 1) {
    det = g[0][0];
    n[0] = r[0];
  } else if (dim == 2) {
    det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
    n[0] = r[0] * g[1][1] - g[0][1] * r[1];
    n[1] = g[0][0] * r[1] - r[0] * g[1][0];
  } else if (dim == 3) {
    auto det3 = [](const std::array<std::array<mpz_class, 3>, 3>& a) -> mpz_class {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    det = det3(g);
    for (int k = 0; k < 3; ++k) {
      auto gk = g;
      for (int row = 0; row < 3; ++row) gk[row][k] = r[row];
      n[k] = det3(gk);
    }
  }
  if (dim > 0 && sgn(det) == 0) return false;
  const mpz_class den = dim > 0 ? mpz_class(d * det * f) : d;
  std::array<mpz_class, 3> sum;  // sum_l n_l e_l: z - c_0 = sum / den
  for (int k = 0; k < 3; ++k) {
    sum[k] = 0;
    for (int l = 0; l < dim; ++l) sum[k] += n[l] * e[l][k];
    mpq_class value(x[0][k] * (dim > 0 ? mpz_class(det * f) : mpz_class(1)) + sum[k], den);
    value.canonicalize();
    (*z)[k] = std::move(value);
  }
  mpq_class offset(dot(sum, sum), den * den);
  offset.canonicalize();
  *power = offset - *w[0];
  return true;
}

}  // namespace

const PowerSimplex& AlphaComplex::exact(std::uint32_t s) const {
  PowerSimplex& p = simplices_[s];
  if (p.exact) return p;
  std::array<const ExactPoint3*, 4> cp{};
  std::array<const mpq_class*, 4> wp{};
  for (int i = 0; i <= p.dim; ++i) {
    cp[i] = &balls_->centers[p.balls[i]];
    wp[i] = &balls_->squared_radii[p.balls[i]];
  }
  std::array<mpq_class, 3> z;
  bool canonical = true;
  for (int i = 0; i <= p.dim; ++i) canonical = canonical && canonical_ball_[p.balls[i]];
  bool solved = false;
  if (canonical) {
    solved = integer_power_centre(cp, wp, p.dim, &z, &p.power);
  } else {  // GMP's rational arithmetic keeps such inputs' form; so does the output
    std::array<std::array<mpq_class, 3>, 4> c;
    std::array<const std::array<mpq_class, 3>*, 4> rows{};
    for (int i = 0; i <= p.dim; ++i) {
      c[i] = {cp[i]->x, cp[i]->y, cp[i]->z};
      rows[i] = &c[i];
    }
    solved = solve_power_centre<mpq_class>(rows, wp, p.dim, &z, &p.power);
  }
  if (!solved)
    throw std::logic_error("union alpha complex: degenerate simplex in the regular triangulation");
  p.centre = {z[0], z[1], z[2]};
  p.approx_centre = {enclose(z[0]), enclose(z[1]), enclose(z[2])};
  p.approx_power = enclose(p.power);
  p.exact = true;
  ++exact_count_;
  return p;
}

void AlphaComplex::approximate_centres() {
  for (std::uint32_t s = 0; s < simplices_.size(); ++s) {
    PowerSimplex& p = simplices_[s];
    std::array<const std::array<Interval, 3>*, 4> cp{};
    std::array<const Interval*, 4> wp{};
    for (int i = 0; i <= p.dim; ++i) {
      cp[i] = &approx_ball_[p.balls[i]];
      wp[i] = &approx_weight_[p.balls[i]];
    }
    if (!solve_power_centre<Interval>(cp, wp, p.dim, &p.approx_centre, &p.approx_power)) exact(s);
  }
}

int AlphaComplex::link_sign(std::uint32_t s, std::uint32_t j) const {
  const PowerSimplex& p = simplices_[s];
  Interval d(0.0);
  for (int k = 0; k < 3; ++k) d += square(p.approx_centre[k] - approx_ball_[j][k]);
  const Interval v = d - approx_weight_[j] - p.approx_power;
  if (v.lo > 0) return 1;
  if (v.hi < 0) return -1;
  const PowerSimplex& e = exact(s);
  return sgn(power(*balls_, j, e.centre) - e.power);
}

int AlphaComplex::compare_powers(std::uint32_t a, std::uint32_t b) const {
  if (a == b) return 0;
  const Interval d = simplices_[a].approx_power - simplices_[b].approx_power;
  if (d.lo > 0) return 1;
  if (d.hi < 0) return -1;
  return cmp(exact(a).power, exact(b).power) < 0 ? -1 : cmp(exact(a).power, exact(b).power) > 0 ? 1 : 0;
}

int AlphaComplex::power_sign(std::uint32_t s) const {
  const Interval& w = simplices_[s].approx_power;
  if (w.lo > 0) return 1;
  if (w.hi < 0) return -1;
  return sgn(exact(s).power);
}

// rho(sigma) = w(sigma) if z(sigma) lies in the dual face (no link ball has a smaller power
// there), else the minimum over the dual face's facets, the cofaces (top-down). rho is kept
// as the simplex whose power it is.
void AlphaComplex::compute_rho() {
  rho_sign_.assign(simplices_.size(), 1);
  for (int dim = 3; dim >= 0; --dim)
    for (std::uint32_t s : by_dim_[dim]) {
      PowerSimplex& p = simplices_[s];
      bool inside = true;
      for (std::uint32_t c : p.cofaces) {
        const PowerSimplex& q = simplices_[c];
        for (int k = 0; k <= q.dim && inside; ++k)
          if (!std::binary_search(p.balls.begin(), p.balls.begin() + p.dim + 1, q.balls[k]))
            inside = link_sign(s, q.balls[k]) >= 0;
      }
      p.rho_simplex = s;
      if (!inside) {
        p.rho_simplex = simplices_[p.cofaces[0]].rho_simplex;
        for (std::uint32_t c : p.cofaces)
          if (compare_powers(simplices_[c].rho_simplex, p.rho_simplex) < 0) p.rho_simplex = simplices_[c].rho_simplex;
      }
      rho_sign_[s] = power_sign(p.rho_simplex);
    }
  // rho = 0: the dual face touches the zero set of min pow at one point (pow is strictly
  // convex on it), the centre of rho_simplex; it counts when that point is interior.
  in_complex_.assign(simplices_.size(), false);
  std::map<std::uint32_t, bool> interior;
  for (std::uint32_t s = 0; s < simplices_.size(); ++s) {
    if (rho_sign_[s] != 0) {
      in_complex_[s] = rho_sign_[s] < 0;
      continue;
    }
    const std::uint32_t r = simplices_[s].rho_simplex;
    auto it = interior.find(r);
    if (it == interior.end()) it = interior.emplace(r, interior_of_union(*balls_, exact(r).centre)).first;
    in_complex_[s] = it->second;
  }
}

bool AlphaComplex::is_singular(std::uint32_t s) const {
  if (!in_complex(s) || simplices_[s].dim == 3) return false;
  for (std::uint32_t c : simplices_[s].cofaces)
    if (in_complex(c)) return false;
  return true;
}

std::array<RadicalNumber, 3> BoundaryVertex::coordinates(const RadicalTable& t) const {
  if (rational) return {RadicalNumber(point.x), RadicalNumber(point.y), RadicalNumber(point.z)};
  return {RadicalNumber(z.x) + RadicalNumber::root(t, radical, side * n.x),
          RadicalNumber(z.y) + RadicalNumber::root(t, radical, side * n.y),
          RadicalNumber(z.z) + RadicalNumber::root(t, radical, side * n.z)};
}

BallSet random_ball_set(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  const double side = 1.6 * std::cbrt(static_cast<double>(n));
  auto uniform = [&](double lo, double width) { return lo + width * static_cast<double>(rng() % 4096) / 4096.0; };
  BallSet s;
  s.source = "random_ball_set(" + std::to_string(n) + ", seed " + std::to_string(seed) + ")";
  for (std::size_t i = 0; i < n; ++i) {
    const double x = uniform(0, side), y = uniform(0, side), z = uniform(0, side), r = uniform(0.8, 0.4);
    s.centers.push_back({mpq_class(x), mpq_class(y), mpq_class(z)});
    s.squared_radii.push_back(mpq_class(r) * mpq_class(r));
    s.approx_centers.push_back({x, y, z});
    s.approx_radii.push_back(r);
  }
  return s;
}

std::array<ExactPoint3, 3> boundary_vertex_key(const BoundaryVertex& v) {
  if (v.rational) return {v.point, {-1, 0, 0}, {0, 0, 0}};
  const mpq_class& lead = sgn(v.n.x) != 0 ? v.n.x : sgn(v.n.y) != 0 ? v.n.y : v.n.z;
  return {v.z, {v.s * dot(v.n, v.n), 0, 0}, mpq_class(v.side / abs(lead)) * v.n};
}

namespace {

// The interval filter for the point z + side sqrt(s) n of triangle t (three spheres
// meeting) against ball j (the extra vertex of a coface): the sign of
// pow_j - pow_t = (pow_j(z) - w) + side 2 n . (c_0 - c_j) sqrt(s), or 0 when unsure.
class DualEdgeFilter {
 public:
  DualEdgeFilter(const AlphaComplex& k, const PowerSimplex& p) : k_(k), p_(p) {
    c0_ = k.approx_ball(p.balls[0]);
    std::array<Interval, 3> e1, e2;
    for (int m = 0; m < 3; ++m) {
      e1[m] = k.approx_ball(p.balls[1])[m] - c0_[m];
      e2[m] = k.approx_ball(p.balls[2])[m] - c0_[m];
    }
    n_ = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const Interval nn = square(n_[0]) + square(n_[1]) + square(n_[2]);
    usable_ = nn.lo > 0;
    if (usable_) root_ = sqrt(-p.approx_power / nn);
  }

  int sign(int side, std::uint32_t j) const {
    if (!usable_) return 0;
    const auto& cj = k_.approx_ball(j);
    Interval a = -k_.approx_weight(j) - p_.approx_power, bn(0.0);
    for (int x = 0; x < 3; ++x) {
      a += square(p_.approx_centre[x] - cj[x]);
      bn += n_[x] * (c0_[x] - cj[x]);
    }
    const Interval v = a + Interval(2.0 * side) * bn * root_;
    return v.lo > 0 ? 1 : v.hi < 0 ? -1 : 0;
  }

  // Whether the point certainly lies in the open ball of some coface's extra vertex.
  bool certainly_off_dual_edge(int side) const {
    for (std::uint32_t c : p_.cofaces) {
      const PowerSimplex& q = k_.simplices()[c];
      for (int m = 0; m < 4; ++m) {
        const std::uint32_t j = q.balls[m];
        if (std::find(p_.balls.begin(), p_.balls.begin() + 3, j) != p_.balls.begin() + 3) continue;
        if (sign(side, j) < 0) return true;
      }
    }
    return false;
  }

 private:
  const AlphaComplex& k_;
  const PowerSimplex& p_;
  std::array<Interval, 3> c0_, n_;
  Interval root_;
  bool usable_ = false;
};

}  // namespace

std::vector<BoundaryVertex> boundary_vertices(const BallSet& b, const AlphaComplex& k, RadicalTable* table,
                                              bool filtered) {
  std::deque<BoundaryVertex> found;  // no copies on growth (GMP's rationals move with a throwing move)
  // A point on four or more spheres comes from several triangles.
  auto key_less = [](const std::array<ExactPoint3, 3>& x, const std::array<ExactPoint3, 3>& y) {
    for (int i = 0; i < 3; ++i)
      if (int c = compare_lex(x[i], y[i])) return c < 0;
    return false;
  };
  std::map<std::array<ExactPoint3, 3>, bool, decltype(key_less)> seen(key_less);
  for (std::uint32_t t : k.of_dimension(2)) {
    if (k.power_sign(t) > 0) continue;  // the three spheres do not meet
    if (filtered) {
      const DualEdgeFilter coarse(k, k.simplices()[t]);  // the centre's enclosure from intervals
      if (coarse.certainly_off_dual_edge(1) && coarse.certainly_off_dual_edge(-1)) continue;
    }
    const PowerSimplex& p = k.exact(t);
    const DualEdgeFilter filter(k, p);  // tight: the enclosures of the exact centre and power
    BoundaryVertex v;
    std::copy(p.balls.begin(), p.balls.begin() + 3, v.balls.begin());
    const ExactPoint3& c0 = b.centers[v.balls[0]];
    v.z = p.centre;
    v.n = cross(b.centers[v.balls[1]] - c0, b.centers[v.balls[2]] - c0);
    v.s = -p.power / dot(v.n, v.n);
    const auto root = rational_root(v.s);
    bool registered = false;
    for (int side : {1, -1}) {
      if (side < 0 && sgn(v.s) == 0) break;
      // On the dual edge: pow_j >= pow_i there for the extra ball j of every coface.
      bool valid = true;
      for (std::uint32_t c : p.cofaces) {
        const PowerSimplex& q = k.simplices()[c];
        for (int m = 0; m < 4; ++m) {
          const std::uint32_t j = q.balls[m];
          if (!valid || std::find(v.balls.begin(), v.balls.end(), j) != v.balls.end()) continue;
          if (const int certain = filtered ? filter.sign(side, j) : 0) {
            valid = certain > 0;
            continue;
          }
          const mpq_class a = power(b, j, v.z) - p.power;
          valid &= sign_with_root(a, side, 2 * dot(v.n, c0 - b.centers[j]), v.s) >= 0;
        }
      }
      if (!valid) continue;
      v.side = side;
      if (root) {
        v.rational = true;
        v.point = v.z + mpq_class(side * *root) * v.n;
        if (!seen.emplace(boundary_vertex_key(v), true).second) continue;
        if (interior_of_union(b, v.point)) continue;  // surrounded by the balls through it
        v.approx = {enclose(v.point.x), enclose(v.point.y), enclose(v.point.z)};
      } else {
        if (!seen.emplace(boundary_vertex_key(v), true).second) continue;
        if (!registered) v.radical = table->add(v.s);
        registered = true;
        const Interval r = table->root(v.radical);
        v.approx = {enclose(v.z.x) + Interval(side) * enclose(v.n.x) * r, enclose(v.z.y) + Interval(side) * enclose(v.n.y) * r,
                    enclose(v.z.z) + Interval(side) * enclose(v.n.z) * r};
      }
      found.push_back(v);
    }
  }
  std::vector<BoundaryVertex> out;
  out.reserve(found.size());
  for (BoundaryVertex& v : found) out.push_back(std::move(v));
  return out;
}

}  // namespace grassfire
