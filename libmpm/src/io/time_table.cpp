// A time history from a CSV file (io/time_table.hpp).
#include "mpm/io/time_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>

namespace mpm::io {
namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t begin = 0;
  while (true) {
    const auto comma = line.find(',', begin);
    cells.push_back(trimmed(line.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin)));
    if (comma == std::string::npos) return cells;
    begin = comma + 1;
  }
}

/// A finite number spelt as the whole of `text`, or nothing ("nan", "inf", "1.5x" and "" are not).
std::optional<double> finite_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

[[noreturn]] void fail_at(const std::string& file, int line, const std::string& message) {
  throw TimeTableError(fmt::format("{}:{}: {}", file, line, message));
}

}  // namespace

std::array<double, 3> TimeTable::at(double t) const {
  if (t <= time.front()) return values.front();
  if (t >= time.back()) return values.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(time.begin(), time.end(), t) - time.begin());  // t < time[k]
  const double s = (t - time[k - 1]) / (time[k] - time[k - 1]);
  std::array<double, 3> v{};
  for (std::size_t c = 0; c < 3; ++c) v[c] = (1 - s) * values[k - 1][c] + s * values[k][c];
  return v;
}

TimeTable read_time_table(const std::filesystem::path& file, const std::vector<std::string>& columns) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) throw TimeTableError(name + ": cannot be opened");
  TimeTable table;
  table.file = file;
  std::vector<int> slot;  // per value column of the header, its slot in `columns`
  std::string header_text;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = trimmed(line);
    if (text.empty() || text[0] == '#') continue;
    auto fail = [&](const std::string& message) { fail_at(name, number, message); };
    const std::vector<std::string> cells = split(text);
    if (header_text.empty()) {  // the header
      header_text = text;
      if (cells[0] != "t")
        fail(fmt::format("the first column of the header must be t (s), got '{}' (expected a header such as t, {})",
                         cells[0], fmt::join(columns, ", ")));
      for (std::size_t c = 1; c < cells.size(); ++c) {
        const auto at = std::find(columns.begin(), columns.end(), cells[c]);
        if (at == columns.end())
          fail(fmt::format("unknown column '{}'; valid columns after t: {}", cells[c], fmt::join(columns, ", ")));
        const int s = static_cast<int>(at - columns.begin());
        if (std::find(slot.begin(), slot.end(), s) != slot.end())
          fail(fmt::format("column '{}' given twice", cells[c]));
        slot.push_back(s);
      }
      if (slot.empty())
        fail(fmt::format("the header names no value column (expected t, {})", fmt::join(columns, ", ")));
      continue;
    }
    if (cells.size() != slot.size() + 1)
      fail(fmt::format("expected {} values ({}), got {}", slot.size() + 1, header_text, cells.size()));
    std::array<double, 4> row{};
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const auto v = finite_number(cells[c]);
      if (!v)
        fail(fmt::format("'{}' is not a finite number (column {})", cells[c],
                         c == 0 ? std::string("t") : columns[static_cast<std::size_t>(slot[c - 1])]));
      row[c] = *v;
    }
    if (!table.time.empty() && !(row[0] > table.time.back()))
      fail(fmt::format("time {:g} s does not come after the previous row's {:g} s (times must increase)", row[0],
                       table.time.back()));
    table.time.push_back(row[0]);
    std::array<double, 3> values{};
    for (std::size_t c = 0; c < slot.size(); ++c) values[static_cast<std::size_t>(slot[c])] = row[c + 1];
    table.values.push_back(values);
  }
  if (header_text.empty()) throw TimeTableError(name + ": empty (expected a header line t, ... and rows of numbers)");
  if (table.time.empty()) throw TimeTableError(name + ": has a header but no rows");
  return table;
}

}  // namespace mpm::io
