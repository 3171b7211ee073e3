#include "scene/csv.hpp"

#include <locale.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "scene/input_file.hpp"

namespace coatfft::scene {

namespace fs = std::filesystem;

namespace {

// The values of a CSV file, row after row, and where its first row is.
struct CsvTable {
  std::vector<double> values;
  std::size_t rows = 0, cols = 0;
  std::size_t first_line = 0;
};

// A value's place in a CSV file, for messages: "PATH:LINE: row R, column C: ".
struct CsvPlace {
  const fs::path& path;
  std::size_t line, row, column;
};
std::ostream& operator<<(std::ostream& os, const CsvPlace& at) {
  return os << at.path.string() << ':' << at.line << ": row " << at.row << ", column " << at.column
            << ": ";
}

bool is_csv_separator(char c) {
  return c == ' ' || c == ',' || c == ';' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// strtod in the "C" locale (a decimal point, whatever locale the program set).
double c_strtod(const std::string& text) {
  static const locale_t c_locale = ::newlocale(LC_ALL_MASK, "C", locale_t{});
  return ::strtod_l(text.c_str(), nullptr, c_locale);
}

double parse_csv_value(const CsvPlace& at, std::string_view token) {
  std::string_view number = token;
  if (number.size() > 1 && number[0] == '+' && number[1] != '-' && number[1] != '+')
    number.remove_prefix(1);  // from_chars takes no '+'
  double value = 0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  COATFFT_REQUIRE(end == number.data() + number.size() &&
                      (error == std::errc{} || error == std::errc::result_out_of_range),
                  at, quoted_excerpt(token), " is not a number");
  if (error == std::errc{}) return value;
  // from_chars reports underflow and overflow alike; strtod tells them apart and gives an
  // underflow its IEEE value (0 or a subnormal), as numpy.loadtxt reads it.
  value = c_strtod(std::string(number));
  COATFFT_REQUIRE(std::abs(value) != HUGE_VAL, at, quoted_excerpt(token),
                  " is out of the range of float64");
  return value;
}

// Reads the values of one line (comment included) into `table`; a line without values is skipped.
void read_csv_line(const fs::path& path, std::size_t line_number, std::string_view line,
                   CsvTable& table) {
  std::size_t column = 0;
  for (const std::string_view token : csv_tokens(line)) {
    table.values.push_back(parse_csv_value({path, line_number, table.rows, column}, token));
    ++column;
  }
  if (column == 0) return;
  if (table.rows == 0) {
    table.cols = column;
    table.first_line = line_number;
  }
  COATFFT_REQUIRE(column == table.cols, path.string(), ':', line_number, ": row ", table.rows,
                  " has ", column, " columns, row 0 (line ", table.first_line, ") has ",
                  table.cols);
  ++table.rows;
}

}  // namespace

std::vector<std::string_view> csv_tokens(std::string_view line) {
  line = line.substr(0, line.find('#'));
  std::vector<std::string_view> tokens;
  for (std::size_t pos = 0;;) {
    while (pos < line.size() && is_csv_separator(line[pos])) ++pos;
    if (pos == line.size()) break;
    std::size_t end = pos;
    while (end < line.size() && !is_csv_separator(line[end])) ++end;
    tokens.push_back(line.substr(pos, end - pos));
    pos = end;
  }
  return tokens;
}

double csv_value(const fs::path& path, std::size_t line, std::size_t row, std::size_t column,
                 std::string_view token) {
  return parse_csv_value({path, line, row, column}, token);
}

Field read_csv_matrix(const fs::path& path, std::uintmax_t max_bytes) {
  const std::string text = read_input_file(path, "a CSV file", max_bytes);
  CsvTable table;
  std::size_t line_number = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    read_csv_line(path, ++line_number, std::string_view(text).substr(begin, end - begin), table);
    begin = end + 1;
  }
  COATFFT_REQUIRE(table.rows > 0, path.string(), ": no data");
  Field field(static_cast<Eigen::Index>(table.cols), static_cast<Eigen::Index>(table.rows));
  std::copy(table.values.begin(), table.values.end(), field.data());
  return field;
}

}  // namespace coatfft::scene
