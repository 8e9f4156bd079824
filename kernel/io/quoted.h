// quoted.h -- a token of an input file as the readers' error messages show it.
//
// A token longer than 40 characters is cut to its first 40 followed by "..." and its
// length, so that a message stays one readable line whatever the file holds (a damaged
// file may carry a megabyte-long word). quote_token() adds single quotes (for words that are
// not what was expected), shorten_token() does not (for numbers read, e.g. a negative radius).
#pragma once

#include <string>

namespace grassfire {

inline std::string shorten_token(const std::string& token) {
  constexpr std::size_t kShown = 40;
  if (token.size() <= kShown) return token;
  return token.substr(0, kShown) + "... (" + std::to_string(token.size()) + " characters)";
}

inline std::string quote_token(const std::string& token) {
  constexpr std::size_t kShown = 40;
  if (token.size() <= kShown) return "'" + token + "'";
  return "'" + token.substr(0, kShown) + "...' (" + std::to_string(token.size()) + " characters)";
}

}  // namespace grassfire
