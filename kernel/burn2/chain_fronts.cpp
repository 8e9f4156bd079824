// chain_fronts.cpp -- see chain_fronts.h.
#include "burn2/chain_fronts.h"

#include <stdexcept>
#include <string>

#include "number/compensated_sum.h"

namespace grassfire {

ChainFronts::ChainFronts(const MedialGraph& g, const MedialChains& chains, GrassfireResult& result)
    : g_(g), chains_(chains), result_(result), run_first_(2 * std::size_t{chains.count()}, kNoTime) {}

TimeId ChainFronts::run(std::uint32_t end, TimeId t) {
  const std::uint32_t c = end >> 1, k = chains_.length(c);
  BurnTimes& times = result_.times;
  const Interval base = times.approx(t);
  CompensatedSum sum;
  TimeId prev = t;
  for (std::uint32_t i = 1; i <= k; ++i) {
    const std::uint32_t e = end & 1 ? chains_.edge(c, k + 1 - i) : chains_.edge(c, i);
    sum += g_.edge(e).length;
    prev = times.advance(prev, e, base + sum.value());
    if (i == 1) run_first_[end] = prev;
  }
  return prev;
}

TimeId ChainFronts::time_at(std::uint32_t end, std::uint32_t i, const TimeId sent[2]) const {
  const std::uint32_t c = end >> 1, k = chains_.length(c);
  if (end & 1) return i == k ? sent[1] : run_first_[end] + (k - i) - 1;
  return i == 0 ? sent[0] : run_first_[end] + i - 1;
}

EventRank ChainFronts::rank_at(std::uint32_t c, std::uint32_t end, std::uint32_t i, const EventRank rank[2]) const {
  const std::uint32_t k = chains_.length(c);
  // An interior node burns at the arrival through the edge on the side of the end.
  if (end == 0) return i == 0 ? rank[0] : EventRank{false, chains_.node(c, i), chains_.edge(c, i)};
  return i == k ? rank[1] : EventRank{false, chains_.node(c, i), chains_.edge(c, i + 1)};
}

TimeId& ChainFronts::fire_from(std::uint32_t edge, std::uint32_t node) {
  EdgeFire& f = result_.fire[edge];
  return g_.edge(edge).u == node ? f.from_u : f.from_v;
}

void ChainFronts::resolve(std::uint32_t c, const TimeId sent[2], const EventRank rank[2],
                          std::vector<QuenchRecord>& quenches, std::vector<BurnEvent>& events) {
  const std::uint32_t k = chains_.length(c);
  if (sent[0] != kNoTime) fire_from(chains_.edge(c, 1), chains_.node(c, 0)) = sent[0];
  if (sent[1] != kNoTime) fire_from(chains_.edge(c, k), chains_.node(c, k)) = sent[1];
  if (sent[0] != kNoTime && sent[1] != kNoTime)
    both_fronts(c, sent, rank, quenches, events);
  else if (sent[0] != kNoTime)
    one_front(c, 2 * c, sent);
  else if (sent[1] != kNoTime)
    one_front(c, 2 * c + 1, sent);
  // Neither: the chain lies in the 2-core and never burns.
}

void ChainFronts::one_front(std::uint32_t c, std::uint32_t end, const TimeId sent[2]) {
  const std::uint32_t k = chains_.length(c);
  const bool from_x0 = (end & 1) == 0;
  for (std::uint32_t i = 1; i < k; ++i) {
    const std::uint32_t x = chains_.node(c, from_x0 ? i : k - i);
    const TimeId t = time_at(end, from_x0 ? i : k - i, sent);
    result_.burn[x] = t;
    fire_from(chains_.edge(c, from_x0 ? i + 1 : k - i), x) = t;
  }
}

void ChainFronts::both_fronts(std::uint32_t c, const TimeId sent[2], const EventRank rank[2],
                              std::vector<QuenchRecord>& quenches, std::vector<BurnEvent>& events) {
  const std::uint32_t k = chains_.length(c);
  if (run_first_[2 * c] == kNoTime) run(2 * c, sent[0]);
  if (run_first_[2 * c + 1] == kNoTime) run(2 * c + 1, sent[1]);
  const BurnTimes& times = result_.times;
  auto A = [&](std::uint32_t i) { return time_at(2 * c, i, sent); };
  auto B = [&](std::uint32_t i) { return time_at(2 * c + 1, i, sent); };
  // A_i - B_i is non-decreasing; A_0 <= B_0 and A_k >= B_k (an end sends only before the
  // other front reaches it). The fronts meet at the first i with A_i >= B_i.
  std::uint32_t lo = 0, hi = k;
  while (lo < hi) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    if (times.compare(A(mid), B(mid)) >= 0)
      hi = mid;
    else
      lo = mid + 1;
  }
  const std::uint32_t m = lo;
  const int at_m = times.compare(A(m), B(m));
  if (at_m < 0 || (at_m > 0 && m == 0))
    throw std::logic_error("extended grassfire: fronts in chain " + std::to_string(c) + " are out of order");
  for (std::uint32_t i = 1; i < k; ++i) result_.burn[chains_.node(c, i)] = i < m || (i == m && at_m == 0) ? A(i) : B(i);
  for (std::uint32_t i = 2; i <= std::min(m, k); ++i) fire_from(chains_.edge(c, i), chains_.node(c, i - 1)) = A(i - 1);
  for (std::uint32_t i = m + 1; i < k; ++i) fire_from(chains_.edge(c, i), chains_.node(c, i)) = B(i);
  QuenchRecord q;
  TimeId when = kNoTime;
  if (at_m == 0) {
    // The fronts reach x_m together. An interior node burns at the arrival the queue
    // takes first and sends fire into the other edge, where the other front is pending.
    q.place.node = chains_.node(c, m);
    when = m == 0 ? sent[0] : m == k ? sent[1] : A(m);
    if (m > 0 && m < k) {
      const bool a_first = rank_at(c, 0, m, rank) < rank_at(c, 1, m, rank);
      when = a_first ? A(m) : B(m);
      result_.burn[q.place.node] = when;
      fire_from(chains_.edge(c, a_first ? m + 1 : m), q.place.node) = when;
    }
    q.edf = times.approx(when);
  } else {
    // Inside e_m, between x_{m-1} (burnt from end 0) and x_m (from end 1): offset from the
    // first of them to send fire into e_m.
    if (m < k) fire_from(chains_.edge(c, m), chains_.node(c, m)) = B(m);
    const std::uint32_t e = chains_.edge(c, m);
    const int d = times.compare(A(m - 1), B(m));
    const bool a_second = d > 0 || (d == 0 && rank_at(c, 1, m, rank) < rank_at(c, 0, m - 1, rank));
    const TimeId tk = a_second ? B(m) : A(m - 1), tj = a_second ? A(m - 1) : B(m);
    const Interval w = g_.edge(e).length;
    q.place.at_node = false;
    q.place.edge = e;
    q.place.from = chains_.node(c, a_second ? m : m - 1);
    q.place.offset = half(w + times.approx(tj) - times.approx(tk));
    q.edf = half(times.approx(tk) + times.approx(tj) + w);
    q.sent_from = tk;
    q.sent_other = tj;
  }
  quenches.push_back(q);
  events.push_back({BurnEventType::Quench, q.edf, q.place, when});
}

}  // namespace grassfire
