// figure_registry.h -- one generator per dissertation figure, all run by paper_figures.
//
// Each paper-figures/fig_*.cpp registers generators that write SVG files (and CSV or
// other data) into the output folder and return what they wrote with a caption. The
// driver writes index.html showing every figure; run.sh turns SVGs into PNGs.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace grassfire::figures {

struct FigureFile {
  std::string file;     // path relative to the output folder, e.g. "fig3_2.svg"
  std::string caption;  // what the picture shows, and the dissertation figure it redoes
};

struct FigureContext {
  std::string out_dir;   // paper-figures/out
  std::string data_dir;  // the project's data/ folder
};

using FigureFn = std::function<std::vector<FigureFile>(const FigureContext&)>;
bool register_figure(std::string id, std::string title, FigureFn fn);

struct FigureEntry {
  std::string id, title;
  FigureFn fn;
};
std::vector<FigureEntry> registered_figures();

}  // namespace grassfire::figures

#define GF_FIG_CONCAT_INNER(a, b) a##b
#define GF_FIG_CONCAT(a, b) GF_FIG_CONCAT_INNER(a, b)
#define GF_REGISTER_FIGURE(id, title, fn) \
  static const bool GF_FIG_CONCAT(gf_registered_figure_, __LINE__) = ::grassfire::figures::register_figure(id, title, fn)
