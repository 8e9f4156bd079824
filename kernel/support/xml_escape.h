// xml_escape.h -- text made safe inside XML and HTML elements (SVG captions, reports).
//
// Computes: s with <, > and & replaced by their entities. Complexity: O(|s|).
#pragma once

#include <string>

namespace grassfire {

inline std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

}  // namespace grassfire
