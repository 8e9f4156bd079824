// shard.h -- `--shard I/N`: a deterministic split of a study's inputs, and CSV rows that
// concatenate into the unsharded result.
//
// Split: the inputs, in the order the study lists them (sorted file names, or the study's
// own fixed list), are dealt round-robin: shard I of N takes the inputs whose position p
// has p mod N = I. Round-robin rather than blocks, so that a folder sorted by class gives
// every shard a mix of sizes. Every input lands in exactly one shard.
// Rows: write_sorted_csv writes the header, then the rows in byte order (what `LC_ALL=C
// sort` gives), so the rows of shards 0..N-1, concatenated and sorted, are the rows of the
// unsharded run (up to timing columns, which differ between any two runs):
//     (head -n 1 shard_0.csv; tail -q -n +2 shard_*.csv | LC_ALL=C sort) > whole.csv
// Summaries (medians, slopes, plots) need all rows: a sharded run writes its rows only.
// Contract: rows have no line breaks (the studies replace them in free text).
// Complexity: O(inputs) to split, O(R log R) to sort R rows.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/progress.h"

namespace grassfire::experiments {

struct Shard {
  std::size_t index = 0, count = 1;
  bool whole() const { return count == 1; }
  bool takes(std::size_t position) const { return position % count == index; }
  std::string label() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "I/N" with 0 <= I < N; std::invalid_argument otherwise.
inline Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  auto number = [&](const std::string& s) {
    if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 9)
      throw std::invalid_argument("--shard must be I/N with 0 <= I < N, got '" + text + "'");
    return static_cast<std::size_t>(std::stoul(s));
  };
  if (slash == std::string::npos) number("");
  const Shard s{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (s.count == 0 || s.index >= s.count)
    throw std::invalid_argument("--shard must be I/N with 0 <= I < N, got '" + text + "'");
  return s;
}

// Removes `--shard I/N` (or `--shard=I/N`) from the command line, so that each study keeps
// its own argument handling, and returns it (the whole when absent).
inline Shard take_shard(int& argc, char** argv) {
  Shard shard;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--shard")) {
      if (i + 1 >= argc) throw std::invalid_argument("--shard needs a value I/N");
      shard = parse_shard(argv[++i]);
    } else if (!std::strncmp(argv[i], "--shard=", 8)) {
      shard = parse_shard(argv[i] + 8);
    } else {
      argv[out++] = argv[i];
    }
  }
  argc = out;
  argv[argc] = nullptr;
  return shard;
}

// The inputs this shard takes, in their order.
template <class T>
std::vector<T> shard_of(const std::vector<T>& inputs, const Shard& shard) {
  std::vector<T> mine;
  for (std::size_t p = 0; p < inputs.size(); ++p)
    if (shard.takes(p)) mine.push_back(inputs[p]);
  return mine;
}

// The header line, then the rows in byte order; each row a line without its newline.
inline void write_sorted_csv(std::ostream& os, const std::string& header, std::vector<std::string> rows) {
  std::sort(rows.begin(), rows.end());
  os << header << '\n';
  for (const std::string& r : rows) os << r << '\n';
}
inline void write_sorted_csv(const std::string& path, const std::string& header, std::vector<std::string> rows) {
  std::ofstream os(path);
  write_sorted_csv(os, header, std::move(rows));
  if (!os) throw std::runtime_error(path + ": cannot write");
}

// True for a shard, after a note that `rows` were written and that the summary needs
// every row; the study then stops.
inline bool rows_only(const Shard& shard, const std::string& rows) {
  if (shard.whole()) return false;
  note("shard " + shard.label() + ": rows written to " + rows +
       "; summaries and plots need every row (run without --shard)");
  return true;
}

}  // namespace grassfire::experiments
