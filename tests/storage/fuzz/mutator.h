#pragma once
// A bounded, deterministic mutational fuzzer for the parsers a user feeds
// (issue 16): no libFuzzer needed, the same inputs on every run for a seed.
// Each input is one of the seeds after 1 (half of them) to 8 mutations: byte flips, bytes
// set to values that trip parsers, inserted / deleted / duplicated ranges,
// splices with another seed, truncation, and (for text) numbers replaced by
// extreme ones and structural characters inserted or removed.
#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace rockface::fuzz {

class Mutator {
 public:
  // `page_size` > 0: the inputs are paged files (SQLite); half of the byte
  // mutations then hit a page's header or the file header, where a damaged
  // byte reaches the parser rather than an image blob.
  Mutator(std::vector<std::string> seeds, std::uint64_t seed, bool text, std::size_t page_size = 0)
      : seeds_(std::move(seeds)), rng_(seed), text_(text), page_size_(page_size) {}

  std::string next() {
    std::string s = seeds_[pick(seeds_.size())];
    // Mostly one mutation (an input that still parses as JSON reaches the
    // field checks), sometimes up to eight.
    const int rounds = pick(2) == 0 ? 1 : 1 + static_cast<int>(pick(8));
    for (int r = 0; r < rounds; ++r) mutate(s);
    return s;
  }

 private:
  std::size_t pick(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng_() % n); }

  // A position in s to mutate.
  std::size_t position(const std::string& s) {
    constexpr std::size_t kFileHeader = 100, kPageHeader = 12;
    if (page_size_ > 0 && s.size() > kFileHeader && pick(2) == 0) {
      const std::size_t at = pick(2) == 0
                                 ? pick(kFileHeader)
                                 : pick(s.size() / page_size_ + 1) * page_size_ + pick(kPageHeader);
      if (at < s.size()) return at;
    }
    return pick(s.size());
  }

  void mutate(std::string& s) {
    const int kinds = text_ ? 10 : 7;
    switch (pick(static_cast<std::size_t>(kinds))) {
      case 0:  // flip a bit
        if (!s.empty()) s[position(s)] ^= static_cast<char>(1u << pick(8));
        break;
      case 1: {  // a byte parsers trip on
        static constexpr std::array<unsigned char, 12> kBytes{0,    0xff, 0x7f, 0x80, '"', '\\',
                                                              '\n', ',',  '-',  '.',  '{', '['};
        if (!s.empty()) s[position(s)] = static_cast<char>(kBytes[pick(kBytes.size())]);
        break;
      }
      case 2: {  // insert random bytes
        const std::size_t at = pick(s.size() + 1), n = 1 + pick(16);
        std::string bytes;
        for (std::size_t i = 0; i < n; ++i) bytes += static_cast<char>(pick(256));
        s.insert(at, bytes);
        break;
      }
      case 3:  // delete a range
        if (!s.empty()) {
          const std::size_t at = pick(s.size());
          s.erase(at, 1 + pick(std::min<std::size_t>(64, s.size() - at)));
        }
        break;
      case 4:  // duplicate a range
        if (!s.empty() && s.size() < (1u << 20)) {
          const std::size_t at = pick(s.size()),
                            n = 1 + pick(std::min<std::size_t>(256, s.size() - at));
          s.insert(pick(s.size() + 1), s.substr(at, n));
        }
        break;
      case 5: {  // splice with another seed
        const std::string& other = seeds_[pick(seeds_.size())];
        if (!other.empty() && !s.empty()) {
          const std::size_t a = pick(s.size()), b = pick(other.size());
          s = s.substr(0, a) + other.substr(b);
        }
        break;
      }
      case 6:  // truncate
        if (!s.empty()) s.resize(pick(s.size()));
        break;
      case 7: {  // a number replaced by an extreme one
        static constexpr std::array<std::string_view, 14> kNumbers{
            "0",   "-0",  "-1",  "1e308",  "1e309",      "-1e309",
            "nan", "NaN", "inf", "1e-320", "4294967296", "-9223372036854775809",
            "0.5", "null"};
        replace_number(s, std::string(kNumbers[pick(kNumbers.size())]));
        break;
      }
      case 8: {  // a JSON value replaced by one of another type
        static constexpr std::array<std::string_view, 8> kValues{
            "[]", "{}", "\"\"", "true", "null", "[[[[[[[[]]]]]]]]", "{\"a\":1}", "\"x\""};
        replace_number(s, std::string(kValues[pick(kValues.size())]));
        break;
      }
      case 9: {  // structure: remove or insert a bracket or separator
        static constexpr std::string_view kStructure = "{}[],:\"";
        const char c = kStructure[pick(kStructure.size())];
        const auto at = s.find(c, pick(s.size() + 1));
        if (at != std::string::npos && pick(2) == 0)
          s.erase(at, 1);
        else
          s.insert(pick(s.size() + 1), 1, c);
        break;
      }
    }
  }

  // Replaces the number (or word) found from a random position on.
  void replace_number(std::string& s, const std::string& with) {
    if (s.empty()) return;
    std::size_t at = pick(s.size());
    while (at < s.size() && !(std::isdigit(static_cast<unsigned char>(s[at])) || s[at] == '-'))
      ++at;
    if (at == s.size()) return;
    std::size_t end = at + 1;
    while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '.' ||
                              s[end] == '-' || s[end] == '+'))
      ++end;
    s.replace(at, end - at, with);
  }

  std::vector<std::string> seeds_;
  std::mt19937_64 rng_;
  bool text_;
  std::size_t page_size_;
};

}  // namespace rockface::fuzz
