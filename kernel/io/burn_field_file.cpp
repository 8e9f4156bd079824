// burn_field_file.cpp -- see burn_field_file.h.
#include "io/burn_field_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "io/complex_text.h"
#include "io/json_numbers.h"
#include "io/json_text.h"
#include "support/atomic_file.h"
#include "support/format_error.h"

namespace grassfire {
namespace {

constexpr const char* kFormat = "grassfire-burn3d-field";
constexpr int kVersion = 1;

struct Fnv1a {
  std::uint64_t h = 1469598103934665603ULL;
  void bytes(const std::string& s) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
    h = (h ^ 0xffu) * 1099511628211ULL;  // a separator: "ab","c" differs from "a","bc"
  }
  void number(std::uint64_t n) { bytes(std::to_string(n)); }
};

[[noreturn]] void refuse(const std::string& path, const std::string& problem) { throw FormatError(path + ": " + problem); }

const nlohmann::json& member(const nlohmann::json& j, const char* key, const std::string& path) {
  if (!j.is_object() || !j.contains(key)) refuse(path, std::string("no member \"") + key + "\"");
  return j[key];
}

// An array of numbers (null: +infinity) of `size` entries (any size when size is npos).
std::vector<double> read_doubles(const nlohmann::json& j, const char* key, std::size_t size, const std::string& path) {
  const nlohmann::json& a = member(j, key, path);
  if (!a.is_array() || (size != std::string::npos && a.size() != size))
    refuse(path, std::string("\"") + key + "\" is not an array of " + std::to_string(size) + " numbers");
  std::vector<double> out;
  out.reserve(a.size());
  for (const nlohmann::json& v : a) {
    if (v.is_null()) {
      out.push_back(std::numeric_limits<double>::infinity());
    } else if (v.is_number()) {
      out.push_back(v.get<double>());
    } else {
      refuse(path, std::string("\"") + key + "\" holds a value that is not a number");
    }
  }
  return out;
}

template <class Int>
std::vector<Int> read_integers(const nlohmann::json& j, const char* key, std::size_t size, const std::string& path) {
  const nlohmann::json& a = member(j, key, path);
  if (!a.is_array() || (size != std::string::npos && a.size() != size))
    refuse(path, std::string("\"") + key + "\" is not an array of " + std::to_string(size) + " indices");
  std::vector<Int> out;
  out.reserve(a.size());
  for (const nlohmann::json& v : a) {
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() > std::numeric_limits<Int>::max())
      refuse(path, std::string("\"") + key + "\" holds a value that is not an index");
    out.push_back(static_cast<Int>(v.get<std::uint64_t>()));
  }
  return out;
}

nlohmann::json complex_counts(const MedialComplex& mc) {
  return {{"vertices", mc.vertex_count()}, {"edges", mc.edge_count()}, {"triangles", mc.triangle_count()},
          {"digest", complex_digest(mc)}};
}

// The complex's counts, then its digest, against the file's.
void check_same_complex(const nlohmann::json& file, const MedialComplex& mc, const std::string& path) {
  const nlohmann::json& c = member(file, "complex", path);
  const nlohmann::json mine = complex_counts(mc);
  for (const char* key : {"vertices", "edges", "triangles"}) {
    const nlohmann::json& n = member(c, key, path);
    if (n != mine[key])
      refuse(path, "the field was burned on another complex (" + n.dump() + " " + key + ", the input has " +
                       mine[key].dump() + ")");
  }
  if (member(c, "digest", path) != mine["digest"])
    refuse(path, "the field was burned on another complex (its digest " + c["digest"].dump() + ", the input's \"" +
                     mine["digest"].get<std::string>() + "\"): the same counts, other coordinates or cells");
}

}  // namespace

std::string complex_digest(const MedialComplex& mc) {
  Fnv1a h;
  h.number(mc.vertex_count());
  for (const ComplexVertex& v : mc.vertices()) {
    for (const mpq_class* c : {&v.exact.x, &v.exact.y, &v.exact.z}) h.bytes(c->get_str());
    h.bytes(v.radius_squared.get_str());
  }
  h.number(mc.edge_count());
  for (const ComplexEdge& e : mc.edges()) {
    h.number(e.v[0]), h.number(e.v[1]);
    h.number(static_cast<unsigned>(e.stratum)), h.number(static_cast<unsigned>(e.rule));
    if (e.rule == IgnitionRule::DistanceToPoint)
      for (const mpq_class* c : {&e.rule_point.x, &e.rule_point.y, &e.rule_point.z}) h.bytes(c->get_str());
  }
  h.number(mc.triangle_count());
  for (const ComplexTriangle& t : mc.triangles())
    for (std::uint32_t v : t.v) h.number(v);
  h.number(mc.sheets().size());
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h.h));
  return text;
}

void write_burn_field(const MedialComplex& mc, const DiscreteBurning& d, const std::string& input,
                      const std::string& path) {
  if (!d.source_points.empty())
    throw std::invalid_argument("--field writes a burning from the border only (no --sources): it is what curves3d, "
                                "paths3d and prune3d burn");
  nlohmann::json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["input"] = input;
  j["method"] = "discrete";
  j["spacing"] = d.spacing;
  j["complex"] = complex_counts(mc);
  j["vertex_bt"] = finite_or_null(d.vertex_bt);
  j["vertex_et"] = finite_or_null(d.vertex_et);
  j["steiner_bt"] = finite_or_null(d.steiner_bt);
  j["edge_first_steiner"] = d.edge_first_steiner;
  j["arrival_time"] = finite_or_null(d.arrival_time);
  j["vertex_slot"] = d.vertex_slot;
  j["edge_slot"] = d.edge_slot;
  j["arrival_from"] = d.arrival_from;
  j["burn_slot"] = d.burn_slot;
  j["stats"] = {{"steiner_points", d.stats.steiner_points},
                {"arrivals_pushed", d.stats.pushes},
                {"arrivals_popped", d.stats.pops},
                {"seconds", d.stats.seconds}};
  write_file_atomically(path, j.dump() + "\n");
}

DiscreteBurning read_burn_field(const std::string& path, const MedialComplex& mc) {
  const nlohmann::json j = parse_json_text(read_text_file(path), path);
  if (!j.is_object() || j.value("format", "") != kFormat)
    refuse(path, std::string("not a burning field (format \"") + kFormat + "\", written by burn3d --field)");
  if (j.value("version", 0) != kVersion) refuse(path, "version " + member(j, "version", path).dump() + " is not 1");
  if (member(j, "method", path) != "discrete")
    refuse(path, "a field file holds a discrete burning; method " + j["method"].dump() + " cannot be read back");
  check_same_complex(j, mc, path);
  const std::size_t nv = mc.vertex_count(), ne = mc.edge_count();
  DiscreteBurning d;
  const nlohmann::json& h = member(j, "spacing", path);
  if (!h.is_number() || !(h.get<double>() > 0) || !std::isfinite(h.get<double>()))
    refuse(path, "\"spacing\" is not a positive number");
  d.spacing = h.get<double>();
  d.vertex_bt = read_doubles(j, "vertex_bt", nv, path);
  d.vertex_et = read_doubles(j, "vertex_et", nv, path);
  d.edge_first_steiner = read_integers<std::uint64_t>(j, "edge_first_steiner", ne + 1, path);
  d.vertex_slot = read_integers<std::uint64_t>(j, "vertex_slot", nv + 1, path);
  d.edge_slot = read_integers<std::uint64_t>(j, "edge_slot", ne + 1, path);
  if (d.edge_first_steiner.front() != 0 || d.vertex_slot.front() != 0)
    refuse(path, "\"edge_first_steiner\" and \"vertex_slot\" must start at 0");
  for (std::size_t e = 0; e < ne; ++e)
    if (d.edge_first_steiner[e + 1] < d.edge_first_steiner[e]) refuse(path, "\"edge_first_steiner\" decreases");
  const std::size_t steiner = d.edge_first_steiner.back();
  d.steiner_bt = read_doubles(j, "steiner_bt", steiner, path);
  d.arrival_time = read_doubles(j, "arrival_time", std::string::npos, path);
  const std::size_t slots = d.arrival_time.size();
  // Every slot range the burning's accessors index lies inside arrival_time.
  for (std::size_t v = 0; v < nv; ++v)
    if (d.vertex_slot[v + 1] != d.vertex_slot[v] + mc.link_elements(static_cast<std::uint32_t>(v)).size())
      refuse(path, "\"vertex_slot\" does not match the links of the complex");
  for (std::size_t e = 0; e < ne; ++e) {
    const std::uint64_t k = 2 + mc.edge_triangles(static_cast<std::uint32_t>(e)).size();
    if (d.edge_slot[e] < d.vertex_slot.back() || d.edge_slot[e + 1] != d.edge_slot[e] + k * (d.edge_first_steiner[e + 1] - d.edge_first_steiner[e]))
      refuse(path, "\"edge_slot\" does not match the edges of the complex");
  }
  if (d.edge_slot.back() != slots) refuse(path, "\"arrival_time\" has " + std::to_string(slots) + " slots, the complex " +
                                                std::to_string(d.edge_slot.back()));
  d.arrival_from = read_integers<std::uint32_t>(j, "arrival_from", slots, path);
  d.burn_slot = read_integers<std::uint32_t>(j, "burn_slot", nv + steiner, path);
  const std::uint64_t points = nv + steiner;
  for (std::uint32_t from : d.arrival_from)
    if (from != kNoIndex && from >= points) refuse(path, "\"arrival_from\" names a graph point that does not exist");
  auto check_burn_slot = [&](std::uint64_t x, std::uint64_t elements) {
    const std::uint32_t s = d.burn_slot[x];
    if (s != kNoIndex && s != DiscreteBurning::kIgnited && s >= elements)
      refuse(path, "\"burn_slot\" names a link element that does not exist");
  };
  for (std::size_t v = 0; v < nv; ++v) check_burn_slot(v, d.vertex_slot[v + 1] - d.vertex_slot[v]);
  for (std::size_t e = 0; e < ne; ++e)
    for (std::uint64_t x = d.edge_first_steiner[e]; x < d.edge_first_steiner[e + 1]; ++x)
      check_burn_slot(nv + x, 2 + mc.edge_triangles(static_cast<std::uint32_t>(e)).size());
  if (const nlohmann::json* s = j.contains("stats") ? &j["stats"] : nullptr; s && s->is_object()) {
    d.stats.steiner_points = s->value("steiner_points", std::uint64_t{0});
    d.stats.pushes = s->value("arrivals_pushed", std::uint64_t{0});
    d.stats.pops = s->value("arrivals_popped", std::uint64_t{0});
    d.stats.seconds = s->value("seconds", 0.0);
  }
  return d;
}

}  // namespace grassfire
