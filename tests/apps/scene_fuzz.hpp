#pragma once
// Mutations of scene files for the scene-parser fuzz test (test_scene_fuzz.cpp, scripts/fuzz_scenes.sh): what a
// user's typo or a damaged file does to a scene. Deterministic for a seed on every platform: std::mt19937_64 is
// specified bit for bit, and the draws use only its raw output (the standard distributions are not).
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace fuzz {

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed) {}
  /// A whole number in [0, n).
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(engine_() % n); }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v[below(v.size())];
  }

 private:
  std::mt19937_64 engine_;
};

/// The kinds of mutation (each case applies one to three of them).
enum class Mutation { delete_line, duplicate_line, extreme_number, wrong_type, truncate, flip_byte, swap_lines };

inline const char* mutation_name(Mutation m) {
  constexpr const char* names[] = {"delete line", "duplicate line", "extreme number", "wrong type",
                                   "truncate",    "flip byte",      "swap lines"};
  return names[static_cast<int>(m)];
}

inline std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return lines;
}

inline std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + '\n';
  return text;
}

/// The positions [begin, end) of the numbers in `line` (digits with sign, point and exponent).
inline std::vector<std::pair<std::size_t, std::size_t>> numbers_in(const std::string& line) {
  std::vector<std::pair<std::size_t, std::size_t>> found;
  for (std::size_t i = 0; i < line.size();) {
    const bool starts = std::isdigit(static_cast<unsigned char>(line[i])) ||
                        ((line[i] == '-' || line[i] == '.') && i + 1 < line.size() &&
                         std::isdigit(static_cast<unsigned char>(line[i + 1])));
    if (!starts || (i > 0 && (std::isalnum(static_cast<unsigned char>(line[i - 1])) || line[i - 1] == '_'))) {
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < line.size() &&
           (std::isdigit(static_cast<unsigned char>(line[j])) || line[j] == '.' || line[j] == 'e' || line[j] == 'E' ||
            ((line[j] == '-' || line[j] == '+') && (line[j - 1] == 'e' || line[j - 1] == 'E'))))
      ++j;
    found.emplace_back(i, j);
    i = j;
  }
  return found;
}

/// The values a number is replaced with: limits of double, zero and signs, huge counts, non-numbers.
inline const std::vector<std::string>& extreme_numbers() {
  static const std::vector<std::string> values{"0",       "-0",
                                               "-1",      "1e308",
                                               "-1e308",  "5e-324",
                                               "-5e-324", "1e-300",
                                               "1e300",   "1e6",
                                               "1e9",     "1e12",
                                               "1e-9",    "1e-15",
                                               ".nan",    ".inf",
                                               "-.inf",   "2147483648",
                                               "0x10",    "1e400",
                                               "nan",     "inf",
                                               "1.5",     "-1e-9",
                                               "3",       "100",
                                               "101",     "1e200",
                                               "x/0",     "0/0",
                                               "1e-6",    "7",
                                               "99999",   "123456789012345678901234567890"};
  return values;
}

/// A value of another YAML type than the one expected.
inline const std::vector<std::string>& wrong_types() {
  static const std::vector<std::string> values{"[1, 2]", "{a: 1}", "\"text\"",     "~",   "",      "[]",
                                               "{}",     "true",   "[[1]]",        "- 1", "&a 1",  "*a",
                                               "!!str",  "'",      "[1, 2, 3, 4]", "abc", "{x: [", ": :"};
  return values;
}

/// One mutation of `text`; `what` receives a description (for the report of a failing case).
inline std::string mutate(const std::string& text, Draw& draw, std::string& what) {
  std::vector<std::string> lines = split_lines(text);
  const auto m = static_cast<Mutation>(draw.below(7));
  what += std::string(mutation_name(m));
  if (lines.empty()) return text + "x: 1\n";
  const std::size_t k = draw.below(lines.size());
  switch (m) {
    case Mutation::delete_line:
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(k));
      break;
    case Mutation::duplicate_line:
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(k), lines[k]);
      break;
    case Mutation::swap_lines:
      std::swap(lines[k], lines[draw.below(lines.size())]);
      break;
    case Mutation::extreme_number: {
      // A line with a number (searched from k on): one of its numbers replaced.
      for (std::size_t n = 0; n < lines.size(); ++n) {
        std::string& line = lines[(k + n) % lines.size()];
        const auto found = numbers_in(line);
        if (found.empty()) continue;
        const auto [b, e] = found[draw.below(found.size())];
        const std::string& value = draw.pick(extreme_numbers());
        what += " '" + line.substr(b, e - b) + "' -> '" + value + "'";
        line.replace(b, e - b, value);
        break;
      }
      break;
    }
    case Mutation::wrong_type: {
      // The value after a key's colon (or after a list's dash) replaced.
      std::string& line = lines[k];
      std::size_t at = line.find(": ");
      if (at == std::string::npos) at = line.find("- ");
      if (at == std::string::npos) at = line.size() > 0 ? line.size() - 1 : 0;
      const std::string& value = draw.pick(wrong_types());
      what += " line " + std::to_string(k + 1) + " -> '" + value + "'";
      line = line.substr(0, std::min(line.size(), at + 2)) + value;
      break;
    }
    case Mutation::truncate: {
      const std::string joined = join_lines(lines);
      const std::size_t at = draw.below(joined.size() + 1);
      what += " at byte " + std::to_string(at);
      return joined.substr(0, at);
    }
    case Mutation::flip_byte: {
      std::string joined = join_lines(lines);
      if (joined.empty()) return joined;
      const std::size_t at = draw.below(joined.size());
      const auto bit = static_cast<char>(1 << draw.below(8));
      joined[at] = static_cast<char>(joined[at] ^ bit);
      what += " byte " + std::to_string(at);
      return joined;
    }
  }
  return join_lines(lines);
}

}  // namespace fuzz
