// print_union_axis_digests -- prints "index name hash size" for the corpus of
// union_axis_digest.h, built against whichever union_of_balls_axis is linked.
// tests/data/union_axis_digests.txt is its output against the library of main bad0ea7
// (before the fast path):
//   g++ -O2 -frounding-math -std=c++17 -DCGAL_USE_GMPXX=1 -Ikernel -Itests \
//       tests/print_union_axis_digests.cpp build/libgrassfire_kernel.a -lpng -lz -lgif \
//       -lflint-arb -lflint -lgmpxx -lmpfr -lgmp && ./a.out data
// With more arguments i j ..., prints the texts of those corpus entries instead (to compare).
// Not part of the build (test_union_balls_fast.cpp recomputes the same lines).
#include <cstdio>
#include <string>

#include "union_axis_digest.h"

int main(int argc, char** argv) {
  using namespace grassfire;
  using namespace grassfire::testing;
  const auto corpus = union_digest_corpus(argc > 1 ? argv[1] : "data");
  if (argc > 2) {
    for (int a = 2; a < argc; ++a) std::fputs(union_axis_text(union_of_balls_axis(corpus[std::stoul(argv[a])])).c_str(), stdout);
    return 0;
  }
  for (std::size_t i = 0; i < corpus.size(); ++i) {
    const std::string text = union_axis_text(union_of_balls_axis(corpus[i]));
    std::printf("%zu %s %016llx %zu\n", i, corpus[i].source.c_str(), (unsigned long long)union_fnv1a(text), text.size());
  }
}
