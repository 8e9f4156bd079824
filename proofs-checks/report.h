// report.h -- the proof-check report: the table of rows, the summary, and the mutant table,
// as markdown (`--markdown`, stdout) and as an HTML fragment (`--html`, inlined by the
// gallery of paper-figures/main.cpp).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "check_registry.h"

namespace grassfire::checks {

// What the mutants did to one row: the mutants run against its family, and those that
// turned its clean pass into a fail.
struct MutantOutcome {
  std::string proposition, corpus;
  Verdict clean = Verdict::Fail;
  std::vector<std::string> tried, detected;
};

struct MutantReport {
  std::string corpus_size;                            // the corpora the mutants ran on
  std::vector<MutantOutcome> rows;
  std::vector<std::pair<std::string, MutantInfo>> legend;  // (family, mutant)
  std::vector<std::string> problems;                  // a mutant that threw, rows that differ
};

// A checked row (clean verdict Pass) that detected no mutant: a defect of the checks.
bool undetected(const MutantOutcome& o);

void write_markdown(std::ostream& os, const std::vector<CheckRow>& rows, const MutantReport* mutants);
void write_html(std::ostream& os, const std::vector<CheckRow>& rows, const MutantReport* mutants);

}  // namespace grassfire::checks
