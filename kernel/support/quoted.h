// quoted.h -- a token of an input file as the readers' error messages show it.
//
// A token longer than 40 characters is cut to its first 40 followed by "..." and its
// length, and bytes that are not printable ASCII are written \xHH, so that a message stays
// one readable line whatever the file holds (a damaged file may carry a megabyte-long
// word, or binary bytes). quote_token() adds single quotes (for words that are not what
// was expected), shorten_token() does not (for numbers read, e.g. a negative radius).
#pragma once

#include <string>

namespace grassfire {

namespace detail {
inline std::string printable_prefix(const std::string& token, std::size_t n) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < token.size() && i < n; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 32 && c < 127) out += static_cast<char>(c);
    else out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  return out;
}
constexpr std::size_t kShownCharacters = 40;
}  // namespace detail

inline std::string shorten_token(const std::string& token) {
  const std::string shown = detail::printable_prefix(token, detail::kShownCharacters);
  if (token.size() <= detail::kShownCharacters) return shown;
  return shown + "... (" + std::to_string(token.size()) + " characters)";
}

inline std::string quote_token(const std::string& token) {
  const std::string shown = detail::printable_prefix(token, detail::kShownCharacters);
  if (token.size() <= detail::kShownCharacters) return "'" + shown + "'";
  return "'" + shown + "...' (" + std::to_string(token.size()) + " characters)";
}

}  // namespace grassfire
