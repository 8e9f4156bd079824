// study_alignment -- translational alignment of the human figures of the `children` class
// by centroid, bounding-box centre, EMA and PR maximum (3.5.2, Fig. 3.8).
//
// For every pair (a, b) of the shapes found (children-*.json in SHAPES_DIR, all 20 for the
// report), b is translated so that its centre meets a's, for each method, and the overlap
// is the exact intersection over union (apps2d/alignment.h: CGAL Boolean set operations
// on exact coordinates). Centres come from the exact polygon axis (pipeline/edf2d.h).
// Output, with CLASS the class name: OUT/alignment_CLASS_pairs.csv (a, b, method, iou),
// OUT/alignment_CLASS_summary.csv (per method: pairs, mean, median and min IoU, and pairs
// where it beats centroid alignment; files the loader rejected, as comment lines),
// OUT/alignment_CLASS_centres.csv (every shape's centres), OUT/alignment_CLASS_iou.svg
// (per method, the IoU of every pair sorted, as curves).
// The `children` class of the dataset is one child drawn 20 times with small variations;
// the `stef` class (a skater in 20 poses) is the setting of Fig. 3.8 (body movement).
// --shard I/N writes every N-th shape's centres and every N-th pair, rows only (experiments/shard.h).
// Usage: study_alignment SHAPES_DIR [OUT] [--class NAME] [--shard I/N] [--progress|--quiet]
//   (NAME: children by default)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "apps2d/alignment.h"
#include "support/progress.h"
#include "pipeline/edf2d.h"
#include "plot_svg.h"
#include "io/load_shape.h"
#include "shapes/validate_shape.h"
#include "shard.h"
#include "cli.h"
#include "run_options.h"

using namespace grassfire;

namespace {

struct Entry {
  std::string name;
  Shape2 shape;
  ShapeCentres centres;
};

std::vector<std::filesystem::path> class_files(const std::string& dir, const std::string& cls) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string stem = e.path().stem().string();
    if (e.path().extension() == ".json" && stem.rfind(cls + "-", 0) == 0) files.push_back(e.path());
  }
  // Numeric order: children-2 before children-10.
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    const std::string sa = a.stem().string(), sb = b.stem().string();
    return std::make_pair(sa.size(), sa) < std::make_pair(sb.size(), sb);
  });
  return files;
}

Entry load_entry(const std::filesystem::path& f) {
  Entry e{f.stem().string(), load_shape(f.string()), {}};
  Edf2dOptions opt;
  opt.axis = AxisMethod::ExactPolygon;
  const Edf2dResult r = compute_edf2d(e.shape, opt);
  e.centres = shape_centres(e.shape, *r.graph, *r.burning);
  return e;
}

std::string fmt(const std::optional<Point2>& p) {
  if (!p) return "nan,nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f,%.6f", p->x, p->y);
  return buf;
}

constexpr const char* kUsage =
    "usage: study_alignment SHAPES_DIR [OUT] [--class NAME] [--shard I/N] [--progress|--quiet]\ntranslational alignment of the human figures of the `children` class by centroid, bounding-box centre, EMA and PR maximum (3.5.2, Fig. 3.8).\n(CSV columns and details: the header of experiments/study_alignment.cpp)\n";

int run(int argc, char** argv) {
  const experiments::RunOptions cmd = experiments::parse_run_options(argc, argv, {{}, {"--class"}, 1, 2});
  const experiments::Shard shard = cmd.shard;
  const std::string dir = cmd.positional[0], out = cmd.positional_or(1, "."), cls = cmd.text("--class", "children");
  std::vector<Entry> shapes;
  std::vector<std::string> skipped;  // files the loader rejects (e.g. a self-touching outline)
  try {
    for (const auto& f : class_files(dir, cls)) {
      try {
        shapes.push_back(load_entry(f));
      } catch (const InvalidShapeError& e) {
        skipped.push_back(e.what());
        note(std::string("skipped: ") + e.what());
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study_alignment: %s\n", e.what());
    return 1;
  }
  if (shapes.size() < 2) {
    std::fprintf(stderr, "study_alignment: fewer than two '%s' shapes in %s\n", cls.c_str(), dir.c_str());
    return 1;
  }
  // Shards split the shapes' rows and the pairs' rows (pair k of the i < j order); every
  // shard loads every shape, which the pairs need.
  std::vector<std::string> centre_rows;
  for (std::size_t i = 0; i < shapes.size(); ++i)
    if (shard.takes(i))
      centre_rows.push_back(shapes[i].name + "," + fmt(shapes[i].centres.centroid) + "," +
                            fmt(shapes[i].centres.bounding_box) + "," + fmt(shapes[i].centres.ema) + "," +
                            fmt(shapes[i].centres.pr_maximum));
  experiments::write_sorted_csv(out + "/alignment_" + cls + "_centres.csv",
                                "shape,centroid_x,centroid_y,bbox_x,bbox_y,ema_x,ema_y,pr_max_x,pr_max_y", centre_rows);

  std::vector<std::string> pair_rows;
  std::map<AlignmentMethod, std::vector<double>> iou;
  std::map<AlignmentMethod, std::size_t> beats_centroid;
  const std::size_t pair_count = shapes.size() * (shapes.size() - 1) / 2;
  const std::size_t my_pairs = pair_count > shard.index ? (pair_count - shard.index + shard.count - 1) / shard.count : 0;
  Progress progress("study_alignment " + cls + " " + shard.label(), my_pairs);
  for (std::size_t i = 0, k = 0; i < shapes.size(); ++i)
    for (std::size_t j = i + 1; j < shapes.size(); ++j, ++k) {
      if (!shard.takes(k)) continue;
      double centroid_iou = std::nan("");
      for (AlignmentMethod m : all_alignment_methods()) {
        const std::optional<Point2> shift = alignment_shift(shapes[i].centres, shapes[j].centres, m);
        if (!shift) continue;
        const double v = polygon_overlap(shapes[i].shape, shapes[j].shape, *shift).iou;
        if (m == AlignmentMethod::Centroid) centroid_iou = v;
        beats_centroid[m] += v > centroid_iou;
        iou[m].push_back(v);
        char buf[256];
        std::snprintf(buf, sizeof buf, "%s,%s,%s,%.6f,%.6f,%.6f", shapes[i].name.c_str(), shapes[j].name.c_str(),
                      to_string(m), shift->x, shift->y, v);
        pair_rows.push_back(buf);
      }
      progress.advance();
    }
  progress.done();
  experiments::write_sorted_csv(out + "/alignment_" + cls + "_pairs.csv", "a,b,method,shift_x,shift_y,iou", pair_rows);
  if (experiments::rows_only(shard, out + "/alignment_" + cls + "_{centres,pairs}.csv")) return 0;

  std::ofstream summary(out + "/alignment_" + cls + "_summary.csv");
  summary << "method,shapes,pairs,mean_iou,median_iou,min_iou,pairs_better_than_centroid\n";
  for (const std::string& why : skipped) summary << "# skipped: " << why << "\n";
  plot::Plot p;
  p.title = "Alignment of the '" + cls + "' shapes: IoU of every pair, sorted";
  p.x_label = "pair rank (sorted by IoU)";
  p.y_label = "IoU";
  for (AlignmentMethod m : all_alignment_methods()) {
    std::vector<double> v = iou[m];
    std::sort(v.begin(), v.end());
    double mean = 0;
    for (double x : v) mean += x;
    mean = v.empty() ? std::nan("") : mean / double(v.size());
    const double median = v.empty() ? std::nan("") : v[v.size() / 2];
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%zu,%zu,%.4f,%.4f,%.4f,%zu\n", to_string(m), shapes.size(), v.size(), mean,
                  median, v.empty() ? std::nan("") : v.front(), beats_centroid[m]);
    summary << buf;
    if (notes_enabled()) std::fprintf(stderr, "%s", buf);
    if (v.empty()) continue;
    plot::Series s;
    s.name = std::string(to_string(m)) + " (mean " + std::to_string(mean).substr(0, 5) + ")";
    s.colour = plot::series_colour(p.series.size());
    s.markers = false;
    for (std::size_t k = 0; k < v.size(); ++k) s.x.push_back(double(k)), s.y.push_back(v[k]);
    p.series.push_back(s);
  }
  plot::save(p, out + "/alignment_" + cls + "_iou.svg");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return grassfire::experiments::guarded_main(argc, argv, "study_alignment", kUsage, run);
}
