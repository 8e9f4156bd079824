// options.h -- a small command-line option parser shared by every subcommand.
//
// Declare options (flags and valued options) and positional arguments with their help
// text, then parse(). `--help`/`-h` prints the generated usage and makes parse() return
// false with exit code 0; a malformed command line prints the usage and an error and
// returns false with exit code 2. Values are checked when read (integers, reals).
// Every command also takes --quiet (nothing but errors) and --progress (progress lines on
// stderr even when it is not a terminal); parse() sets the verbosity of support/progress.h.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "shapes/image_shape.h"

namespace grassfire {
struct MeshRepairOptions;  // medial3/mesh/mesh_repair.h
}

namespace grassfire::cli {

class Options {
 public:
  Options(std::string command, std::string summary);

  // A positional argument; an optional one may be left out (has_arg says whether it was given).
  Options& positional(const std::string& name, const std::string& help, bool required = true);
  Options& flag(const std::string& name, const std::string& help);
  Options& option(const std::string& name, const std::string& value_name, const std::string& help,
                  std::optional<std::string> default_value = std::nullopt);
  // Free text printed after the option list (formats, examples).
  Options& epilog(const std::string& text);

  // False when the caller should exit with exit_code() (help printed, or an error).
  bool parse(int argc, char** argv);
  int exit_code() const { return exit_code_; }

  const std::string& arg(const std::string& positional_name) const;
  bool has_arg(const std::string& positional_name) const { return args_.count(positional_name) > 0; }
  bool has(const std::string& name) const;  // a flag given, or an option with a value
  std::string get(const std::string& name) const;
  long get_long(const std::string& name, long min_value, long max_value) const;
  double get_double(const std::string& name) const;
  std::string usage() const;

 private:
  struct Spec {
    std::string name, value_name, help;
    bool takes_value;
    std::optional<std::string> default_value;
  };
  const Spec* find(const std::string& name) const;

  std::string command_, summary_, epilog_;
  std::vector<std::pair<std::string, std::string>> positionals_;
  std::size_t required_positionals_ = 0;  // the first ones are required
  std::vector<Spec> specs_;
  std::map<std::string, std::string> values_;
  std::map<std::string, std::string> args_;
  int exit_code_ = 0;
};

// The options of a shape given as an image (shapes/image_shape.h): --connectivity,
// --contour, --foreground, --threshold, --largest; every 2D command that loads a SHAPE takes them.
void add_image_options(Options& opt);
ImageShapeOptions image_options(const Options& opt);

// The repair of a defective mesh (medial3/mesh/mesh_repair.h): --repair,
// --repair-alpha, --repair-offset; every 3D command that builds the axis of a mesh takes them.
void add_repair_options(Options& opt);
MeshRepairOptions repair_options(const Options& opt);

}  // namespace grassfire::cli
