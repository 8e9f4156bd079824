// study_adversarial_inputs.cpp -- adversarial geometry through the pipelines the program
// runs, counting internal messages (docs/design.md 3: valid input never gets an internal
// invariant message; bad input gets a clear one).
//
// Usage: study_adversarial_inputs [--inputs N] [--seconds S] [--check-every K] [--hang-seconds H]
//                                 [--kind K]... [--out FILE] [--append]
// Kinds (each input i is a pure function of the kind and i):
//  - polygon:<kind> for every kind of shapes/adversarial_polygons.h: the polygon, validated
//    (invalid ones are generator misses, counted apart), then `edf2d --exact`'s pipeline
//    (compute_edf2d: exact polygon axis, EDF, measures) on every input, and the
//    definition-level check of the axis (medial2/polygon/polygon_axis_validate.h: R =
//    distance to the boundary at every node, leaves = convex corners) on every K-th input
//    (default K = 200: the check is exact at every node and edge against every boundary
//    segment, 10 to 50 times the pipeline's cost; K = 1 checks all); the diagrams rebuilt
//    by CGAL are counted (fallbacks);
//  - mesh:near-coplanar: an octahedron whose faces are split at a centroid lifted off the
//    face by 10^-k of its size (k in 3..15), written as OFF with 17 significant digits;
//  - mesh:slivers: a tetrahedron whose faces are split at a point 10^-k of the edge length
//    from one of their edges (sliver triangles);
//  - complex:singular-edges: books of 3..6 triangular pages on one spine, page directions
//    apart by 10^-k radians (near-coplanar pages at a singular edge), spine lengths 10^-j,
//    written as grassfire-complex JSON;
//  the 3D kinds run `burn3d --mesh-is-complex --method exact` / `burn3d --method exact`'s
//  pipeline (pipeline/burn3d.h); a mesh with a source at its vertex 0 (t0 = 0) and queries
//  at its vertices and half way to vertex 0 (the midpoints are off the bent mesh: located
//  at their nearest points), a book burning from its border.
// Outcomes per input: accepted; refused (an exception whose message names the input and
// carries no internal text: a clear message); internal (std::logic_error other than
// std::invalid_argument, or a message with internal text: CGAL, assertion, invariant,
// std::...). Each kind runs until N inputs (default 10^5; a generator miss is not an input)
// or S seconds (thread CPU; default no limit) are spent. Crashes and hangs: a fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL,
// SIGABRT) or one input running more than H seconds (wall clock, default 300) ends the run
// with exit status 3 and the input's name on stderr, so a run that finishes had neither;
// the slowest input of each kind (thread CPU seconds) is in the CSV. SIGTERM or SIGINT
// stops the run after the input running: the kind is written with the inputs it ran (its
// row marked `stopped`), the kinds after it are not run.
// Writes one CSV row per kind: kind,inputs,generator_misses,accepted,refused,internal,
// definition_checked,definition_failures,fallbacks,seconds,slowest_input_seconds,stopped
// (default experiments/results/adversarial_inputs.csv), rewritten after every kind
// (--append: adds the rows to an existing FILE, so kinds can be run apart) and prints every
// internal message (first 20 per kind) on stderr.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli.h"
#include "run_options.h"
#include "complex3/raw_complex.h"
#include "support/atomic_file.h"
#include "io/complex_json.h"
#include "support/cpu_clock.h"
#include "io/decimal_text.h"
#include "medial2/polygon/polygon_axis_validate.h"
#include "pipeline/burn3d.h"
#include "pipeline/edf2d.h"
#include "shapes/adversarial_polygons.h"
#include "shapes/validate_shape.h"

using namespace grassfire;

namespace {

constexpr const char* kUsage =
    "study_adversarial_inputs [--inputs N] [--seconds S] [--check-every K] [--hang-seconds H] [--kind K]...\n"
    "                         [--out FILE] [--append]\n"
    "adversarial polygons, meshes and complexes through the edf2d / burn3d pipelines;\n"
    "CSV of outcome counts per kind (default experiments/results/adversarial_inputs.csv)\n";

enum class Outcome { Accepted, Refused, Internal, Miss };

bool internal_text(const std::string& m) {
  for (const char* marker : {"CGAL", "assertion", "Assertion", "precondition", "Precondition", "violation", "invariant",
                             "std::", "basic_string", "vector::", "bad_alloc", "json.exception"})
    if (m.find(marker) != std::string::npos) return true;
  return false;
}

struct Tally {
  std::uint64_t inputs = 0, misses = 0, accepted = 0, refused = 0, internal = 0, definition_checked = 0,
                definition_failures = 0, fallbacks = 0;
  double seconds = 0, slowest = 0;
};

std::string digits17(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// --- meshes ---------------------------------------------------------------------------

using P3 = std::array<double, 3>;
P3 add(const P3& a, const P3& b, double s = 1) { return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}; }
P3 cross(const P3& a, const P3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double norm(const P3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

struct Mesh {
  std::vector<P3> v;
  std::vector<std::array<int, 3>> f;
};

std::string off_text(const Mesh& m) {
  std::ostringstream o;
  o << "OFF\n" << m.v.size() << ' ' << m.f.size() << " 0\n";
  for (const P3& p : m.v) o << digits17(p[0]) << ' ' << digits17(p[1]) << ' ' << digits17(p[2]) << '\n';
  for (const auto& t : m.f) o << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return o.str();
}

// Each face (a, b, c) becomes three triangles around the point q.
Mesh split_faces(const Mesh& in, const std::function<P3(const P3&, const P3&, const P3&)>& point) {
  Mesh m{in.v, {}};
  for (const auto& t : in.f) {
    const int q = static_cast<int>(m.v.size());
    m.v.push_back(point(in.v[t[0]], in.v[t[1]], in.v[t[2]]));
    m.f.push_back({t[0], t[1], q});
    m.f.push_back({t[1], t[2], q});
    m.f.push_back({t[2], t[0], q});
  }
  return m;
}

Mesh near_coplanar_mesh(std::mt19937_64& rng) {
  const double s = std::pow(10.0, std::uniform_real_distribution<double>(-3, 3)(rng));
  const P3 c = {std::uniform_real_distribution<double>(-1, 1)(rng), std::uniform_real_distribution<double>(-1, 1)(rng), 0.25};
  Mesh octa{{add(c, {s, 0, 0}), add(c, {-s, 0, 0}), add(c, {0, s, 0}), add(c, {0, -s, 0}), add(c, {0, 0, s}), add(c, {0, 0, -s})},
            {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  std::uniform_int_distribution<int> k(3, 15), sign(0, 1);
  return split_faces(octa, [&](const P3& a, const P3& b, const P3& cc) {
    const P3 g = {(a[0] + b[0] + cc[0]) / 3, (a[1] + b[1] + cc[1]) / 3, (a[2] + b[2] + cc[2]) / 3};
    const P3 n = cross(add(b, a, -1), add(cc, a, -1));
    const double lift = (sign(rng) ? 1 : -1) * s * std::pow(10.0, -k(rng));
    return add(g, n, lift / norm(n));
  });
}

Mesh sliver_mesh(std::mt19937_64& rng) {
  const double s = std::pow(10.0, std::uniform_real_distribution<double>(-2, 2)(rng));
  Mesh tet{{{0, 0, 0}, {s, 0, 0}, {0, s, 0}, {0, 0, s}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
  std::uniform_int_distribution<int> k(2, 15);
  std::uniform_real_distribution<double> along(0.05, 0.95);
  return split_faces(tet, [&](const P3& a, const P3& b, const P3& c) {
    // Near edge ab, inside the face: a + t (b - a) + e (c - (a + b) / 2) with e = 10^-k.
    const double t = along(rng), e = std::pow(10.0, -k(rng));
    const P3 m = add(a, add(b, a, -1), t);
    return add(m, add(c, {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2}, -1), e);
  });
}

// --- complexes ------------------------------------------------------------------------

mpq_class decimal(double x) { return mpq_class(x); }  // a double, exactly

RawComplex singular_book(std::mt19937_64& rng) {
  const int pages = std::uniform_int_distribution<int>(3, 6)(rng);
  const double spine = std::pow(10.0, -std::uniform_int_distribution<int>(0, 6)(rng));
  const double gap = std::pow(10.0, -std::uniform_int_distribution<int>(1, 12)(rng));
  RawComplex r;
  r.source = "book";
  r.vertices = {{0, 0, 0}, {0, 0, decimal(spine)}};
  double angle = 0;
  for (int p = 0; p < pages; ++p) {
    // Two pages close together, the rest spread out.
    angle += p == 1 ? gap : 2.0 * 3.14159265358979 / pages;
    const double w = std::uniform_real_distribution<double>(0.5, 2)(rng);
    r.vertices.push_back({decimal(w * std::cos(angle)), decimal(w * std::sin(angle)), decimal(spine / 2)});
    r.triangles.push_back({0, 1, static_cast<std::uint32_t>(2 + p)});
  }
  r.radius_squared.assign(r.vertices.size(), 0);
  return r;
}

// --- running --------------------------------------------------------------------------

// The input running now, for the crash and hang reports: a fatal signal writes its name
// and exits 3 (async-signal-safe: write and _exit on a fixed buffer); a thread checks five
// times a second that no input has run more than the limit (wall clock), else does the same.
class Watchdog {
 public:
  explicit Watchdog(double limit_seconds) : limit_(limit_seconds) {
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, on_signal);
    for (int sig : {SIGTERM, SIGINT}) std::signal(sig, on_stop);
    thread_ = std::thread([this] {
      while (!quit_) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        const std::int64_t started = started_ms_.load();
        if (started >= 0 && now_ms() - started > static_cast<std::int64_t>(limit_ * 1000)) report("hang (over the time limit)");
      }
    });
  }
  ~Watchdog() {
    quit_ = true;
    thread_.join();
  }
  void start(const std::string& name) {
    std::snprintf(current_, sizeof current_, "%s", name.c_str());
    started_ms_ = now_ms();
  }
  void stop() { started_ms_ = -1; }
  static bool stop_requested() { return stop_requested_ != 0; }

 private:
  static std::int64_t now_ms() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  static void report(const char* what) {
    const char* head = "study_adversarial_inputs: ";
    for (const char* part : {head, what, " at ", static_cast<const char*>(current_), "\n"})
      if (::write(2, part, std::strlen(part)) < 0) break;
    ::_exit(3);
  }
  static void on_signal(int) { report("crash (fatal signal)"); }
  static void on_stop(int) { stop_requested_ = 1; }
  static inline volatile std::sig_atomic_t stop_requested_ = 0;
  static inline char current_[256] = "(none)";
  double limit_;
  std::atomic<std::int64_t> started_ms_{-1};
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

Outcome classify(const std::string& message, bool logic, const std::string& name, std::vector<std::string>& findings) {
  if (!logic && !internal_text(message)) return Outcome::Refused;
  if (findings.size() < 20) findings.push_back(name + ": " + message);
  return Outcome::Internal;
}

template <class F>
Outcome guarded(const std::string& name, std::vector<std::string>& findings, F&& f) {
  try {
    f();
    return Outcome::Accepted;
  } catch (const InvalidShapeError&) {
    return Outcome::Miss;
  } catch (const std::invalid_argument& e) {
    return classify(e.what(), false, name, findings);
  } catch (const std::logic_error& e) {
    return classify(std::string("logic_error: ") + e.what(), true, name, findings);
  } catch (const std::exception& e) {
    return classify(e.what(), false, name, findings);
  }
}

Outcome run_polygon(const std::string& kind, std::uint64_t i, bool check, Tally& t, std::vector<std::string>& findings) {
  Shape2 s = adversarial_polygon(kind, i);
  return guarded(s.name, findings, [&] {
    validate_shape(s, s.name);
    Edf2dOptions o;
    o.axis = AxisMethod::ExactPolygon;
    const Edf2dResult r = compute_edf2d(s, o);
    t.fallbacks += r.polygon_report.voronoi_fallbacks;
    if (!check) return;
    ++t.definition_checked;
    const AxisValidation v = validate_polygon_axis(*r.graph);
    if (!v.ok()) {
      ++t.definition_failures;
      if (findings.size() < 20) findings.push_back(s.name + ": definition check: " + v.failures.front());
    }
  });
}

// A point as a CSV row with the digits off_text writes (io/decimal_text.h: the same point).
CsvPoint row(const P3& p, std::size_t line) {
  CsvPoint c;
  c.line = line;
  c.point = {*parse_exact_decimal(digits17(p[0])), *parse_exact_decimal(digits17(p[1])),
             *parse_exact_decimal(digits17(p[2]))};
  c.t0 = 0;
  return c;
}

// The burn3d pipeline on a file holding `text`; a mesh gets a source at its vertex 0 and
// queries at its other vertices and at their midpoints with vertex 0.
Outcome run_burn3d(const std::string& path, const std::string& text, const Mesh* mesh, std::vector<std::string>& findings) {
  std::ofstream(path) << text;
  return guarded(path, findings, [&] {
    Burn3dSetup setup;
    setup.input = path;
    setup.method = "exact";
    setup.mesh_is_complex = mesh != nullptr;
    setup.sources.name = "sources";
    setup.queries.name = "queries";
    if (mesh) {
      setup.sources.rows.push_back(row(mesh->v[0], 1));
      for (std::size_t v = 1; v < mesh->v.size(); ++v) {
        setup.queries.rows.push_back(row(mesh->v[v], 2 * v));
        setup.queries.rows.push_back(row(add(mesh->v[v], add(mesh->v[0], mesh->v[v], -1), 0.5), 2 * v + 1));
      }
    }
    (void)burn3d(setup);
  });
}

}  // namespace

int run(int argc, char** argv) {
  experiments::RunOptionSpec spec{
      {"--append"}, {"--inputs", "--seconds", "--check-every", "--hang-seconds", "--kind", "--out"}, 0, 0};
  spec.shard = false;
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, spec);
  const std::uint64_t inputs = cmd.count("--inputs", 100000);
  const double seconds = cmd.number("--seconds", INFINITY);
  const std::uint64_t check_every = cmd.count("--check-every", 200);
  const double hang_seconds = cmd.number("--hang-seconds", 300);
  if (check_every == 0) throw experiments::UsageError("--check-every must be at least 1");
  std::vector<std::string> kinds = cmd.values("--kind");
  const std::string out = cmd.text("--out", std::string(GF_PROJECT_DATA) + "/../experiments/results/adversarial_inputs.csv");
  const bool append = cmd.flag("--append");
  if (kinds.empty()) {
    for (const std::string& k : adversarial_polygon_kinds()) kinds.push_back("polygon:" + k);
    for (const char* k : {"mesh:near-coplanar", "mesh:slivers", "complex:singular-edges"}) kinds.push_back(k);
  }
  const std::string tmp = std::filesystem::temp_directory_path().string() + "/gf_adversarial_" + std::to_string(::getpid());
  std::ostringstream csv;
  if (append) {
    std::ifstream old(out);
    if (!old) throw std::invalid_argument("--append: cannot read " + out);
    csv << old.rdbuf();
  } else {
    csv << "kind,inputs,generator_misses,accepted,refused,internal,definition_checked,definition_failures,fallbacks,"
           "seconds,slowest_input_seconds,stopped\n";
  }
  Watchdog watchdog(hang_seconds);
  for (const std::string& kind : kinds) {
    if (Watchdog::stop_requested()) break;
    Tally t;
    std::vector<std::string> findings;
    const double t0 = thread_seconds();
    // N valid inputs (generator misses do not count), at most 10 N tries.
    for (std::uint64_t i = 0; t.inputs < inputs && i < 10 * inputs && thread_seconds() - t0 < seconds &&
                              !Watchdog::stop_requested();
         ++i) {
      std::mt19937_64 rng(i * 0x9e3779b97f4a7c15ull + std::hash<std::string>{}(kind));
      watchdog.start(kind + " input " + std::to_string(i));
      const double input_start = thread_seconds();
      Outcome o;
      if (kind.rfind("polygon:", 0) == 0) {
        o = run_polygon(kind.substr(8), i, i % check_every == 0, t, findings);
      } else if (kind == "mesh:near-coplanar") {
        const Mesh m = near_coplanar_mesh(rng);
        o = run_burn3d(tmp + ".off", off_text(m), &m, findings);
      } else if (kind == "mesh:slivers") {
        const Mesh m = sliver_mesh(rng);
        o = run_burn3d(tmp + ".off", off_text(m), &m, findings);
      } else if (kind == "complex:singular-edges") {
        o = run_burn3d(tmp + ".json", complex_json_text(singular_book(rng)), nullptr, findings);
      } else {
        throw std::invalid_argument("unknown kind " + kind);
      }
      t.slowest = std::max(t.slowest, thread_seconds() - input_start);
      watchdog.stop();
      if (o == Outcome::Miss) {
        ++t.misses;
        continue;
      }
      ++t.inputs;
      t.accepted += o == Outcome::Accepted;
      t.refused += o == Outcome::Refused;
      t.internal += o == Outcome::Internal;
    }
    t.seconds = thread_seconds() - t0;
    for (const std::string& f : findings) std::cerr << kind << ": " << f << "\n";
    csv << kind << ',' << t.inputs << ',' << t.misses << ',' << t.accepted << ',' << t.refused << ',' << t.internal << ','
        << t.definition_checked << ',' << t.definition_failures << ',' << t.fallbacks << ',' << t.seconds << ','
        << t.slowest << ',' << (Watchdog::stop_requested() ? "stopped" : "") << "\n";
    std::cout << kind << ": " << t.inputs << " inputs (" << t.misses << " generator misses), " << t.accepted
              << " accepted, " << t.refused << " refused, " << t.internal << " internal, " << t.definition_checked
              << " checked against the definition, " << t.definition_failures << " definition failures, " << t.fallbacks
              << " fallbacks, " << t.seconds << " s (slowest input " << t.slowest << " s)\n"
              << std::flush;
    write_file_atomically(out, csv.str());  // the kinds done so far survive a run stopped later
  }
  for (const char* ext : {".off", ".json"}) std::filesystem::remove(tmp + ext);
  write_file_atomically(out, csv.str());
  std::cout << "wrote " << out << "\n";
  return 0;
}

int main(int argc, char** argv) {
  return experiments::guarded_main(argc, argv, "study_adversarial_inputs", kUsage, run);
}
