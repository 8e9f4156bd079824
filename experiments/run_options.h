// experiments/run_options.h -- the command line every study shares, parsed in one place.
//
// Computes: RunOptions from argc/argv and the study's RunOptionSpec: `--shard I/N`
// (experiments/shard.h), `--quiet` / `--progress` (support/progress.h), the study's flags
// (`--quick`), its options with one value (`--seeds K`, repeatable: every value is kept)
// and its positional arguments (a folder, an output folder), in the order given.
// Contract: an unknown `--option`, an option without its value, a value that is not the
// number asked for, or fewer / more positional arguments than the spec allows throws
// UsageError; guarded_main (experiments/cli.h) prints it with the usage on stderr and
// exits 2. Nothing runs before the whole command line is accepted.
// folder_files(folder, extensions): the files of a folder argument with one of those
// extensions, sorted by path (the order experiments/shard.h deals them in); an unreadable
// folder throws std::runtime_error "folder: reason".
// Complexity: O(arguments x spec entries); folder_files O(F log F) for F files.
#pragma once

#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "shard.h"
#include "support/progress.h"

namespace grassfire::experiments {

// A command line the study does not accept (its message says why).
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct RunOptionSpec {
  std::vector<std::string> flags;    // switches without a value, e.g. "--quick"
  std::vector<std::string> options;  // switches with one value, e.g. "--seeds"
  std::size_t min_positional = 0, max_positional = 0;
  bool shard = true;  // accepts --shard I/N
};

class RunOptions {
 public:
  Shard shard;
  std::vector<std::string> positional;

  bool flag(const std::string& name) const {
    for (const auto& f : flags_)
      if (f == name) return true;
    return false;
  }
  // Every value given to `name`, in order.
  std::vector<std::string> values(const std::string& name) const {
    std::vector<std::string> out;
    for (const auto& [k, v] : values_)
      if (k == name) out.push_back(v);
    return out;
  }
  // The last value given to `name`, if any.
  std::optional<std::string> value(const std::string& name) const {
    const auto all = values(name);
    return all.empty() ? std::nullopt : std::optional<std::string>(all.back());
  }
  std::string text(const std::string& name, const std::string& fallback) const { return value(name).value_or(fallback); }
  // A non-negative integer / a finite number; UsageError names the option and the text.
  std::uint64_t count(const std::string& name, std::uint64_t fallback) const {
    const auto v = value(name);
    if (!v) return fallback;
    if (v->empty() || v->size() > 18 || v->find_first_not_of("0123456789") != std::string::npos)
      throw UsageError(name + " needs a non-negative integer, got '" + *v + "'");
    return std::stoull(*v);
  }
  double number(const std::string& name, double fallback) const {
    const auto v = value(name);
    if (!v) return fallback;
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(*v, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != v->size() || !(x - x == 0)) throw UsageError(name + " needs a number, got '" + *v + "'");
    return x;
  }
  // Positional argument k, or `fallback` when fewer were given.
  std::string positional_or(std::size_t k, const std::string& fallback) const {
    return k < positional.size() ? positional[k] : fallback;
  }

 private:
  friend RunOptions parse_run_options(int, char**, const RunOptionSpec&);
  std::vector<std::string> flags_;
  std::vector<std::pair<std::string, std::string>> values_;
};

inline RunOptions parse_run_options(int argc, char** argv, const RunOptionSpec& spec) {
  RunOptions r;
  auto known = [](const std::vector<std::string>& names, const std::string& a) {
    for (const auto& n : names)
      if (n == a) return true;
    return false;
  };
  try {
    if (spec.shard) r.shard = take_shard(argc, argv);
    take_verbosity_flags(argc, argv);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (known(spec.flags, a)) {
      r.flags_.push_back(a);
    } else if (known(spec.options, a)) {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      r.values_.emplace_back(a, argv[++i]);
    } else if (a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9')) {
      throw UsageError("unknown option " + a);
    } else {
      r.positional.push_back(a);
    }
  }
  if (r.positional.size() < spec.min_positional)
    throw UsageError(spec.min_positional == 1 ? "missing argument" : "missing arguments");
  if (r.positional.size() > spec.max_positional) throw UsageError("unexpected argument " + r.positional[spec.max_positional]);
  return r;
}

inline std::vector<std::filesystem::path> folder_files(const std::string& folder, const std::vector<std::string>& extensions) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec))
    if (std::find(extensions.begin(), extensions.end(), e.path().extension().string()) != extensions.end())
      files.push_back(e.path());
  if (ec) throw std::runtime_error(folder + ": " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace grassfire::experiments
