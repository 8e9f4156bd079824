// caption_printf.h -- printf-style formatting into a std::string, for the numbers that
// figure captions and panel titles print (Figs. 3.5 and 3.8).
#pragma once

#include <cstdio>
#include <string>

namespace grassfire::figures {

// The text std::snprintf would write, of whatever length.
template <class... Args>
std::string caption_printf(const char* format, Args... args) {
  const int n = std::snprintf(nullptr, 0, format, args...);
  if (n <= 0) return {};
  std::string out(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), format, args...);
  out.pop_back();
  return out;
}

}  // namespace grassfire::figures
