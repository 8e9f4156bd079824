// report.cpp -- markdown and HTML forms of the proof-check report (see report.h).
#include "report.h"

#include <cstdio>

#include "support/xml_escape.h"

namespace grassfire::checks {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Pass: return "pass";
    case Verdict::Fail: return "FAIL";
    case Verdict::NotChecked: return "not checked";
  }
  return "?";
}

bool undetected(const MutantOutcome& o) { return o.clean == Verdict::Pass && o.detected.empty(); }

namespace {

std::string format_violation(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// A markdown table cell: '|' would end the cell.
std::string md(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string summary(const std::vector<CheckRow>& rows) {
  std::size_t pass = 0, fail = 0, not_checked = 0;
  for (const CheckRow& r : rows)
    (r.verdict == Verdict::Pass ? pass : r.verdict == Verdict::Fail ? fail : not_checked)++;
  return std::to_string(rows.size()) + " rows: " + std::to_string(pass) + " pass, " + std::to_string(fail) +
         " fail, " + std::to_string(not_checked) + " not checked (no independent computation yet; see the note)";
}

std::string detected_cell(const MutantOutcome& o) {
  if (o.clean == Verdict::NotChecked) return "(row not checked)";
  if (o.clean == Verdict::Fail) return "(row fails without a mutant)";
  return o.detected.empty() ? "NONE" : joined(o.detected);
}

}  // namespace

void write_markdown(std::ostream& os, const std::vector<CheckRow>& rows, const MutantReport* mutants) {
  os << "| proposition | corpus | reference | instances | points checked | worst violation | tolerance | verdict | note |\n"
        "|---|---|---|---:|---:|---:|---|---|---|\n";
  for (const CheckRow& r : rows)
    os << "| " << md(r.proposition) << " | " << md(r.corpus) << " | " << md(r.reference) << " | " << r.instances
       << " | " << r.points << " | " << format_violation(r.worst_violation) << " " << r.unit << " | "
       << md(r.tolerance) << " | " << to_string(r.verdict) << " | " << md(r.note) << " |\n";
  os << "\n" << summary(rows) << "\n";
  if (!mutants) return;
  os << "\n### Mutants (" << mutants->corpus_size << " corpora)\n\n"
     << "| proposition | corpus | mutants tried | mutants detected |\n|---|---|---:|---|\n";
  for (const MutantOutcome& o : mutants->rows)
    os << "| " << md(o.proposition) << " | " << md(o.corpus) << " | " << o.tried.size() << " | "
       << md(detected_cell(o)) << " |\n";
  os << "\n| check | mutant | what it breaks |\n|---|---|---|\n";
  for (const auto& [family, m] : mutants->legend) os << "| " << family << " | " << m.name << " | " << md(m.breaks) << " |\n";
  for (const std::string& p : mutants->problems) os << "\nproblem: " << p << "\n";
}

void write_html(std::ostream& os, const std::vector<CheckRow>& rows, const MutantReport* mutants) {
  os << "<table class=\"checks\"><tr><th>proposition</th><th>corpus</th><th>reference</th><th>instances</th>"
        "<th>points checked</th><th>worst violation</th><th>tolerance</th><th>verdict</th><th>note</th></tr>\n";
  for (const CheckRow& r : rows) {
    const char* cls = r.verdict == Verdict::Pass ? "pass" : r.verdict == Verdict::Fail ? "fail" : "notchecked";
    os << "<tr><td>" << xml_escape(r.proposition) << "</td><td>" << xml_escape(r.corpus) << "</td><td>" << xml_escape(r.reference)
       << "</td><td>" << r.instances << "</td><td>" << r.points << "</td><td>" << format_violation(r.worst_violation)
       << " " << xml_escape(r.unit) << "</td><td>" << xml_escape(r.tolerance) << "</td><td class=\"" << cls << "\">"
       << to_string(r.verdict) << "</td><td>" << xml_escape(r.note) << "</td></tr>\n";
  }
  os << "</table>\n<p>" << xml_escape(summary(rows)) << "</p>\n";
  if (!mutants) return;
  os << "<h3>Mutants (" << xml_escape(mutants->corpus_size) << " corpora)</h3>\n"
     << "<p>Each check reruns with one deliberately broken engine output, rule or input; a row detects a "
        "mutant when its pass turns into a fail. Every checked row must detect at least one.</p>\n"
     << "<table class=\"checks\"><tr><th>proposition</th><th>corpus</th><th>mutants tried</th>"
        "<th>mutants detected</th></tr>\n";
  for (const MutantOutcome& o : mutants->rows)
    os << "<tr><td>" << xml_escape(o.proposition) << "</td><td>" << xml_escape(o.corpus) << "</td><td>" << o.tried.size()
       << "</td><td" << (undetected(o) ? " class=\"fail\"" : "") << ">" << xml_escape(detected_cell(o)) << "</td></tr>\n";
  os << "</table>\n<table class=\"checks\"><tr><th>check</th><th>mutant</th><th>what it breaks</th></tr>\n";
  for (const auto& [family, m] : mutants->legend)
    os << "<tr><td>" << xml_escape(family) << "</td><td>" << xml_escape(m.name) << "</td><td>" << xml_escape(m.breaks) << "</td></tr>\n";
  os << "</table>\n";
  for (const std::string& p : mutants->problems) os << "<p class=\"fail\">problem: " << xml_escape(p) << "</p>\n";
}

}  // namespace grassfire::checks
