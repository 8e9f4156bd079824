// main.cpp -- runs every registered proof check and prints the report table.
//
// usage: proof_checks [--quick] [--data DIR] [--only NAME] [--markdown FILE] [--html FILE]
// Exit code 0 when every row passes, 1 otherwise, 2 on a bad command line.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "check_registry.h"

namespace grassfire::checks {

namespace {
std::vector<std::pair<std::string, CheckFn>>& registry() {
  static std::vector<std::pair<std::string, CheckFn>> list;
  return list;
}

std::string format_violation(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

void write_markdown(std::ostream& os, const std::vector<CheckRow>& rows) {
  os << "| proposition | corpus | instances | points checked | worst violation | verdict | note |\n"
        "|---|---|---:|---:|---:|---|---|\n";
  for (const CheckRow& r : rows)
    os << "| " << r.proposition << " | " << r.corpus << " | " << r.instances << " | " << r.points << " | "
       << format_violation(r.worst_violation) << " " << r.unit << " | " << (r.pass ? "pass" : "FAIL") << " | "
       << r.note << " |\n";
}

void write_html(std::ostream& os, const std::vector<CheckRow>& rows) {
  os << "<table class=\"checks\"><tr><th>proposition</th><th>corpus</th><th>instances</th><th>points checked</th>"
        "<th>worst violation</th><th>verdict</th><th>note</th></tr>\n";
  for (const CheckRow& r : rows)
    os << "<tr><td>" << r.proposition << "</td><td>" << r.corpus << "</td><td>" << r.instances << "</td><td>"
       << r.points << "</td><td>" << format_violation(r.worst_violation) << " " << r.unit << "</td><td class=\""
       << (r.pass ? "pass\">pass" : "fail\">FAIL") << "</td><td>" << r.note << "</td></tr>\n";
  os << "</table>\n";
}
}  // namespace

bool register_check(std::string name, CheckFn fn) {
  registry().emplace_back(std::move(name), std::move(fn));
  return true;
}

std::vector<std::pair<std::string, CheckFn>> registered_checks() {
  auto list = registry();
  std::stable_sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return list;
}

}  // namespace grassfire::checks

int main(int argc, char** argv) {
  using namespace grassfire::checks;
  CheckContext ctx;
  ctx.data_dir = GF_PROJECT_DATA;
  std::string only, markdown, html;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "proof_checks: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--quick")
      ctx.quick = true;
    else if (a == "--data")
      ctx.data_dir = value();
    else if (a == "--only")
      only = value();
    else if (a == "--markdown")
      markdown = value();
    else if (a == "--html")
      html = value();
    else if (a == "--help" || a == "-h") {
      std::cout << "usage: proof_checks [--quick] [--data DIR] [--only NAME] [--markdown FILE] [--html FILE]\n"
                   "Checks the dissertation's propositions numerically and prints the report table.\n"
                   "Exit code 0 when every row passes.\nchecks:";
      for (const auto& [name, fn] : registered_checks()) std::cout << " " << name;
      std::cout << "\n";
      return 0;
    } else {
      std::cerr << "proof_checks: unknown argument '" << a << "' (see --help)\n";
      return 2;
    }
  }
  std::vector<CheckRow> rows;
  for (const auto& [name, fn] : registered_checks()) {
    if (!only.empty() && name != only) continue;
    const auto start = std::chrono::steady_clock::now();
    std::cerr << "proof_checks: running " << name << " ..." << std::endl;
    for (CheckRow& r : fn(ctx)) rows.push_back(std::move(r));
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cerr << "proof_checks: " << name << " done in " << secs << " s" << std::endl;
  }
  write_markdown(std::cout, rows);
  if (!markdown.empty()) {
    std::ofstream f(markdown);
    write_markdown(f, rows);
  }
  if (!html.empty()) {
    std::ofstream f(html);
    write_html(f, rows);
  }
  const bool all_pass = !rows.empty() && std::all_of(rows.begin(), rows.end(), [](const CheckRow& r) { return r.pass; });
  return all_pass ? 0 : 1;
}
