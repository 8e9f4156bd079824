// progress.h -- progress and notes on stderr for long runs; the --quiet / --progress switches.
//
// Computes nothing: it reports. One process-wide verbosity, set once by the program
// (tools/options.h: every command takes --quiet and --progress), the studies and figures
// (experiments/run_options.h) or the Python module (grassfire.set_verbosity):
//   Quiet    -- nothing but errors (errors are exceptions; their callers print them);
//   Normal   -- notes (one line each: what a run decided that the user should know);
//   Progress -- notes and progress lines, wherever stderr goes;
//   Auto     -- notes, and progress lines when stderr is a terminal (the default).
// A Progress on a terminal redraws one line ("\r", at most 5 times a second) and clears it
// when done; on a file or pipe (--progress) it writes a line every 10 seconds, so that a
// cluster job's log shows where it is; while a stage reports its state in words (fraction()
// with a detail: the exact engine's sweep), at most once a second either way. The environment variable
// GRASSFIRE_PROGRESS_SECONDS, when set, replaces both intervals (tests set it to 0 to see
// every report without waiting). Results never go to stderr, so --quiet changes no output file.
// An input the user gave as something other than a path (the Python module writes an array
// to a temporary file) is named in notes and progress lines as the user named it: while a
// NoteAlias lives on a thread, every occurrence of its path in what that thread prints
// reads as its name.
// Contract: not thread-safe (one Progress per thread at a time; the studies are sequential).
// Complexity: advance() is O(1) and reads the clock once every 1024 calls.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace grassfire {

enum class Verbosity { Quiet, Normal, Progress, Auto };

void set_verbosity(Verbosity v);
Verbosity verbosity();
// "quiet", "normal", "progress", "auto" (std::invalid_argument otherwise).
Verbosity parse_verbosity(const std::string& name);
bool notes_enabled();     // not Quiet
bool progress_enabled();  // Progress, or Auto with stderr a terminal

// One line on stderr unless Quiet.
void note(const std::string& text);

// Shows `name` for `path` in this thread's notes and progress lines while it lives (the
// innermost alias wins; an empty path does nothing).
class NoteAlias {
 public:
  NoteAlias(std::string path, std::string name);
  ~NoteAlias();
  NoteAlias(const NoteAlias&) = delete;
  NoteAlias& operator=(const NoteAlias&) = delete;
  // `text` with this thread's aliases applied.
  static std::string shown(std::string text);

 private:
  std::string path_, name_;
  const NoteAlias* outer_;
};

// For programs with their own argument handling (experiments, figures): removes --quiet
// and --progress from the command line and sets the verbosity they ask for.
void take_verbosity_flags(int& argc, char** argv);

// A task of `total` steps (0: unknown), e.g. Progress p("study_stability", files.size()).
class Progress {
 public:
  Progress(std::string task, std::uint64_t total);
  ~Progress() { done(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::uint64_t steps = 1) {
    done_ += steps;
    if (enabled_ && ++calls_ % 1024 == 0) maybe_draw();
  }
  // Names what is being done now (a file, a figure) and draws when due.
  void item(const std::string& what);
  // Names the stage a long run enters and draws at once (one line per stage in a log).
  void stage(const std::string& what);
  // For a run that knows the fraction done of its current stage (in [0, 1]) rather than a
  // step count (the burn3d methods, pipeline/burn3d_methods.h): shows "stage 45%"; a new
  // stage draws at once, the same stage when due. `detail` (e.g. "t = 1.2 of ~3.4, 5000
  // events, 9000 windows") is shown before the stage, and makes a line due every second.
  void fraction(const std::string& stage, double done, const std::string& detail = "");
  // Ends the report: clears the terminal line (call it before printing results) or logs
  // the total; later calls do nothing.
  void done();

 private:
  void maybe_draw();
  void draw();

  std::string task_, item_, detail_;
  double interval_override_ = -1;  // GRASSFIRE_PROGRESS_SECONDS, or -1
  std::uint64_t total_ = 0, done_ = 0, calls_ = 0;
  double fraction_ = -1;  // >= 0 once fraction() is used: shown instead of the step counts
  bool enabled_ = false, terminal_ = false, drawn_ = false, staged_ = false;  // staged: no time estimate
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace grassfire
