// mutator.cpp -- see mutator.h.
#include "mutator.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace grassfire::fuzz {

namespace {

constexpr std::size_t kMaxInput = 1 << 20;

const std::vector<std::string>& interesting_numbers() {
  static const std::vector<std::string> n = {
      "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e308", "1e309", "-1e309", "1e-320", "4.9e-324",
      "0", "-0", "-1", "1", "2", "3", "255", "256", "65535", "65536", "2147483647", "2147483648", "-2147483649",
      "4294967295", "4294967296", "1000000000000", "9223372036854775807", "9223372036854775808",
      "18446744073709551615", "18446744073709551616", "999999999999999999999999999999", "0.1", "1e400000",
      "1e-400000", "0x10", "1/2", "1e+6", "3.4028235e38", "1.7976931348623157e308", "1e", ".", "-", "+.e-",
      "1e999999999999", "00000000000000000000000000001"};
  return n;
}

const std::vector<std::string>& interesting_bytes() {
  static const std::vector<std::string> b = {"\n", " ", "\t", "\r", "#", "-", ".", "e", "0", "9", ",", "(", ")", "{",
                                             "}", "[", "]", "\"", ":", std::string(1, '\0'), "\xff", "/"};
  return b;
}

bool is_number_char(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'; }

// [begin, end) of the maximal runs of non-space characters, or of number characters that
// hold a digit.
std::vector<std::pair<std::size_t, std::size_t>> runs(const std::string& s, bool numbers) {
  const auto in = [&](char c) { return numbers ? is_number_char(c) : !std::isspace(static_cast<unsigned char>(c)); };
  std::vector<std::pair<std::size_t, std::size_t>> r;
  for (std::size_t i = 0; i < s.size();) {
    if (!in(s[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    bool digit = false;
    for (; j < s.size() && in(s[j]); ++j) digit = digit || std::isdigit(static_cast<unsigned char>(s[j]));
    if (!numbers || digit) r.push_back({i, j});
    i = j;
  }
  return r;
}

std::vector<std::pair<std::size_t, std::size_t>> lines(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> r;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i)
    if (i == s.size() || s[i] == '\n') {
      r.push_back({start, std::min(i + 1, s.size())});
      start = i + 1;
    }
  return r;
}

std::string pick(const std::vector<std::string>& v, Rng& rng) { return v[rng.below(v.size())]; }

void replace_number(std::string& s, Rng& rng) {
  const auto r = runs(s, true);
  if (r.empty()) return;
  const auto [b, e] = r[rng.below(r.size())];
  std::string text = pick(interesting_numbers(), rng);
  if (rng.chance(30)) {  // arithmetic on the number instead
    const std::string old = s.substr(b, e - b);
    const long long v = std::strtoll(old.c_str(), nullptr, 10);
    const long long choices[] = {v + 1, v - 1, -v, v * 10, v * 1000003, v / 2};
    text = std::to_string(choices[rng.below(6)]);
  }
  s.replace(b, e - b, text);
}

void swap_tokens(std::string& s, Rng& rng) {
  const auto r = runs(s, false);
  if (r.size() < 2) return;
  auto a = r[rng.below(r.size())], b = r[rng.below(r.size())];
  if (a.first > b.first) std::swap(a, b);
  if (a.second > b.first) return;
  const std::string ta = s.substr(a.first, a.second - a.first), tb = s.substr(b.first, b.second - b.first);
  s.replace(b.first, b.second - b.first, ta);
  s.replace(a.first, a.second - a.first, tb);
}

void mutate_lines(std::string& s, Rng& rng) {
  const auto l = lines(s);
  if (l.empty()) return;
  const auto [b, e] = l[rng.below(l.size())];
  const std::string line = s.substr(b, e - b);
  switch (rng.below(3)) {
    case 0: s.insert(b, line); break;                       // duplicate
    case 1: s.erase(b, e - b); break;                       // delete
    default: {                                              // move elsewhere
      s.erase(b, e - b);
      const auto l2 = lines(s);
      s.insert(l2[rng.below(l2.size())].first, line);
    }
  }
}

void overwrite_word(std::string& s, Rng& rng) {
  if (s.size() < 4) return;
  static const std::uint32_t words[] = {0, 1, 0x7fffffff, 0x80000000, 0xffffffff, 0x7fc00000 /* NaN */,
                                        0x7f800000 /* inf */, 0xff800000, 0x00000001 /* denormal */, 1000000, 3};
  std::uint32_t w = words[rng.below(sizeof words / sizeof words[0])];
  if (rng.chance(20)) w = static_cast<std::uint32_t>(rng.next());
  const std::size_t at = rng.chance(30) && s.size() >= 84 ? 80 : rng.below(s.size() - 3);
  std::memcpy(&s[at], &w, 4);
}

void mutate_once(std::string& s, const std::vector<std::string>& corpus, Rng& rng) {
  const std::size_t n = s.size();
  switch (rng.below(13)) {
    case 0: if (n) s[rng.below(n)] ^= static_cast<char>(1u << rng.below(8)); break;
    case 1: if (n) s[rng.below(n)] = pick(interesting_bytes(), rng)[0]; break;
    case 2: {
      std::string add = rng.chance(50) ? pick(interesting_bytes(), rng) : pick(interesting_numbers(), rng);
      for (std::size_t k = rng.below(4); k > 0; --k) add += static_cast<char>(rng.below(256));
      s.insert(n ? rng.below(n + 1) : 0, add);
      break;
    }
    case 3: if (n) { const std::size_t b = rng.below(n); s.erase(b, 1 + rng.below(std::min<std::size_t>(n - b, 64))); } break;
    case 4: if (n) { const std::size_t b = rng.below(n); const std::string chunk = s.substr(b, 1 + rng.below(256)); s.insert(rng.below(n + 1), chunk); } break;
    case 5: if (n) s.resize(rng.below(n)); break;
    case 6: swap_tokens(s, rng); break;
    case 7: case 8: replace_number(s, rng); break;
    case 9: mutate_lines(s, rng); break;
    case 10: {  // splice: a prefix of this input, a suffix of another
      const std::string& other = corpus[rng.below(corpus.size())];
      s = s.substr(0, n ? rng.below(n + 1) : 0) + other.substr(other.empty() ? 0 : rng.below(other.size()));
      break;
    }
    case 11: overwrite_word(s, rng); break;
    default: {  // a long token: digits, letters or an opening bracket repeated
      const char fill[] = {'9', 'a', '(', '[', '{', '-', ' '};
      s.insert(n ? rng.below(n + 1) : 0, std::string(1000 + rng.below(200000), fill[rng.below(sizeof fill)]));
    }
  }
  if (s.size() > kMaxInput) s.resize(kMaxInput);
}

}  // namespace

std::uint64_t Rng::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::size_t Rng::below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

std::uint64_t input_seed(std::uint64_t seed, const std::string& reader, std::uint64_t index) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the reader name
  for (char c : reader) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  Rng r(seed ^ h);
  r.next();
  return r.next() ^ (index * 0x9e3779b97f4a7c15ull);
}

std::string mutate(const std::vector<std::string>& corpus, Rng& rng) {
  std::string s = corpus[rng.below(corpus.size())];
  // Half the inputs carry one mutation, so that more of them pass the parser and reach the
  // checks behind it; the others stack 2 to 4.
  for (std::size_t k = rng.chance(50) ? 1 : 2 + rng.below(3); k > 0; --k) mutate_once(s, corpus, rng);
  return s;
}

}  // namespace grassfire::fuzz
