// mutator.h -- a deterministic, seeded mutator of input files for fuzz_readers.
//
// Computes: from a corpus of valid and malformed files of one format, the i-th mutated
// input of a run, a pure function of (seed, reader name, i), so that any input of a run
// can be rebuilt alone. Each input is a corpus file with 1 (half of the inputs) or 2 to 4
// stacked mutations: bit flips, byte sets, byte insertions and deletions, chunk
// duplication, truncation, token swaps, number replacement (NaN, inf, huge, tiny,
// negative, counts near 2^31, 2^32, 2^64, 10^12), number arithmetic, line duplication,
// deletion and moves, splicing with another corpus file, 32-bit words and floats
// overwritten (for binary formats), and long tokens.
// Inputs are capped at 1 MiB.
// Complexity: O(input size) per mutation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace grassfire::fuzz {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();                 // splitmix64
  std::size_t below(std::size_t n);     // uniform enough in [0, n), n > 0
  bool chance(unsigned percent) { return below(100) < percent; }

 private:
  std::uint64_t state_;
};

// The seed of input `index` of reader `reader` in a run with seed `seed`.
std::uint64_t input_seed(std::uint64_t seed, const std::string& reader, std::uint64_t index);

std::string mutate(const std::vector<std::string>& corpus, Rng& rng);

}  // namespace grassfire::fuzz
