// targets.cpp -- see targets.h.
#include "targets.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "medial3/convex/convex_polyhedron_axis.h"
#include "io/halfspace_list.h"
#include "medial3/mesh/mesh_checks.h"
#include "medial3/balls/union_of_balls_axis.h"
#include "complex3/medial_complex.h"
#include "io/complex_json.h"
#include "io/complex_ma.h"
#include "io/disk_list.h"
#include "io/mesh_io.h"
#include "io/shape_json.h"
#include "io/shape_wkt.h"
#include "medial2/disks/disk_union_axis.h"
#include "shapes/validate_shape.h"

namespace grassfire::fuzz {

namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Files of `dir` whose extension is one of `exts`, sorted by size, at most `limit`.
std::vector<fs::path> files(const std::string& dir, const std::vector<std::string>& exts, std::size_t limit = 1000) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && std::find(exts.begin(), exts.end(), e.path().extension().string()) != exts.end())
      out.push_back(e.path());
  std::sort(out.begin(), out.end(), [](const fs::path& a, const fs::path& b) {
    return std::make_pair(fs::file_size(a), a) < std::make_pair(fs::file_size(b), b);
  });
  if (out.size() > limit) out.resize(limit);
  return out;
}

Target make(const std::string& name, const std::string& ext, const std::vector<std::vector<fs::path>>& sources,
            std::function<void(const std::string&, const std::string&)> run) {
  Target t{name, ext, {}, {}, std::move(run)};
  for (const auto& group : sources)
    for (const fs::path& p : group) {
      t.corpus.push_back(file_text(p));
      t.corpus_files.push_back(p.string());
    }
  if (t.corpus.empty()) throw std::runtime_error("fuzz target " + name + ": empty corpus");
  return t;
}

// The grassfire-complex JSON corpus is small (tests/data/3d/*.json): add every readable .ma
// file written in that format (complex_json_text), so that the mutations start from
// documents with hundreds of vertices, triangles and segments too.
void add_complex_json_of_ma(Target& t, const std::vector<std::vector<fs::path>>& sources) {
  for (const auto& group : sources)
    for (const fs::path& p : group) {
      RawComplex raw;
      try {
        raw = parse_ma(file_text(p), p.string());
      } catch (const std::exception&) {
        continue;  // the bad_*.ma files of the test data
      }
      t.corpus.push_back(complex_json_text(raw));
      t.corpus_files.push_back(p.string() + " (as grassfire-complex JSON)");
    }
}

void mesh_target(const std::string& bytes, const std::string& source, bool deep) {
  const TriangleMesh3 m = parse_triangle_mesh(bytes, source);
  require_closed_manifold(m);
  mesh_orientation(m);
  if (deep) convex_polyhedron_from_mesh(m);
}

void shape_target(Shape2 shape, const std::string& source) { validate_shape(shape, source); }

}  // namespace

std::vector<Target> fuzz_targets(const std::string& test_data, const std::string& project_data, bool deep) {
  const std::string t3 = test_data + "/3d", b3 = test_data + "/builders3";
  const auto mesh = [deep](const std::string& bytes, const std::string& source) { mesh_target(bytes, source, deep); };
  std::vector<Target> targets;
  targets.push_back(make("off", "off", {files(t3, {".off"}), files(b3, {".off"}), files(project_data + "/meshes", {".off"})}, mesh));
  targets.push_back(make("ply", "ply", {files(t3, {".ply"})}, mesh));
  targets.push_back(make("obj", "obj", {files(t3, {".obj"})}, mesh));
  targets.push_back(make("stl", "stl", {files(test_data + "/stl", {".stl"})}, mesh));
  targets.push_back(make("balls", "cin", {files(t3, {".cin"}), files(b3, {".balls"}), files(project_data + "/balls", {".cin"})},
                         [deep](const std::string& bytes, const std::string& source) {
                           const BallSet b = parse_ball_list(bytes, source);
                           if (deep) union_of_balls_axis(b);
                         }));
  targets.push_back(make("halfspaces", "hs", {files(b3, {".hs"})}, [deep](const std::string& bytes, const std::string& source) {
    const ConvexPolyhedron p = parse_halfspaces(bytes, source);
    if (deep) convex_polyhedron_axis(p);
  }));
  targets.push_back(make("ma", "ma", {files(t3, {".ma"}), files(project_data + "/ma", {".ma"})},
                         [](const std::string& bytes, const std::string& source) {
                           const MedialComplex mc(parse_ma(bytes, source));
                           mc.validate();
                         }));
  Target complex_json = make("complex_json", "json", {files(t3, {".json"})}, [](const std::string& bytes, const std::string& source) {
    const MedialComplex mc(parse_complex_json(bytes, source));
    mc.validate();
  });
  add_complex_json_of_ma(complex_json, {files(t3, {".ma"}), files(project_data + "/ma", {".ma"})});
  targets.push_back(std::move(complex_json));
  targets.push_back(make("shape_json", "json", {files(test_data + "/shapes", {".json"}), files(project_data + "/shapes2d", {".json"}, 6)},
                         [](const std::string& bytes, const std::string& source) { shape_target(parse_shape_json(bytes, source), source); }));
  targets.push_back(make("shape_wkt", "wkt", {files(test_data + "/shapes", {".wkt", ".txt"})},
                         [](const std::string& bytes, const std::string& source) { shape_target(parse_shape_wkt(bytes, source), source); }));
  targets.push_back(make("disks", "txt", {files(test_data + "/disks", {".txt"})}, [deep](const std::string& bytes, const std::string& source) {
    const DiskList d = parse_disk_list(bytes, source);
    if (deep) disk_union_axis(d);
  }));
  return targets;
}

}  // namespace grassfire::fuzz
