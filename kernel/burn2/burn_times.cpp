// burn_times.cpp -- see burn_times.h.
#include "burn2/burn_times.h"

#include "number/mpfr_bounds.h"

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

ExactSum BurnTimes::exact_difference(TimeId a, TimeId b) const {
  ExactSum sum;
  auto add_record = [&](TimeId t, int s) {
    const Record& r = records_[t];
    ExactSum term = r.pred == kNoTime ? graph_->geometry().exact_radius(r.ref)
                                      : graph_->geometry().exact_length(r.ref);
    if (s > 0)
      sum += term;
    else
      sum -= term;
  };
  // Walk both chains up to their common ancestor; the ancestor's value cancels.
  while (a != b) {
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
  return sign(exact_difference(a, b), &stats_);
}

int BurnTimes::compare_quench(TimeId a, TimeId b, std::uint32_t edge, TimeId c) const {
  const Interval q = half(records_[a].value + records_[b].value + graph_->edge(edge).length);
  const int quick = certified_sign(q - records_[c].value);
  if (quick != kUndecided) {
    ++stats_.filter_decided;
    return quick;
  }
  // The same stages as compare(), on 2 (q - c) = a + b + length - 2 c.
  const LongInterval& la = long_value(a);
  const LongInterval& lb = long_value(b);
  const LongInterval& lc = long_value(c);
  const LongInterval twice = (la + lb + graph_->geometry().enclose_length_long(edge)) - (lc + lc);
  if (twice.lo > 0 || twice.hi < 0) {
    ++stats_.extended_decided;
    return twice.lo > 0 ? 1 : -1;
  }
  const Refined& ra = refined(a);
  const Refined& rb = refined(b);
  const Refined& rc = refined(c);
  MpfrBounds d2(kRefinedBits);
  graph_->geometry().enclose_length(edge, d2.lo, d2.hi);
  mpfr_add(d2.lo, d2.lo, ra.lo, MPFR_RNDD);
  mpfr_add(d2.lo, d2.lo, rb.lo, MPFR_RNDD);
  mpfr_sub(d2.lo, d2.lo, rc.hi, MPFR_RNDD);
  mpfr_sub(d2.lo, d2.lo, rc.hi, MPFR_RNDD);
  mpfr_add(d2.hi, d2.hi, ra.hi, MPFR_RNDU);
  mpfr_add(d2.hi, d2.hi, rb.hi, MPFR_RNDU);
  mpfr_sub(d2.hi, d2.hi, rc.lo, MPFR_RNDU);
  mpfr_sub(d2.hi, d2.hi, rc.lo, MPFR_RNDU);
  if (mpfr_sgn(d2.lo) > 0 || mpfr_sgn(d2.hi) < 0) {
    ++stats_.mpfr_decided;
    return mpfr_sgn(d2.lo) > 0 ? 1 : -1;
  }
  ExactSum d = exact(a) + exact(b) + graph_->geometry().exact_length(edge);
  d.scale(mpq_class(1, 2));
  d -= exact(c);
  return sign(d, &stats_);
}

}  // namespace grassfire
