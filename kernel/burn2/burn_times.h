// burn_times.h -- burn times on a medial graph, kept as a DAG of exact expressions.
//
// Computes: certified comparisons of burn times. A burn time is either an ignition,
// R(z) at a leaf z, or an advance, T + length(e) along an edge (3.3.1). Four stages:
// (1) every record keeps a certified double enclosure, which decides most comparisons;
// (2) otherwise both times get x87 extended-precision enclosures (11 more bits), and
// (3) then 128-bit MPFR enclosures, each computed along the chains from the atoms'
// enclosures and memoised per record, so a chain is refined at most once per stage
// however often it is compared (near-ties between long chains occur on large inputs,
// where the double enclosures of 10^5 summed lengths are about 10^-11 wide);
// Between (1) and (2), exact ties are looked for by value classes: the graph's geometry
// names atoms (R at a node, an edge length) with provably equal values (for the exact
// polygon axis, the atoms an exact symmetry of the polygon maps onto each other:
// medial2/polygon/polygon_axis_symmetry.h). A record's class is hash-consed from its chain: an
// ignition's class from the radius class of its leaf, an advance's from (class of its
// predecessor, length class of its edge), or from (class of its predecessor's
// predecessor, joined length class) when the two edges are pieces of one curve through a
// degree-2 node (MedialGeometry::joined_length_class); by induction on the chain, records
// of equal class have equal values, so mirror chains of a symmetric shape, which share no
// ancestor, tie in O(1) (amortised; classes are computed on demand and memoised). Ties
// proved exactly by stage (4) join their classes (union-find), so later ties between
// their descendants are found here too; a zero that is not certified (exact_sum.h) joins
// nothing.
// (4) otherwise both times are expanded into sums of atoms (R at the ignition leaf plus
// the edge lengths along the chain) down to their first common ancestor, or to the first
// pair of ancestors of equal class; atoms of equal class cancel symbolically
// (burn2/graph_sum.h); only what remains is built as ExactSums and the sign of the
// difference decided exactly (number/exact_sum.h).
// Contract: the graph outlives this object; every edge id and node id is valid.
// Complexity: O(1) to create a time; a comparison is O(1) when the filter or the value
// classes decide, and O(L) exact work for chains of length L otherwise.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "burn2/graph_sum.h"
#include "medial2/medial_graph.h"
#include "number/exact_sum.h"

namespace grassfire {

using TimeId = std::uint32_t;
constexpr TimeId kNoTime = 0xffffffffu;

class BurnTimes {
 public:
  explicit BurnTimes(const MedialGraph& graph);
  ~BurnTimes();
  BurnTimes(BurnTimes&&) noexcept;
  BurnTimes& operator=(BurnTimes&&) noexcept;

  TimeId ignition(std::uint32_t leaf);
  TimeId advance(TimeId from, std::uint32_t edge);
  // The same record, with its enclosure intersected with `enclosure`, another certified
  // enclosure of the same value (from a compensated sum along a chain of edges, which
  // does not widen with the chain's length: number/compensated_sum.h).
  TimeId advance(TimeId from, std::uint32_t edge, const Interval& enclosure);

  const Interval& approx(TimeId t) const { return records_[t].value; }
  // The exact value, as R(leaf) + the lengths of the edges on the chain.
  ExactSum exact(TimeId t) const;
  // The same value as a sum of graph atoms (for exact comparison with other sums).
  GraphSum as_graph_sum(TimeId t) const;
  // The leaf whose ignition starts the chain of t.
  std::uint32_t origin(TimeId t) const;
  // Certified sign of a - b (0 exactly when equal, up to the uncertified case of
  // exact_sum.h for transcendental edge lengths).
  int compare(TimeId a, TimeId b) const;
  // The value class of t (see above): equal classes, provably equal times.
  std::uint32_t value_class(TimeId t) const;

  std::size_t size() const { return records_.size(); }
  const NumberStats& stats() const { return stats_; }
  // The pairs (a, b) whose comparison ended as an uncertified zero (reported, never hidden).
  const std::vector<std::pair<TimeId, TimeId>>& uncertified_pairs() const { return uncertified_pairs_; }
  // Counts a comparison that the caller decided from the enclosures alone.
  void count_filter_decision() const { ++stats_.filter_decided; }
  // Adds the counts of comparisons the caller made of sums of these times.
  void count(const NumberStats& s) const { stats_.merge(s); }
  const MedialGraph& graph() const { return *graph_; }

 private:
  struct Record {
    Interval value;
    TimeId pred;         // kNoTime for an ignition
    std::uint32_t ref;   // the leaf for an ignition, the edge for an advance
    std::uint32_t depth; // chain length
  };
  // a - b as a sum of atoms, down to the first common ancestor or pair of ancestors of
  // equal class.
  GraphSum difference(TimeId a, TimeId b) const;
  // Exact sign of d (atoms of equal class cancelled first); joins the classes of a and b
  // when it proves a certified zero.
  int exact_sign(GraphSum d, TimeId a, TimeId b) const;
  std::uint32_t find_class(std::uint32_t c) const;
  // Stage 2: sign of a - b from memoised extended-precision enclosures, or kUndecided.
  int long_sign(TimeId a, TimeId b) const;
  const LongInterval& long_value(TimeId t) const;
  // Stage 3: sign of a - b from memoised 128-bit enclosures, or kUndecided.
  int refined_sign(TimeId a, TimeId b) const;
  struct Refined;
  const Refined& refined(TimeId t) const;

  const MedialGraph* graph_;
  std::vector<Record> records_;
  mutable NumberStats stats_;
  mutable std::vector<std::pair<TimeId, TimeId>> uncertified_pairs_;
  mutable std::vector<std::unique_ptr<Refined>> refined_;  // by TimeId, filled on demand
  mutable std::vector<LongInterval> long_;                  // by TimeId, filled on demand
  mutable std::vector<std::uint8_t> has_long_;
  mutable std::vector<std::uint32_t> class_;         // by TimeId, filled on demand
  mutable std::vector<std::uint32_t> class_parent_;  // union-find over classes
  mutable std::unordered_map<std::uint64_t, std::uint32_t> class_of_step_;
  mutable std::vector<TimeId> scratch_;
};

}  // namespace grassfire
