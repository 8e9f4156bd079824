// print_medial_complex_digests -- prints "index name hash size [refusal]" for the digest
// corpus of medial_complex_digest.h, built against whichever MedialComplex is linked.
// tests/data/medial_complex_digests.txt is its output against the all-rational library
// of commit 84237b0 (headers of that commit, this file and medial_complex_digest.h):
//   g++ -O2 -frounding-math -std=c++17 -DCGAL_USE_GMPXX=1 -I<84237b0>/kernel -Itests \
//       tests/print_medial_complex_digests.cpp libgrassfire_kernel.a -lpng -lz -lgif \
//       -lflint-arb -lflint -lgmpxx -lmpfr -lgmp && ./a.out data
// Not part of the build (the test recomputes the same lines with the current library).
#include <cstdio>
#include "medial_complex_digest.h"
int main(int argc, char** argv) {
  using namespace grassfire::testing;
  const auto corpus = digest_corpus(argv[1]);
  for (std::size_t i = 0; i < corpus.size(); ++i) {
    const std::string text = digest_text(corpus[i].second);
    std::printf("%zu %s %016llx %zu%s\n", i, corpus[i].first.c_str(), (unsigned long long)fnv1a(text), text.size(),
                text.rfind("refused", 0) == 0 ? (" " + text.substr(0, 120)).c_str() : "");
  }
}
