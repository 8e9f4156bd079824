// graph_sum.h -- exact sums of a medial graph's atoms: R at nodes and edge lengths.
//
// Computes: values  (sum_v a_v R(v) + sum_e b_e length(e)) / d  with integer a, b, d,
// and their certified comparison. Equal atoms cancel symbolically before any arithmetic,
// so two sums along the same path compare equal without evaluating a single root; the
// remainder is compared by its interval enclosure and then exactly (number/exact_sum.h).
// Used by the definitional oracle and by tests that compare it with the engine; compare()
// cancels equal atom ids only, so the oracle does not depend on the value classes that
// the burning engine uses (cancel(g): atoms of equal class, burn2/burn_times.h).
// Complexity: O(k log k) for k atoms, plus the exact work on what does not cancel.
#pragma once

#include <cstdint>
#include <vector>

#include "medial2/medial_graph.h"
#include "number/exact_sum.h"

namespace grassfire {

class GraphSum {
 public:
  GraphSum& add_radius(std::uint32_t node, std::int64_t coef = 1) { return add(node, false, coef); }
  GraphSum& add_length(std::uint32_t edge, std::int64_t coef = 1) { return add(edge, true, coef); }
  GraphSum& operator+=(const GraphSum& o);
  GraphSum& operator-=(const GraphSum& o);
  friend GraphSum operator+(GraphSum a, const GraphSum& b) { return a += b; }
  friend GraphSum operator-(GraphSum a, const GraphSum& b) { return a -= b; }
  // Divides the value by k (k > 0).
  GraphSum& divide(std::int64_t k);

  Interval approx(const MedialGraph& g) const;
  ExactSum exact(const MedialGraph& g) const;
  // Merges equal atoms and drops zero coefficients; the value does not change.
  void cancel();
  // The same, merging atoms of equal value class (MedialGeometry::radius_class and
  // length_class: provably equal values) into their class representative.
  void cancel(const MedialGraph& g);
  bool empty() const { return atoms_.empty(); }

  struct Atom {
    std::uint32_t id;
    bool is_edge;
    std::int64_t coef;
  };
  const std::vector<Atom>& atoms() const { return atoms_; }
  std::int64_t denominator() const { return denominator_; }

 private:
  GraphSum& add(std::uint32_t id, bool is_edge, std::int64_t coef);
  void rescale_to(std::int64_t denominator);

  std::vector<Atom> atoms_;
  std::int64_t denominator_ = 1;
};

// Certified sign of a - b.
int compare(const GraphSum& a, const GraphSum& b, const MedialGraph& g, NumberStats* stats = nullptr);

}  // namespace grassfire
