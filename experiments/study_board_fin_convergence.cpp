// study_board_fin_convergence -- the discrete baseline against the closed form on the board
// and fin (4.1.2, 4.2.1; docs/design.md 5, reference case 1) as the Steiner spacing h halves.
//
// For each h: max, mean and min of BT_discrete - BT over the graph points in the region
// |x| <= 7, y <= 7, z <= 7 (well inside the truncation at E = 10, where the closed form is
// exact: BT <= 10 there), and the kink: where along N the back side's arrival overtakes the
// fin's (the exact kink is t = 2 + sqrt 2 from c, i.e. (2 + sqrt2, 2 + sqrt2, 0)).
// Writes CSV to stdout and to OUT/board_fin_convergence.csv (one row per h), the order of
// convergence to OUT/board_fin_convergence_summary.csv and a log-log plot to
// OUT/board_fin_convergence.svg. --shard I/N runs every N-th h and writes its rows only
// (experiments/shard.h); --quiet writes nothing to stdout.
// Usage: study_board_fin_convergence [OUT] [--quick] [--shard I/N] [--progress|--quiet]
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "burn3/burn3_reference.h"
#include "burn3/discrete/junction_arrivals.h"
#include "complex3/synthetic_complexes.h"
#include "support/progress.h"
#include "render/render3d.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"

using namespace grassfire;

namespace {

struct Row {
  double h = 0, seconds = 0, max_error = 0, mean_error = 0, min_error = 0, kink_t = NAN;
  std::uint64_t steiner = 0, points = 0, kinks = 0;
};

enum Side { kBack = 0, kFront = 1, kFin = 2 };

int side_of(const MedialComplex& mc, std::uint32_t t) {
  Vec3d c{0, 0, 0};
  for (std::uint32_t v : mc.triangle(t).v)
    for (int i = 0; i < 3; ++i) c[i] += mc.vertex(v).approx[i] / 3;
  if (c[2] > 0) return kFin;
  return c[1] < c[0] ? kBack : kFront;
}

double log_pos(double v, double lo, double hi, double a, double b) {
  return a + (std::log(v) - std::log(lo)) / (std::log(hi) - std::log(lo)) * (b - a);
}

void plot(const std::vector<Row>& rows, const std::string& path) {
  SvgCanvas c(640, 440);
  const double x0 = 70, x1 = 600, y0 = 380, y1 = 40;
  double lo = 1e9, hi = 0;
  for (const Row& r : rows)
    for (double v : {r.max_error, r.mean_error, std::abs(r.kink_t - (2 + std::sqrt(2.0)))})
      if (v > 0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  lo = std::pow(10, std::floor(std::log10(lo))), hi = std::pow(10, std::ceil(std::log10(hi)));
  const double hlo = rows.back().h / 1.5, hhi = rows.front().h * 1.5;
  c.polyline({{x0, y1}, {x0, y0}, {x1, y0}}, {0, 0, 0}, 1.2);
  for (double d = lo; d <= hi * 1.01; d *= 10) {
    const double y = log_pos(d, lo, hi, y0, y1);
    c.polyline({{x0, y}, {x1, y}}, {0.85, 0.85, 0.85}, 0.6);
    char buf[32];
    std::snprintf(buf, sizeof buf, "1e%d", static_cast<int>(std::lround(std::log10(d))));
    c.text({x0 - 8, y + 4}, buf, 11, "end");
  }
  for (const Row& r : rows) {
    const double x = log_pos(r.h, hlo, hhi, x0, x1);
    char buf[32];
    std::snprintf(buf, sizeof buf, "1/%g", 1 / r.h);
    c.text({x, y0 + 18}, buf, 11, "middle");
  }
  const struct {
    const char* name;
    Rgb color;
    double Row::*field;
  } series[] = {{"max error", {0.8, 0.1, 0.1}, &Row::max_error}, {"mean error", {0.1, 0.3, 0.8}, &Row::mean_error}};
  int legend = 0;
  for (const auto& s : series) {
    std::vector<Point2d> pts;
    for (const Row& r : rows) pts.push_back({log_pos(r.h, hlo, hhi, x0, x1), log_pos(r.*(s.field), lo, hi, y0, y1)});
    c.polyline(pts, s.color, 2);
    for (const Point2d& p : pts) c.circle(p, 3, s.color, s.color, 0);
    c.text({x0 + 20, y1 + 16 + 16.0 * legend}, s.name, 12, "start", s.color);
    ++legend;
  }
  std::vector<Point2d> kink;
  for (const Row& r : rows) {
    const double e = std::abs(r.kink_t - (2 + std::sqrt(2.0)));
    if (e > 0 && std::isfinite(e)) kink.push_back({log_pos(r.h, hlo, hhi, x0, x1), log_pos(e, lo, hi, y0, y1)});
  }
  c.polyline(kink, {0.1, 0.6, 0.2}, 2, "6,4");
  c.text({x0 + 20, y1 + 16 + 16.0 * legend}, "|kink t - (2 + sqrt 2)|", 12, "start", {0.1, 0.6, 0.2});
  // Reference slope 1.
  c.polyline({{log_pos(rows.front().h, hlo, hhi, x0, x1), log_pos(rows.front().max_error, lo, hi, y0, y1) - 20},
              {log_pos(rows.back().h, hlo, hhi, x0, x1),
               log_pos(rows.front().max_error * rows.back().h / rows.front().h, lo, hi, y0, y1) - 20}},
             {0.5, 0.5, 0.5}, 1, "2,3");
  c.text({x1, y0 - 8}, "slope 1 (dotted)", 11, "end", {0.4, 0.4, 0.4});
  c.text({(x0 + x1) / 2, y0 + 36}, "Steiner spacing h", 13, "middle");
  c.text({(x0 + x1) / 2, 22}, "Board and fin: discrete BT vs closed form (E = 10, region |x|, y, z <= 7)", 13, "middle");
  c.save(path);
}

// Rows: one per h; they do not depend on each other, so shards concatenate.
std::string row_csv(const Row& r) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.6g,%llu,%.4f,%llu,%.6e,%.6e,%.3e,%llu,%.6f,%.6f,%.3e", r.h,
                static_cast<unsigned long long>(r.steiner), r.seconds, static_cast<unsigned long long>(r.points),
                r.max_error, r.mean_error, r.min_error, static_cast<unsigned long long>(r.kinks), r.kink_t,
                1 + r.kink_t / std::sqrt(2.0), std::abs(r.kink_t - (2 + std::sqrt(2.0))));
  return buf;
}

// The order of convergence: max error at 2h over max error at h (2 for first order).
void write_summary(const std::vector<Row>& rows, const std::string& path) {
  std::ofstream os(path);
  os << "h,max_error,max_error_ratio\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.6g,%.6e,%.3f\n", rows[i].h, rows[i].max_error,
                  i == 0 ? NAN : rows[i - 1].max_error / rows[i].max_error);
    os << buf;
  }
}

constexpr const char* kUsage =
    "usage: study_board_fin_convergence [OUT] [--quick] [--shard I/N] [--progress|--quiet]\nthe discrete baseline against the closed form on the board and fin (4.1.2, 4.2.1; docs/design.md 5, reference case 1) as the Steiner spacing h halves.\n(CSV columns and details: the header of experiments/study_board_fin_convergence.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, {{"--quick"}, {}, 0, 1});
  const experiments::Shard shard = cmd.shard;
  const std::string out = cmd.positional_or(0, ".");
  const bool quick = cmd.flag("--quick");
  const MedialComplex mc(board_fin({10, 1}));
  mc.validate();
  const std::uint32_t c = [&] {
    for (std::uint32_t v = 0; v < mc.vertex_count(); ++v)
      if (mc.vertex(v).exact == ExactPoint3{1, 1, 0}) return v;
    throw std::logic_error("no corner c");
  }();
  const std::vector<std::uint32_t> n_chain = singular_curve_from(mc, c);
  auto inside = [](const Vec3d& p) { return std::abs(p[0]) <= 7 && p[1] <= 7 && p[2] <= 7; };
  std::vector<int> levels(quick ? 4 : 7);
  for (std::size_t k = 0; k < levels.size(); ++k) levels[k] = static_cast<int>(k);
  levels = experiments::shard_of(levels, shard);
  std::vector<Row> rows;
  Progress progress("study_board_fin_convergence " + shard.label(), levels.size());
  for (const int k : levels) {
    const double h = 0.5 / std::pow(2.0, k);
    progress.item("h = " + std::to_string(h));
    const DiscreteBurning d = burn_discrete(mc, {h});
    const ErrorSummary e = summarize_error(mc, d, board_fin_burning_time, inside);
    if (e.points == 0 || e.points != e.considered)  // every point of the region compared, none one-sided
      throw std::logic_error("study_board_fin_convergence: compared " + std::to_string(e.points) + " of " +
                             std::to_string(e.considered) + " points (" + std::to_string(e.one_sided_infinite) +
                             " infinite on one side only)");
    const auto along = arrivals_along_curve(mc, d, c, n_chain, [&](std::uint32_t t) { return side_of(mc, t); });
    const std::vector<double> kinks = kinks_along_curve(along, kBack, kFin);
    Row r;
    r.h = h, r.seconds = d.stats.seconds, r.steiner = d.stats.steiner_points, r.points = e.points;
    r.max_error = e.max_error, r.mean_error = e.mean_error, r.min_error = e.min_error;
    r.kinks = kinks.size();
    if (!kinks.empty()) r.kink_t = kinks.front();
    rows.push_back(r);
    progress.advance();
  }
  progress.done();
  std::vector<std::string> lines;
  for (const Row& r : rows) lines.push_back(row_csv(r));
  const std::string header =
      "h,steiner_points,seconds,points_compared,max_error,mean_error,min_error,kink_count,kink_t,kink_x,kink_error";
  if (notes_enabled()) experiments::write_sorted_csv(std::cout, header, lines);
  experiments::write_sorted_csv(out + "/board_fin_convergence.csv", header, lines);
  if (experiments::rows_only(shard, out + "/board_fin_convergence.csv")) return 0;
  write_summary(rows, out + "/board_fin_convergence_summary.csv");
  plot(rows, out + "/board_fin_convergence.svg");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_board_fin_convergence", kUsage, run);
}
