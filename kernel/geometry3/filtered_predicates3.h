// filtered_predicates3.h -- the exact predicates of exact_predicates3.h behind an interval
// filter, on indexed rational points of R^3.
//
// Computes the same three-valued answers as the rational predicates (compare_lex,
// collinear, orientation, EdgeAngularOrder::compare, squared lengths rounded as
// mpq_class::get_d rounds), first in interval arithmetic on a certified enclosure of every
// point, then, only when an interval contains zero, exactly over Q. The filter never
// decides a sign its interval does not certify, so the answers are exactly those of the
// rational predicates (tests compare them on seeded random and degenerate inputs).
// Enclosures: the nearest double of each coordinate widened by an ulp, or the double
// itself when the rational is a double (then the interval is a point, as sharp as a
// static filter). Coordinates beyond 2^200 in magnitude (or not finite as doubles) skip the
// filter: every degree-4 product below then stays far from overflow.
// Counts: every predicate call counts as decided by the filter or by the exact stage
// (docs/design.md 3: count filter failures and exact fallbacks).
// Contract: the points outlive the object and do not change. Complexity: O(1) doubles per
// predicate, O(1) rational operations when the filter fails; construction O(points).
// Section: docs/design.md 3 (interval filter, then exact), 5 (strata, angular order at edges).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "geometry3/exact_predicates3.h"
#include "number/interval.h"

namespace grassfire {

struct FilterCounts {
  std::size_t filtered = 0;  // decided by the interval filter
  std::size_t exact = 0;     // the filter could not decide: decided over Q
};

using IntervalPoint3 = std::array<Interval, 3>;

// A certified enclosure of a rational (see the header comment); `is_double` says whether
// the rational is exactly a normal double (the enclosure is then that point).
struct CoordinateEnclosure {
  Interval value;
  bool is_double = false;
  bool usable = false;  // finite and |q| <= 2^200
};
CoordinateEnclosure enclose_coordinate(const mpq_class& q);

class FilteredPoints {
 public:
  // points(i) for i < n must stay valid while this object lives.
  FilteredPoints(std::size_t n, const std::function<const ExactPoint3&(std::size_t)>& points);
  explicit FilteredPoints(const std::vector<ExactPoint3>& points);

  std::size_t size() const { return exact_.size(); }
  const ExactPoint3& exact(std::uint32_t i) const { return *exact_[i]; }
  const IntervalPoint3& box(std::uint32_t i) const { return box_[i]; }
  bool usable(std::uint32_t i) const { return usable_[i] != 0; }
  bool is_double(std::uint32_t i) const { return double_[i] != 0; }
  FilterCounts& counts() const { return counts_; }

  // compare_lex(exact(i), exact(j)).
  int compare_lex(std::uint32_t i, std::uint32_t j) const;
  // collinear(exact(a), exact(b), exact(c)).
  bool collinear(std::uint32_t a, std::uint32_t b, std::uint32_t c) const;
  // orientation(exact(a), exact(b), exact(c), exact(d)).
  int orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const;
  // std::sqrt(squared_distance(exact(a), exact(b)).get_d()), the same double.
  double distance(std::uint32_t a, std::uint32_t b) const;

  // The certified sign of an interval, or the exact sign of the rational expression it
  // encloses when it contains zero (counted either way).
  template <class ExactSign>
  int sign(const Interval& filtered, ExactSign&& exact_sign) const {
    const int s = certified_sign(filtered);
    if (s != kUndecided) {
      ++counts_.filtered;
      return s;
    }
    ++counts_.exact;
    return exact_sign();
  }

 private:
  std::vector<const ExactPoint3*> exact_;
  std::vector<IntervalPoint3> box_;
  std::vector<std::uint8_t> usable_, double_;
  mutable FilterCounts counts_;
};

// EdgeAngularOrder (exact_predicates3.h) on indexed points: the half-planes about the
// directed line a -> b through the third vertices u, w of the triangles on the edge,
// ordered counterclockwise seen from b from the half-plane through ref. The projections
// of EdgeAngularOrder are never formed: with r = p - a and d = b - a,
//   d . (proj r x proj s) = det(d, r, s) and
//   |d|^2 (proj r . proj s) = |d|^2 (r . s) - (r . d)(s . d),
// so every decision is the sign of a polynomial of degree 3 or 4 in the coordinates.
class FilteredEdgeOrder {
 public:
  FilteredEdgeOrder(const FilteredPoints& points, std::uint32_t a, std::uint32_t b);
  // EdgeAngularOrder(a, b).compare(direction(ref), direction(u), direction(w)).
  int compare(std::uint32_t ref, std::uint32_t u, std::uint32_t w) const;

 private:
  int half(std::uint32_t ref, std::uint32_t u, int det) const;
  int det_sign(std::uint32_t r, std::uint32_t s) const;  // sign of det(d, r - a, s - a)
  int projected_dot_sign(std::uint32_t r, std::uint32_t s) const;
  int self_projected_sign(std::uint32_t r) const;
  const FilteredPoints& p_;
  std::uint32_t a_, b_;
  bool usable_;
  IntervalPoint3 d_;
};

// The plane through a, b, c (not collinear): side(p) = orientation(a, b, c, p), with the
// exact normal and offset computed once, at the first point the filter cannot decide (a
// planar sheet decides every one of its vertices exactly).
class FilteredPlane {
 public:
  FilteredPlane(const FilteredPoints& points, std::uint32_t a, std::uint32_t b, std::uint32_t c);
  int side(std::uint32_t p) const;

 private:
  const FilteredPoints& p_;
  std::array<std::uint32_t, 3> v_;
  bool usable_;
  IntervalPoint3 u_, w_;  // b - a, c - a
  mutable bool exact_ready_ = false;
  mutable ExactPoint3 normal_;
  mutable mpq_class offset_;
};

}  // namespace grassfire
