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
// (4) otherwise both times are expanded into ExactSums (R at the ignition leaf plus the
// edge lengths along the chain), their common part cancelled, and the sign of the
// difference decided exactly (number/exact_sum.h).
// Contract: the graph outlives this object; every edge id and node id is valid.
// Complexity: O(1) to create a time; a comparison is O(1) when the filter decides, and
// O(L) exact work for chains of length L otherwise.
#pragma once

#include <cstdint>
#include <memory>
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
  // Certified sign of (a + b + length(edge)) / 2 - c; used to compare quench values.
  int compare_quench(TimeId a, TimeId b, std::uint32_t edge, TimeId c) const;

  std::size_t size() const { return records_.size(); }
  const NumberStats& stats() const { return stats_; }
  // Counts a comparison that the caller decided from the enclosures alone.
  void count_filter_decision() const { ++stats_.filter_decided; }
  const MedialGraph& graph() const { return *graph_; }

 private:
  struct Record {
    Interval value;
    TimeId pred;         // kNoTime for an ignition
    std::uint32_t ref;   // the leaf for an ignition, the edge for an advance
    std::uint32_t depth; // chain length
  };
  // Exact a - b with the shared part of the two chains cancelled.
  ExactSum exact_difference(TimeId a, TimeId b) const;
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
  mutable std::vector<std::unique_ptr<Refined>> refined_;  // by TimeId, filled on demand
  mutable std::vector<LongInterval> long_;                  // by TimeId, filled on demand
  mutable std::vector<std::uint8_t> has_long_;
};

}  // namespace grassfire
