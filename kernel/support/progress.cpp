// progress.cpp -- see progress.h.
#include "support/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace grassfire {

namespace {

Verbosity g_verbosity = Verbosity::Auto;

bool stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

thread_local const NoteAlias* t_alias = nullptr;

}  // namespace

NoteAlias::NoteAlias(std::string path, std::string name)
    : path_(std::move(path)), name_(std::move(name)), outer_(t_alias) {
  t_alias = this;
}

NoteAlias::~NoteAlias() { t_alias = outer_; }

std::string NoteAlias::shown(std::string text) {
  for (const NoteAlias* a = t_alias; a; a = a->outer_) {
    if (a->path_.empty()) continue;
    for (std::size_t at = text.find(a->path_); at != std::string::npos; at = text.find(a->path_, at + a->name_.size()))
      text.replace(at, a->path_.size(), a->name_);
  }
  return text;
}

void set_verbosity(Verbosity v) { g_verbosity = v; }
Verbosity verbosity() { return g_verbosity; }

Verbosity parse_verbosity(const std::string& name) {
  if (name == "quiet") return Verbosity::Quiet;
  if (name == "normal") return Verbosity::Normal;
  if (name == "progress") return Verbosity::Progress;
  if (name == "auto") return Verbosity::Auto;
  throw std::invalid_argument("verbosity must be 'quiet', 'normal', 'progress' or 'auto', got '" + name + "'");
}

bool notes_enabled() { return g_verbosity != Verbosity::Quiet; }

bool progress_enabled() {
  return g_verbosity == Verbosity::Progress || (g_verbosity == Verbosity::Auto && stderr_is_terminal());
}

void note(const std::string& text) {
  if (notes_enabled()) std::fprintf(stderr, "%s\n", NoteAlias::shown(text).c_str());
}

void take_verbosity_flags(int& argc, char** argv) {
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quiet")
      set_verbosity(Verbosity::Quiet);
    else if (a == "--progress")
      set_verbosity(Verbosity::Progress);
    else
      argv[out++] = argv[i];
  }
  argc = out;
  argv[argc] = nullptr;
}

Progress::Progress(std::string task, std::uint64_t total)
    : task_(NoteAlias::shown(std::move(task))),
      total_(total),
      enabled_(progress_enabled()),
      terminal_(stderr_is_terminal()),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {
  if (const char* seconds = std::getenv("GRASSFIRE_PROGRESS_SECONDS")) interval_override_ = std::max(0.0, std::atof(seconds));
}

void Progress::done() {
  if (!enabled_ || !drawn_) return;
  drawn_ = false;
  enabled_ = false;
  if (terminal_) {
    std::fprintf(stderr, "\r\033[K");  // clear the line: the result lines follow
  } else if (fraction_ >= 0) {
    const double seconds = seconds_between(start_, std::chrono::steady_clock::now());
    std::fprintf(stderr, "%s: done, %.1f s\n", task_.c_str(), seconds);
  } else {
    std::fprintf(stderr, "%s: done, %llu steps, %.1f s\n", task_.c_str(), static_cast<unsigned long long>(done_),
                 seconds_between(start_, std::chrono::steady_clock::now()));
  }
  std::fflush(stderr);
}

void Progress::item(const std::string& what) {
  item_ = what;
  if (enabled_) maybe_draw();
}

void Progress::stage(const std::string& what) {
  detail_.clear();
  item_ = what;
  staged_ = true;  // stages differ in cost: a time estimate from their count would mislead
  if (!enabled_) return;
  last_ = std::chrono::steady_clock::now();
  draw();
}

void Progress::fraction(const std::string& stage, double done, const std::string& detail) {
  fraction_ = std::min(std::max(done, 0.0), 1.0);
  if (stage == item_) {
    detail_ = detail;
    if (enabled_) maybe_draw();
    return;
  }
  this->stage(stage);
  detail_ = detail;  // shown from the next line on
}

void Progress::maybe_draw() {
  const auto now = std::chrono::steady_clock::now();
  const double interval = interval_override_ >= 0 ? interval_override_ : !detail_.empty() ? 1.0 : terminal_ ? 0.2 : 10.0;
  if (seconds_between(last_, now) < interval) return;
  last_ = now;
  draw();
}

void Progress::draw() {
  const double elapsed = seconds_between(start_, last_);
  char counts[96];
  if (fraction_ >= 0)
    std::snprintf(counts, sizeof counts, "%.0f%%", 100.0 * fraction_);
  else if (total_ > 0)
    std::snprintf(counts, sizeof counts, "%llu/%llu (%.0f%%)", static_cast<unsigned long long>(done_),
                  static_cast<unsigned long long>(total_), 100.0 * static_cast<double>(done_) / total_);
  else
    std::snprintf(counts, sizeof counts, "%llu", static_cast<unsigned long long>(done_));
  char eta[48] = "";
  if (total_ > 0 && done_ > 0 && done_ < total_ && !staged_)
    std::snprintf(eta, sizeof eta, ", about %.0f s left", elapsed * static_cast<double>(total_ - done_) / done_);
  std::string line = task_ + ": " + counts + ", " + std::to_string(static_cast<long long>(elapsed)) + " s" + eta;
  if (!detail_.empty()) line += ", " + detail_;
  if (!item_.empty()) line += " -- " + NoteAlias::shown(item_);
  if (terminal_) {
    if (line.size() > 150) line = line.substr(0, 147) + "...";
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace grassfire
