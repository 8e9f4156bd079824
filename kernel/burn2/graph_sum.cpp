// graph_sum.cpp -- see graph_sum.h.
#include "burn2/graph_sum.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace grassfire {

GraphSum& GraphSum::add(std::uint32_t id, bool is_edge, std::int64_t coef) {
  atoms_.push_back({id, is_edge, coef * denominator_});
  return *this;
}

void GraphSum::rescale_to(std::int64_t denominator) {
  if (denominator % denominator_ != 0) throw std::logic_error("graph sum: incompatible denominators");
  const std::int64_t f = denominator / denominator_;
  for (Atom& a : atoms_) a.coef *= f;
  denominator_ = denominator;
}

GraphSum& GraphSum::operator+=(const GraphSum& o) {
  const std::int64_t d = std::lcm(denominator_, o.denominator_);
  rescale_to(d);
  const std::int64_t f = d / o.denominator_;
  for (const Atom& a : o.atoms_) atoms_.push_back({a.id, a.is_edge, a.coef * f});
  return *this;
}

GraphSum& GraphSum::operator-=(const GraphSum& o) {
  GraphSum negated = o;
  for (Atom& a : negated.atoms_) a.coef = -a.coef;
  return *this += negated;
}

GraphSum& GraphSum::divide(std::int64_t k) {
  denominator_ *= k;
  return *this;
}

void GraphSum::cancel() {
  std::sort(atoms_.begin(), atoms_.end(), [](const Atom& a, const Atom& b) {
    return a.is_edge != b.is_edge ? a.is_edge < b.is_edge : a.id < b.id;
  });
  std::vector<Atom> merged;
  for (const Atom& a : atoms_) {
    if (!merged.empty() && merged.back().id == a.id && merged.back().is_edge == a.is_edge)
      merged.back().coef += a.coef;
    else
      merged.push_back(a);
  }
  atoms_.clear();
  for (const Atom& a : merged)
    if (a.coef != 0) atoms_.push_back(a);
}

void GraphSum::cancel(const MedialGraph& g) {
  const MedialGeometry& geo = g.geometry();
  for (Atom& a : atoms_) a.id = a.is_edge ? geo.length_class(a.id) : geo.radius_class(a.id);
  cancel();
}

Interval GraphSum::approx(const MedialGraph& g) const {
  Interval sum(0.0);
  for (const Atom& a : atoms_) {
    const Interval v = a.is_edge ? g.edge(a.id).length : g.node(a.id).radius;
    sum += Interval(static_cast<double>(a.coef)) * v;
  }
  return sum / Interval(static_cast<double>(denominator_));
}

ExactSum GraphSum::exact(const MedialGraph& g) const {
  ExactSum sum;
  for (const Atom& a : atoms_) {
    ExactSum v = a.is_edge ? g.geometry().exact_length(a.id) : g.geometry().exact_radius(a.id);
    sum += v.scale(mpq_class(static_cast<long>(a.coef)));
  }
  return sum.scale(mpq_class(1, static_cast<unsigned long>(denominator_)));
}

int compare(const GraphSum& a, const GraphSum& b, const MedialGraph& g, NumberStats* stats) {
  GraphSum d = a - b;
  d.cancel();
  if (d.empty()) {
    if (stats) ++stats->exact_zero;
    return 0;
  }
  const int quick = certified_sign(d.approx(g));
  if (quick != kUndecided) {
    if (stats) ++stats->filter_decided;
    return quick;
  }
  return sign(d.exact(g), stats);
}

}  // namespace grassfire
