// json_text.cpp -- see json_text.h.
#include "io/json_text.h"

#include <cstring>
#include <set>
#include <vector>

#include "support/quoted.h"

namespace grassfire {
namespace {

// nlohmann quotes the input it stopped at ("last read: '<token>'", "number overflow parsing
// '<token>'", maybe followed by "; expected ..."); a long token is shown shortened.
std::string shorten_quoted_input(const std::string& reason) {
  for (const char* opener : {"last read: '", "parsing '"}) {
    const std::size_t at = reason.find(opener);
    if (at == std::string::npos) continue;
    const std::size_t from = at + std::strlen(opener) - 1;
    std::size_t to = reason.rfind("'; expected");
    if (to == std::string::npos || to < from) to = reason.back() == '\'' ? reason.size() - 1 : std::string::npos;
    if (to == std::string::npos || to <= from) continue;
    return reason.substr(0, from) + quote_token(reason.substr(from + 1, to - from - 1)) + reason.substr(to + 1);
  }
  return reason;
}

// nlohmann's SAX DOM builder behind a filter that keeps number text, watches keys, and
// turns parse errors into positioned messages.
class PositionedDomParser {
 public:
  PositionedDomParser(nlohmann::json& doc, const std::string& text, const std::string& source,
                      const JsonReadOptions& options)
      : dom_(doc), text_(text), source_(source), options_(options) {}

  bool null() { return dom_.null(); }
  bool boolean(bool v) { return dom_.boolean(v); }
  bool number_integer(nlohmann::json::number_integer_t v) { return dom_.number_integer(v); }
  bool number_unsigned(nlohmann::json::number_unsigned_t v) { return dom_.number_unsigned(v); }
  bool number_float(nlohmann::json::number_float_t v, const std::string& s) {
    if (!options_.numbers_as_text) return dom_.number_float(v, s);
    std::string text = s;
    return dom_.string(text);
  }
  bool string(std::string& v) { return dom_.string(v); }
  bool binary(nlohmann::json::binary_t& v) { return dom_.binary(v); }
  bool start_object(std::size_t n) {
    keys_.emplace_back();
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    if (options_.reject_duplicate_keys && !keys_.back().insert(k).second)
      throw JsonSyntaxError(source_ + ": key \"" + shorten_token(k) + "\" appears twice in one object");
    return dom_.key(k);
  }
  bool end_object() {
    keys_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) { return dom_.start_array(n); }
  bool end_array() { return dom_.end_array(); }

  bool parse_error(std::size_t offset, const std::string& /*token*/, const nlohmann::detail::exception& e) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < offset && i < text_.size(); ++i) {
      column = text_[i] == '\n' ? 1 : column + 1;
      line += text_[i] == '\n';
    }
    // e.what() is "[json.exception.<kind>.<id>] [parse error at line L, column C: ]<reason>".
    std::string reason = e.what();
    reason = reason.substr(reason.find("] ") + 2);
    if (reason.rfind("parse error", 0) == 0) reason = reason.substr(reason.find(": ") + 2);
    reason = shorten_quoted_input(reason);
    throw JsonSyntaxError(source_ + ":" + std::to_string(line) + ":" + std::to_string(column) +
                          ": invalid JSON: " + reason);
  }

 private:
  nlohmann::detail::json_sax_dom_parser<nlohmann::json> dom_;
  const std::string& text_;
  const std::string& source_;
  const JsonReadOptions& options_;
  std::vector<std::set<std::string>> keys_;  // keys seen, per open object
};

}  // namespace

nlohmann::json parse_json_text(const std::string& text, const std::string& source, const JsonReadOptions& options) {
  nlohmann::json doc;
  PositionedDomParser parser(doc, text, source, options);
  nlohmann::json::sax_parse(text, &parser);
  return doc;
}

}  // namespace grassfire
