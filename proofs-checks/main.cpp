// main.cpp -- runs every registered proof check, prints the report, and with --mutants
// reruns each check once per mutant to show that every checked row can fail.
//
// usage: proof_checks [--quick] [--data DIR] [--only NAME] [--markdown FILE] [--html FILE]
//                     [--mutants | --mutants-only]
// Corpora: full by default, --quick the CTest size. The mutant runs use the tiny corpora
// for the clean run and every mutant alike (one run of a check per mutant).
// Exit code 0 when no row fails and, with mutants, every checked row detected at least
// one mutant; 1 otherwise; 2 on a bad command line.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "check_registry.h"
#include "report.h"

namespace grassfire::checks {

namespace {

std::vector<RegisteredCheck>& registry() {
  static std::vector<RegisteredCheck> list;
  return list;
}

std::vector<CheckRow> run_check(const RegisteredCheck& c, const CheckContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  std::cerr << "proof_checks: running " << c.name << (ctx.mutant.empty() ? "" : " with mutant " + ctx.mutant)
            << " ..." << std::endl;
  std::vector<CheckRow> rows = c.fn(ctx);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "proof_checks: " << c.name << " done in " << secs << " s" << std::endl;
  return rows;
}

// One clean run and one run per mutant of a check, at the same corpus size; rows are
// matched by (proposition, corpus).
void run_mutants(const RegisteredCheck& c, CheckContext ctx, MutantReport& report) {
  ctx.mutant.clear();
  const std::vector<CheckRow> clean = run_check(c, ctx);
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  const std::size_t first = report.rows.size();
  for (const CheckRow& r : clean) {
    index[{r.proposition, r.corpus}] = report.rows.size();
    report.rows.push_back({r.proposition, r.corpus, r.verdict, {}, {}});
  }
  for (const MutantInfo& m : c.mutants) {
    report.legend.push_back({c.name, m});
    ctx.mutant = m.name;
    std::vector<CheckRow> rows;
    try {
      rows = run_check(c, ctx);
    } catch (const std::exception& e) {
      report.problems.push_back(c.name + " with mutant " + m.name + " threw: " + e.what());
      continue;
    }
    for (std::size_t i = first; i < report.rows.size(); ++i) report.rows[i].tried.push_back(m.name);
    for (const CheckRow& r : rows) {
      const auto it = index.find({r.proposition, r.corpus});
      if (it == index.end()) {
        report.problems.push_back(c.name + " with mutant " + m.name + " made a row the clean run has not: " +
                                  r.proposition + " / " + r.corpus);
        continue;
      }
      MutantOutcome& o = report.rows[it->second];
      if (o.clean == Verdict::Pass && r.verdict == Verdict::Fail) o.detected.push_back(m.name);
    }
  }
}

struct Options {
  CheckContext ctx;
  std::string only, markdown, html;
  bool mutants = false, report = true;
};

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "proof_checks: " << message << " (see --help)\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  o.ctx.data_dir = GF_PROJECT_DATA;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--quick")
      o.ctx.size = CorpusSize::Quick;
    else if (a == "--data")
      o.ctx.data_dir = value();
    else if (a == "--only")
      o.only = value();
    else if (a == "--markdown")
      o.markdown = value();
    else if (a == "--html")
      o.html = value();
    else if (a == "--mutants")
      o.mutants = true;
    else if (a == "--mutants-only")
      o.mutants = true, o.report = false;
    else if (a == "--help" || a == "-h") {
      std::cout << "usage: proof_checks [--quick] [--data DIR] [--only NAME] [--markdown FILE] [--html FILE]\n"
                   "                    [--mutants | --mutants-only]\n"
                   "Checks the dissertation's propositions numerically and prints the report table; with\n"
                   "--mutants also reruns every check against deliberately broken engines and prints which\n"
                   "mutants each row detected. Exit code 0 when no row fails and every checked row\n"
                   "detected a mutant.\nchecks:";
      for (const RegisteredCheck& c : registered_checks()) std::cout << " " << c.name;
      std::cout << "\n";
      std::exit(0);
    } else {
      usage_error("unknown argument '" + a + "'");
    }
  }
  return o;
}

}  // namespace

bool register_check(std::string name, CheckFn fn, MutantList mutants) {
  registry().push_back({std::move(name), std::move(fn), std::move(mutants)});
  return true;
}

std::vector<RegisteredCheck> registered_checks() {
  auto list = registry();
  std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return list;
}

}  // namespace grassfire::checks

int main(int argc, char** argv) {
  using namespace grassfire::checks;
  const Options o = parse(argc, argv);
  std::vector<CheckRow> rows;
  MutantReport mutants;
  CheckContext mutant_ctx = o.ctx;
  mutant_ctx.size = CorpusSize::Tiny;
  mutants.corpus_size = "tiny";
  for (const RegisteredCheck& c : registered_checks()) {
    if (!o.only.empty() && c.name != o.only) continue;
    if (o.report)
      for (CheckRow& r : run_check(c, o.ctx)) rows.push_back(std::move(r));
    if (o.mutants) run_mutants(c, mutant_ctx, mutants);
  }
  const MutantReport* m = o.mutants ? &mutants : nullptr;
  write_markdown(std::cout, rows, m);
  if (!o.markdown.empty()) {
    std::ofstream f(o.markdown);
    write_markdown(f, rows, m);
  }
  if (!o.html.empty()) {
    std::ofstream f(o.html);
    write_html(f, rows, m);
  }
  bool ok = !o.report || (!rows.empty() && std::none_of(rows.begin(), rows.end(), [](const CheckRow& r) {
                            return r.verdict == Verdict::Fail;
                          }));
  if (o.mutants) {
    for (const MutantOutcome& r : mutants.rows) {
      if (undetected(r)) std::cerr << "proof_checks: no mutant detected by: " << r.proposition << " / " << r.corpus << "\n";
      ok = ok && !undetected(r) && r.clean != Verdict::Fail;
    }
    ok = ok && mutants.problems.empty() && !mutants.rows.empty();
  }
  return ok ? 0 : 1;
}
