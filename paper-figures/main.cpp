// main.cpp -- regenerates the dissertation's figures into one folder with an index.html.
//
// usage: paper_figures [--out DIR] [--data DIR] [--only ID] [--list] [--progress|--quiet]
// Writes every registered figure, then DIR/index.html, which shows each figure (as PNG,
// produced from the SVG by run.sh) with its caption, and inlines DIR/proof-checks.html
// (the proof-check report: rows, references, verdicts and the table of mutants each row
// detected) when it exists. Exit code 1 when a generator fails.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "figure_registry.h"
#include "support/progress.h"
#include "support/xml_escape.h"

namespace grassfire::figures {

namespace {
std::vector<FigureEntry>& registry() {
  static std::vector<FigureEntry> list;
  return list;
}

std::string gallery_name(const std::string& file) {
  const std::string svg = ".svg";
  if (file.size() > svg.size() && file.compare(file.size() - svg.size(), svg.size(), svg) == 0)
    return file.substr(0, file.size() - svg.size()) + ".png";
  return file;
}

void write_index(const std::string& dir, const std::vector<std::pair<FigureEntry, std::vector<FigureFile>>>& done) {
  std::ofstream os(dir + "/index.html");
  os << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>grassfire: figures of Liu 2011</title>\n"
        "<style>body{font-family:sans-serif;max-width:1200px;margin:auto;padding:1em}"
        "figure{display:inline-block;vertical-align:top;margin:0.5em;max-width:560px}"
        "img{max-width:100%;border:1px solid #ccc}figcaption{font-size:0.9em}"
        "table.checks{border-collapse:collapse}table.checks td,table.checks th{border:1px solid #bbb;padding:3px 6px}"
        "td.pass{color:#070}td.fail,p.fail{color:#b00;font-weight:bold}td.notchecked{color:#777}</style></head><body>\n"
        "<h1>grassfire: the figures of <i>Multi-Dimensional Medial Geometry</i> (Liu 2011), regenerated</h1>\n";
  std::ifstream checks(dir + "/proof-checks.html");
  if (checks) {
    os << "<h2>Proof checks</h2>\n" << checks.rdbuf() << "\n";
  }
  for (const auto& [entry, files] : done) {
    os << "<h2 id=\"" << entry.id << "\">" << xml_escape(entry.title) << "</h2>\n";
    for (const FigureFile& f : files) {
      const std::string shown = gallery_name(f.file);
      if (shown.size() > 4 && shown.substr(shown.size() - 4) == ".png")
        os << "<figure><a href=\"" << f.file << "\"><img src=\"" << shown << "\" alt=\"" << f.file
           << "\"></a><figcaption>" << xml_escape(f.caption) << "</figcaption></figure>\n";
      else
        os << "<p><a href=\"" << f.file << "\">" << f.file << "</a>: " << xml_escape(f.caption) << "</p>\n";
    }
  }
  os << "</body></html>\n";
}
// Runs one generator in a child process, so that a crash in one figure cannot take the
// others down; the files it wrote come back through a pipe as "file<TAB>caption" lines.
std::vector<FigureFile> run_isolated(const FigureEntry& f, const FigureContext& ctx) {
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(fd[0]);
    int code = 0;
    std::string out;
    try {
      for (const FigureFile& file : f.fn(ctx)) {
        std::string caption = file.caption;
        std::replace(caption.begin(), caption.end(), '\n', ' ');
        std::replace(caption.begin(), caption.end(), '\t', ' ');
        out += file.file + "\t" + caption + "\n";
      }
    } catch (const std::exception& e) {
      std::cerr << "paper_figures: " << f.id << ": " << e.what() << std::endl;
      code = 1;
    }
    const ssize_t n = static_cast<ssize_t>(out.size());
    if (write(fd[1], out.data(), out.size()) != n) code = 1;
    _exit(code);
  }
  close(fd[1]);
  std::string text;
  char buf[4096];
  ssize_t got;
  while ((got = read(fd[0], buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(got));
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(WIFSIGNALED(status) ? "crashed with signal " + std::to_string(WTERMSIG(status))
                                                 : "failed");
  std::vector<FigureFile> files;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t tab = line.find('\t');
    if (tab != std::string::npos) files.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return files;
}

}  // namespace

bool register_figure(std::string id, std::string title, FigureFn fn) {
  registry().push_back({std::move(id), std::move(title), std::move(fn)});
  return true;
}

std::vector<FigureEntry> registered_figures() {
  auto list = registry();
  std::stable_sort(list.begin(), list.end(), [](const FigureEntry& a, const FigureEntry& b) { return a.id < b.id; });
  return list;
}

}  // namespace grassfire::figures

int main(int argc, char** argv) {
  using namespace grassfire::figures;
  grassfire::take_verbosity_flags(argc, argv);
  FigureContext ctx;
  ctx.out_dir = "paper-figures/out";
  ctx.data_dir = GF_PROJECT_DATA;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "paper_figures: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--out")
      ctx.out_dir = value();
    else if (a == "--data")
      ctx.data_dir = value();
    else if (a == "--only")
      only = value();
    else if (a == "--list") {
      for (const FigureEntry& f : registered_figures()) std::cout << f.id << "\t" << f.title << "\n";
      return 0;
    } else if (a == "--help" || a == "-h") {
      std::cout << "usage: paper_figures [--out DIR] [--data DIR] [--only ID] [--list] [--progress|--quiet]\n"
                   "Regenerates the dissertation's figures as SVG into DIR (default paper-figures/out)\n"
                   "and writes DIR/index.html. --quiet prints only failures; --progress shows progress\n"
                   "even when stderr is not a terminal.\n";
      return 0;
    } else {
      std::cerr << "paper_figures: unknown argument '" << a << "' (see --help)\n";
      return 2;
    }
  }
  std::filesystem::create_directories(ctx.out_dir);
  std::vector<std::pair<FigureEntry, std::vector<FigureFile>>> done;
  int failures = 0;
  std::vector<FigureEntry> figures;
  for (const FigureEntry& f : registered_figures())
    if (only.empty() || f.id == only) figures.push_back(f);
  grassfire::Progress progress("paper_figures", figures.size());
  for (const FigureEntry& f : figures) {
    progress.item(f.id);
    const auto start = std::chrono::steady_clock::now();
    try {
      done.emplace_back(f, run_isolated(f, ctx));
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      grassfire::note("paper_figures: " + f.id + ": " + std::to_string(done.back().second.size()) + " files in " +
                      std::to_string(secs) + " s");
    } catch (const std::exception& e) {
      std::cerr << "paper_figures: " << f.id << " failed: " << e.what() << std::endl;
      ++failures;
    }
    progress.advance();
  }
  progress.done();
  write_index(ctx.out_dir, done);
  return failures == 0 ? 0 : 1;
}
