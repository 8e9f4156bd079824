// complex_builder.h -- assembling a RawComplex from exact points, merging equal points.
//
// Computes: vertex ids for exact points (equal coordinates give the same id, so conforming
// meshes of several pieces share their common vertices), triangles, segments and border
// ignition rules, collected into a RawComplex. Used by the synthetic complexes and the
// readers. Complexity: O(log n) exact comparisons per vertex.
#pragma once

#include <map>
#include <string>

#include "geometry3/exact_predicates3.h"
#include "complex3/raw_complex.h"

namespace grassfire {

class ComplexBuilder {
 public:
  explicit ComplexBuilder(std::string source) { raw_.source = std::move(source); }

  std::uint32_t vertex(const ExactPoint3& p, const mpq_class& radius_squared = 0) {
    auto [it, inserted] = ids_.emplace(p, static_cast<std::uint32_t>(raw_.vertices.size()));
    if (inserted) {
      raw_.vertices.push_back(p);
      raw_.radius_squared.push_back(radius_squared);
    }
    return it->second;
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { raw_.triangles.push_back({a, b, c}); }
  // Two triangles a b c and a c d for the quad a b c d.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  void segment(std::uint32_t a, std::uint32_t b) { raw_.segments.push_back({a, b}); }
  void rule(std::uint32_t a, std::uint32_t b, IgnitionRule r, const ExactPoint3& point = {}) {
    raw_.border_rules.push_back({{a, b}, r, point});
  }
  const RawComplex& raw() const { return raw_; }
  RawComplex take() { return std::move(raw_); }

 private:
  struct LexLess {
    bool operator()(const ExactPoint3& a, const ExactPoint3& b) const { return compare_lex(a, b) < 0; }
  };
  RawComplex raw_;
  std::map<ExactPoint3, std::uint32_t, LexLess> ids_;
};

}  // namespace grassfire
