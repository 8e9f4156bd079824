// burn_times.cpp -- see burn_times.h.
#include "burn2/burn_times.h"

#include "number/mpfr_bounds.h"

#include <algorithm>
#include <stdexcept>

namespace grassfire {

namespace {
constexpr long kRefinedBits = 128;
}  // namespace

// A 128-bit MPFR enclosure [lo, hi].
struct BurnTimes::Refined : MpfrBounds {
  Refined() : MpfrBounds(kRefinedBits) {}
};

BurnTimes::BurnTimes(const MedialGraph& graph) : graph_(&graph) {}
BurnTimes::~BurnTimes() = default;
BurnTimes::BurnTimes(BurnTimes&&) noexcept = default;
BurnTimes& BurnTimes::operator=(BurnTimes&&) noexcept = default;

const BurnTimes::Refined& BurnTimes::refined(TimeId t) const {
  if (refined_.size() < records_.size()) refined_.resize(records_.size());
  // Walk up to the nearest memoised ancestor, then fill in downwards.
  std::vector<TimeId> chain;
  for (TimeId cur = t; cur != kNoTime && !refined_[cur]; cur = records_[cur].pred) chain.push_back(cur);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const Record& r = records_[*it];
    auto out = std::make_unique<Refined>();
    if (r.pred == kNoTime) {
      graph_->geometry().enclose_radius(r.ref, out->lo, out->hi);
    } else {
      MpfrBounds step(kRefinedBits);
      graph_->geometry().enclose_length(r.ref, step.lo, step.hi);
      const Refined& base = *refined_[r.pred];
      mpfr_add(out->lo, base.lo, step.lo, MPFR_RNDD);
      mpfr_add(out->hi, base.hi, step.hi, MPFR_RNDU);
    }
    refined_[*it] = std::move(out);
  }
  return *refined_[t];
}

const LongInterval& BurnTimes::long_value(TimeId t) const {
  if (long_.size() < records_.size()) {
    long_.resize(records_.size());
    has_long_.resize(records_.size(), 0);
  }
  std::vector<TimeId> chain;
  for (TimeId cur = t; cur != kNoTime && !has_long_[cur]; cur = records_[cur].pred) chain.push_back(cur);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const Record& r = records_[*it];
    long_[*it] = r.pred == kNoTime ? graph_->geometry().enclose_radius_long(r.ref)
                                   : long_[r.pred] + graph_->geometry().enclose_length_long(r.ref);
    has_long_[*it] = 1;
  }
  return long_[t];
}

int BurnTimes::long_sign(TimeId a, TimeId b) const {
  const LongInterval& x = long_value(a);
  const LongInterval& y = long_value(b);
  if (x.hi < y.lo) return -1;
  if (y.hi < x.lo) return 1;
  return kUndecided;
}

int BurnTimes::refined_sign(TimeId a, TimeId b) const {
  const Refined& x = refined(a);
  const Refined& y = refined(b);
  if (mpfr_less_p(x.hi, y.lo)) return -1;
  if (mpfr_less_p(y.hi, x.lo)) return 1;
  return kUndecided;
}

TimeId BurnTimes::ignition(std::uint32_t leaf) {
  records_.push_back({graph_->node(leaf).radius, kNoTime, leaf, 0});
  return static_cast<TimeId>(records_.size() - 1);
}

TimeId BurnTimes::advance(TimeId from, std::uint32_t edge) {
  const Record& r = records_[from];
  const Record next{r.value + graph_->edge(edge).length, from, edge, r.depth + 1};
  records_.push_back(next);
  return static_cast<TimeId>(records_.size() - 1);
}

TimeId BurnTimes::advance(TimeId from, std::uint32_t edge, const Interval& enclosure) {
  const TimeId t = advance(from, edge);
  Interval& v = records_[t].value;
  v = {std::max(v.lo, enclosure.lo), std::min(v.hi, enclosure.hi)};
  return t;
}

ExactSum BurnTimes::exact(TimeId t) const {
  ExactSum sum;
  for (TimeId cur = t; cur != kNoTime; cur = records_[cur].pred) {
    const Record& r = records_[cur];
    if (r.pred == kNoTime)
      sum += graph_->geometry().exact_radius(r.ref);
    else
      sum += graph_->geometry().exact_length(r.ref);
  }
  return sum;
}

GraphSum BurnTimes::as_graph_sum(TimeId t) const {
  GraphSum sum;
  for (TimeId cur = t; cur != kNoTime; cur = records_[cur].pred) {
    const Record& r = records_[cur];
    if (r.pred == kNoTime)
      sum.add_radius(r.ref);
    else
      sum.add_length(r.ref);
  }
  return sum;
}

std::uint32_t BurnTimes::origin(TimeId t) const {
  while (records_[t].pred != kNoTime) t = records_[t].pred;
  return records_[t].ref;
}

namespace {
constexpr std::uint32_t kNoClass = 0xffffffffu;
}  // namespace

std::uint32_t BurnTimes::find_class(std::uint32_t c) const {
  while (class_parent_[c] != c) c = class_parent_[c] = class_parent_[class_parent_[c]];
  return c;
}

std::uint32_t BurnTimes::value_class(TimeId t) const {
  if (class_.size() < records_.size()) class_.resize(records_.size(), kNoClass);
  scratch_.clear();
  for (TimeId cur = t; cur != kNoTime && class_[cur] == kNoClass; cur = records_[cur].pred) scratch_.push_back(cur);
  const MedialGeometry& geo = graph_->geometry();
  for (auto it = scratch_.rbegin(); it != scratch_.rend(); ++it) {
    const Record& r = records_[*it];
    // An ignition's key has 0xffffffff in the high word, which no class id reaches. An
    // advance that continues its predecessor's edge along one curve (through a degree-2
    // node) is keyed as one step from the predecessor's predecessor with the joined length.
    std::uint64_t key;
    if (r.pred == kNoTime) {
      key = (std::uint64_t{0xffffffffu} << 32) | geo.radius_class(r.ref);
    } else {
      const Record& p = records_[r.pred];
      const std::uint32_t joined = p.pred == kNoTime ? 0xffffffffu : geo.joined_length_class(p.ref, r.ref);
      key = joined != 0xffffffffu ? (std::uint64_t{find_class(class_[p.pred])} << 32) | joined
                                  : (std::uint64_t{find_class(class_[r.pred])} << 32) | geo.length_class(r.ref);
    }
    const auto [pos, fresh] = class_of_step_.emplace(key, static_cast<std::uint32_t>(class_parent_.size()));
    if (fresh) class_parent_.push_back(pos->second);
    class_[*it] = pos->second;
  }
  return find_class(class_[t]);
}

GraphSum BurnTimes::difference(TimeId a, TimeId b) const {
  GraphSum sum;
  auto add_record = [&](TimeId t, std::int64_t s) {
    const Record& r = records_[t];
    if (r.pred == kNoTime)
      sum.add_radius(r.ref, s);
    else
      sum.add_length(r.ref, s);
  };
  // Walk both chains up to their common ancestor, or to ancestors of equal class: the
  // rest of the two values cancels.
  while (a != b && (a == kNoTime || b == kNoTime || value_class(a) != value_class(b))) {
    const std::uint32_t da = a == kNoTime ? 0 : records_[a].depth + 1;
    const std::uint32_t db = b == kNoTime ? 0 : records_[b].depth + 1;
    if (da >= db) {
      add_record(a, +1);
      a = records_[a].pred;
    } else {
      add_record(b, -1);
      b = records_[b].pred;
    }
  }
  return sum;
}

int BurnTimes::exact_sign(GraphSum d, TimeId a, TimeId b) const {
  d.cancel(*graph_);
  int s = 0;
  if (d.empty()) {
    ++stats_.exact_zero;
    ++stats_.class_zero;
  } else {
    const std::uint64_t uncertified = stats_.uncertified_zero;
    s = sign(d.exact(*graph_), &stats_);
    if (stats_.uncertified_zero != uncertified) uncertified_pairs_.emplace_back(a, b);
    if (s != 0 || stats_.uncertified_zero != uncertified) return s;
  }
  const std::uint32_t ca = value_class(a), cb = value_class(b);
  class_parent_[std::max(ca, cb)] = std::min(ca, cb);
  return 0;
}

int BurnTimes::compare(TimeId a, TimeId b) const {
  if (a == b) return 0;
  const Interval& x = records_[a].value;
  const Interval& y = records_[b].value;
  if (x.hi < y.lo) {
    ++stats_.filter_decided;
    return -1;
  }
  if (y.hi < x.lo) {
    ++stats_.filter_decided;
    return 1;
  }
  // Point enclosures are the exact values: ignitions at R = 0 leaves (convex vertices) tie
  // here without building their exact forms.
  if (x.lo == x.hi && y.lo == y.hi && x.lo == y.lo) {
    ++stats_.exact_zero;
    return 0;
  }
  if (value_class(a) == value_class(b)) {
    ++stats_.exact_zero;
    ++stats_.class_zero;
    return 0;
  }
  const int l = long_sign(a, b);
  if (l != kUndecided) {
    ++stats_.extended_decided;
    return l;
  }
  const int r = refined_sign(a, b);
  if (r != kUndecided) {
    ++stats_.mpfr_decided;
    return r;
  }
  return exact_sign(difference(a, b), a, b);
}

}  // namespace grassfire
