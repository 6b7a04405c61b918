#include "mpm/io/csv_log.hpp"

#include "mpm/io/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "mpm/io/number_format.hpp"

namespace mpm::io {
namespace {

// RFC 4180: quote a name that holds a comma, a quote or a line break.
std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

}  // namespace

CsvLog::CsvLog(std::filesystem::path path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("CsvLog: '" + path_.string() + "' has no columns");
  write_atomically(path_, [this](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    for (std::size_t i = 0; i < columns_.size(); ++i) out << (i ? "," : "") << csv_quote(columns_[i]);
    out << '\n';
    out.close();
    if (!out) throw std::runtime_error("CsvLog: cannot write '" + path_.string() + "'");
  });
  out_.open(path_, std::ios::binary | std::ios::app);
  if (!out_) throw std::runtime_error("CsvLog: cannot open '" + path_.string() + "' to append");
}

CsvLog::CsvLog(std::filesystem::path path, std::vector<std::string> columns, const FileMark& from)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("CsvLog: '" + path_.string() + "' has no columns");
  continue_file(from, path_);
  std::ifstream in(path_, std::ios::binary);
  std::string line, header;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) header += ',';
    header += csv_quote(columns_[i]);
  }
  if (!std::getline(in, line) || line != header)
    throw std::runtime_error("cannot continue '" + path_.string() + "': its header is not '" + header + "'");
  for (int number = 2; std::getline(in, line); ++number) {
    std::vector<double> row;
    for (std::size_t begin = 0; begin <= line.size();) {
      const std::size_t end = std::min(line.find(',', begin), line.size());
      double v = 0;
      if (begin == end) {  // an empty cell: no data
        row.push_back(no_data());
        begin = end + 1;
        continue;
      }
      const auto [ptr, error] = std::from_chars(line.data() + begin, line.data() + end, v);
      if (error != std::errc() || ptr != line.data() + end)
        throw std::runtime_error("cannot continue '" + path_.string() + "': line " + std::to_string(number) +
                                 " is not a row of numbers (or empty cells)");
      row.push_back(v);
      begin = end + 1;
    }
    if (row.size() != columns_.size())
      throw std::runtime_error("cannot continue '" + path_.string() + "': line " + std::to_string(number) + " has " +
                               std::to_string(row.size()) + " values for " + std::to_string(columns_.size()) +
                               " columns");
  }
  in.close();
  out_.open(path_, std::ios::binary | std::ios::app);
  if (!out_) throw std::runtime_error("CsvLog: cannot open '" + path_.string() + "' to append");
}

void CsvLog::append(const std::vector<double>& row) {
  if (row.size() != columns_.size())
    throw std::invalid_argument("CsvLog::append: row of " + std::to_string(row.size()) + " values for " +
                                std::to_string(columns_.size()) + " columns in '" + path_.string() + "'");
  std::string line;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i) line += ',';
    if (is_no_data(row[i])) continue;  // an empty cell
    if (!std::isfinite(row[i]))
      throw std::invalid_argument("CsvLog::append: non-finite value in column '" + columns_[i] + "' of '" +
                                  path_.string() + "'");
    line += format_double(row[i]);
  }
  line += '\n';
  out_.write(line.data(), static_cast<std::streamsize>(line.size()));
  out_.flush();
  if (!out_) throw std::runtime_error("CsvLog: cannot write '" + path_.string() + "'");
}

}  // namespace mpm::io
