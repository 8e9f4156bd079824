// bench_polygon_axis -- the exact polygon axis (+ EDF) against bare Boost.Polygon
// construct_voronoi and bare CGAL Segment_Delaunay_graph_2 on the same polygon.
//
// Input: smooth closed polygons with integer vertices (exact on a decimal grid, so the
// Boost path runs), at 10^3, 10^4, 10^5 segments, in two variants per size: the wavy
// circle r(t) = 10^6 (1 + 0.1 sin 7t), which is mirror-symmetric in x = 0 (integer
// rounding keeps the symmetry: thousands of exactly equal burn times, proved by value
// classes, burn2/burn_times.h), and the phase-shifted r(t) = 10^6 (1 + 0.1 sin(7t + 0.3)),
// which has no symmetry (generic input), and the "unrounded" variant: the shifted curve's
// points as computed (full-mantissa doubles, no decimal or int32 binary frame; its near-0
// coordinates such as 10^6 cos(pi/2) ~ 6e-11 with 53 significant bits span ~107 bits once
// scaled to integers, beyond the wide binary frame: the mp binary policy of polygon_axis.h,
// Boost's builder with the mp traits; run up to --max-unrounded segments, default 100000),
// and the "offset" variant: the shifted curve centred at (3 10^6, 3 10^6),
// its points as computed (full-mantissa doubles away from 0: 2^K x them span ~54 bits, the
// wide binary policy runs Boost's builder on 64-bit integers). Each row runs: Boost alone (on the rounded
// polygon for "unrounded"); CGAL SDG alone (bulk insert_segments, CGAL's default filtered
// traits without intersections) unless --max-cgal is below the size; the exact axis (polygon_axis.h); the exact axis plus the extended grassfire
// (extended_grassfire.h).
// Output (stdout): CSV segments,shape,boost_s,cgal_sdg_s,axis_s,axis_plus_edf_s,
// axis_ratio,ratio_to_boost,boost_cpu_s,axis_plus_edf_cpu_s,cpu_ratio,uncertified,
// peak_mem_mb,ratio_to_decimal,construction,load (the 1-minute load average when the row
// was measured, machine_load.h); ratio_to_decimal (unrounded and offset rows)
// = the row's axis_plus_edf_cpu_s / the shifted (decimal) row's of the same size;
// construction = the one the input policy chose (polygon_axis.h); shape is "symmetric" or "shifted"; axis_ratio = axis_s / boost_s,
// ratio_to_boost = axis_plus_edf_s / boost_s (wall clock), cpu_ratio the same in thread
// CPU time (what to read on a loaded machine); uncertified = ties of the burning and
// contractions of the axis that no stage could prove (zero is the goal, docs/design.md 3); an
// empty cgal_sdg_s means skipped; peak_mem_mb is the process's peak resident size after
// the row. Each time is the best of --repeat runs (default 1). stderr: the axis report
// (where its CPU time goes: Voronoi, values, value classes, burning; contractions, double-
// double and Arb refinements), the engine's comparison counts and the value classes.
// Usage: bench_polygon_axis [--sizes 1000,10000,100000] [--max-cgal N] [--max-unrounded N]
//        [--repeat K] [--shapes symmetric,shifted,offset,unrounded] (the rows to run; the
//        ratio_to_decimal column needs "shifted")
#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>
#include <sys/resource.h>

#include <boost/polygon/point_data.hpp>
#include <boost/polygon/segment_data.hpp>
#include <boost/polygon/voronoi.hpp>
#include <algorithm>
#include <chrono>
#include <memory>
#include <utility>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "burn2/extended_grassfire.h"
#include "support/cpu_clock.h"
#include "medial2/polygon/polygon_axis.h"
#include "medial2/polygon/polygon_axis_geometry.h"
#include "medial2/polygon/polygon_axis_symmetry.h"
#include "cli.h"
#include "machine_load.h"

using namespace grassfire;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

Shape2 wavy_circle(int n, double phase, bool round = true, double centre = 0) {
  Shape2 s;
  s.name = "wavy circle " + std::to_string(n);
  Ring r;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n, rad = 1e6 * (1 + 0.1 * std::sin(7 * t + phase));
    const double x = centre + rad * std::cos(t), y = centre + rad * std::sin(t);
    r.points.push_back(round ? Point2{std::round(x), std::round(y)} : Point2{x, y});
  }
  s.rings.push_back(r);
  return s;
}

struct Times {
  double wall, cpu;
};

Times bare_boost(const Shape2& s) {
  namespace bp = boost::polygon;
  const auto& p = s.rings[0].points;
  std::vector<bp::segment_data<int>> seg;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2 a = p[i], b = p[(i + 1) % p.size()];
    seg.emplace_back(bp::point_data<int>(int(a.x), int(a.y)), bp::point_data<int>(int(b.x), int(b.y)));
  }
  const double t0 = now(), c0 = thread_seconds();
  bp::voronoi_diagram<double> vd;
  bp::construct_voronoi(seg.begin(), seg.end(), &vd);
  return {now() - t0, thread_seconds() - c0};
}

double bare_cgal(const Shape2& s) {
  using K = CGAL::Simple_cartesian<double>;
  using Sdg = CGAL::Segment_Delaunay_graph_2<CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<K>>;
  const auto& p = s.rings[0].points;
  std::vector<K::Segment_2> seg;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2 a = p[i], b = p[(i + 1) % p.size()];
    seg.emplace_back(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y));
  }
  const double t0 = now();
  Sdg sdg;
  sdg.insert_segments(seg.begin(), seg.end());
  return now() - t0;
}

double peak_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

struct Row {
  double boost_s = 1e300, cgal_s = 1e300, axis_s = 1e300, both_s = 1e300;
  double boost_cpu = 1e300, both_cpu = 1e300, classes_cpu = 0, burn_cpu = 0;
};

void report_details(int n, const char* shape, const PolygonAxisReport& rep, const Row& row, const MedialGraph& g,
                    const GrassfireResult& r) {
  const NumberStats& st = r.stats();
  std::fprintf(stderr,
               "n=%d %s: CPU boost %.4f s; axis %.4f s (voronoi %.4f, values %.4f), classes %.4f s, burning %.4f s; "
               "%llu nodes, %llu contracted, %llu double-double and %llu Arb refinements, %llu uncertified "
               "contractions; engine: filter %llu, x87 %llu, mpfr %llu, exact zero %llu (by class %llu), "
               "uncertified %llu, max bits %llu\n",
               n, shape, row.boost_cpu, rep.total_seconds, rep.voronoi_seconds, rep.values_seconds, row.classes_cpu,
               row.burn_cpu, (unsigned long long)rep.nodes, (unsigned long long)rep.contracted_edges,
               (unsigned long long)rep.dd_refinements, (unsigned long long)rep.ball_refinements,
               (unsigned long long)rep.uncertified_contractions,
               (unsigned long long)st.filter_decided, (unsigned long long)st.extended_decided,
               (unsigned long long)st.mpfr_decided, (unsigned long long)st.exact_zero,
               (unsigned long long)st.class_zero, (unsigned long long)st.uncertified_zero,
               (unsigned long long)st.max_bits_used);
  if (rep.construction == AxisConstruction::BoostPolygonMp)
    std::fprintf(stderr, "  mp traits: %d-bit integers, %d-bit floats, filter stage %s, %llu decisions by MPFR\n",
                 rep.mp_input_bits, rep.mp_float_bits, rep.mp_filtered ? "completed" : "undecided (MPFR rerun)",
                 (unsigned long long)rep.mp_fallbacks);
  if (const auto* geo = dynamic_cast<const PolygonAxisGeometry*>(&g.geometry())) {
    const AxisValueClasses& vc = geo->value_classes();
    std::fprintf(stderr, "  symmetries %u: nodes in shared classes %llu / %u, edges %llu / %u, unmapped %llu + %llu\n",
                 vc.symmetries, (unsigned long long)vc.nodes_in_shared_classes, g.node_count(),
                 (unsigned long long)vc.edges_in_shared_classes, g.edge_count(), (unsigned long long)vc.unmapped_nodes,
                 (unsigned long long)vc.unmapped_edges);
  }
}

constexpr const char* kUsage =
    "usage: bench_polygon_axis [--sizes a,b,c] [--max-cgal N] [--max-unrounded N] [--repeat K] [--shapes a,b]\nthe exact polygon axis (+ EDF) against bare Boost.Polygon construct_voronoi and bare CGAL Segment_Delaunay_graph_2 on the same polygon.\n(CSV columns and details: the header of experiments/bench_polygon_axis.cpp)\n";

int run(int argc, char** argv) {
  std::vector<int> sizes{1000, 10000, 100000};
  long max_cgal = 100000, max_unrounded = 100000;
  std::string shapes = ",symmetric,shifted,offset,unrounded,";
  int repeat = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--max-cgal") {
      max_cgal = std::atol(argv[i + 1]);
    } else if (a == "--max-unrounded") {
      max_unrounded = std::atol(argv[i + 1]);
    } else if (a == "--shapes") {
      shapes = "," + std::string(argv[i + 1]) + ",";
    } else if (a == "--repeat") {
      repeat = std::max(1, std::atoi(argv[i + 1]));
    } else if (a == "--sizes") {
      sizes.clear();
      std::stringstream ss(argv[i + 1]);
      for (std::string t; std::getline(ss, t, ',');) sizes.push_back(std::atoi(t.c_str()));
    } else {
      std::fputs(kUsage, stderr);
      return 2;
    }
  }
  std::printf("segments,shape,boost_s,cgal_sdg_s,axis_s,axis_plus_edf_s,axis_ratio,ratio_to_boost,boost_cpu_s,"
              "axis_plus_edf_cpu_s,cpu_ratio,uncertified,peak_mem_mb,ratio_to_decimal,construction,load\n");
  for (int n : sizes) {
    double decimal_cpu = 0;
    for (const auto& [shape, phase] :
         {std::pair<const char*, double>{"symmetric", 0.0}, {"shifted", 0.3}, {"offset", 0.3}, {"unrounded", 0.3}}) {
      const bool unrounded = std::string(shape) == "unrounded", offset = std::string(shape) == "offset";
      if (unrounded && n > max_unrounded) continue;
      if (shapes.find(std::string(",") + shape + ",") == std::string::npos) continue;
      const double centre = offset ? 3e6 : 0;
      const Shape2 s = wavy_circle(n, phase, !unrounded && !offset, centre), rounded = wavy_circle(n, phase, true, centre);
      Row row;
      PolygonAxisReport rep;
      std::unique_ptr<MedialGraph> g;
      std::unique_ptr<GrassfireResult> r;
      for (int k = 0; k < repeat; ++k) {
        const Times b = bare_boost(rounded);
        row.boost_s = std::min(row.boost_s, b.wall);
        row.boost_cpu = std::min(row.boost_cpu, b.cpu);
        if (n <= max_cgal) row.cgal_s = std::min(row.cgal_s, bare_cgal(s));
        double t0 = now();
        g = std::make_unique<MedialGraph>(exact_polygon_axis(s, {}, &rep));
        row.axis_s = std::min(row.axis_s, now() - t0);
        g.reset();
        r.reset();
        t0 = now();
        const double c0 = thread_seconds();
        g = std::make_unique<MedialGraph>(exact_polygon_axis(s, {}, &rep));
        const double c1 = thread_seconds();
        dynamic_cast<const PolygonAxisGeometry&>(g->geometry()).value_classes();
        const double c2 = thread_seconds();
        r = std::make_unique<GrassfireResult>(extended_grassfire(*g));
        const double c3 = thread_seconds();
        row.both_s = std::min(row.both_s, now() - t0);
        if (c3 - c0 < row.both_cpu) {
          row.both_cpu = c3 - c0;
          row.classes_cpu = c2 - c1;
          row.burn_cpu = c3 - c2;
        }
      }
      const std::uint64_t uncertified = r->stats().uncertified_zero + rep.uncertified_contractions;
      const std::string cgal = n <= max_cgal ? std::to_string(row.cgal_s) : "";
      if (std::string(shape) == "shifted") decimal_cpu = row.both_cpu;
      const std::string to_decimal = unrounded || offset ? std::to_string(row.both_cpu / decimal_cpu) : "";
      std::printf("%d,%s,%.4f,%s,%.4f,%.4f,%.3f,%.3f,%.4f,%.4f,%.3f,%llu,%.1f,%s,%s,%.2f\n", n, shape, row.boost_s, cgal.c_str(),
                  row.axis_s, row.both_s, row.axis_s / row.boost_s, row.both_s / row.boost_s, row.boost_cpu, row.both_cpu,
                  row.both_cpu / row.boost_cpu, (unsigned long long)uncertified, peak_mb(), to_decimal.c_str(),
                  to_string(rep.construction), bench::machine_load());
      std::fflush(stdout);
      report_details(n, shape, rep, row, *g, *r);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "bench_polygon_axis", kUsage, run);
}
