#include "io/csv.hpp"

#include <locale.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::io {

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

// Whether `token` is a whole number as parse_csv_value reads it (out of range included).
bool is_csv_number(std::string_view token) {
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+')
    token.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return end == token.data() + token.size() &&
         (error == std::errc{} || error == std::errc::result_out_of_range);
}

// A word of a header: text with a letter (ASCII, or a UTF-8 sequence such as "µm"), no number.
bool is_header_word(std::string_view token) {
  const auto letter = [](char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || static_cast<unsigned char>(c) >= 0x80;
  };
  const auto control = [](char c) { return static_cast<unsigned char>(c) < 0x20; };
  return std::any_of(token.begin(), token.end(), letter) &&
         std::none_of(token.begin(), token.end(), control) && !is_csv_number(token);
}

// A header line of a spreadsheet or instrument export ("x,y,z", "Height [nm]"): before the first
// row of values, a line of words only. A line with a number among words is a row with a typo, and
// one with control bytes is not text: both are refused as rows.
bool is_csv_header(std::string_view line) {
  const std::vector<std::string_view> tokens = csv_tokens(line);
  return !tokens.empty() && std::all_of(tokens.begin(), tokens.end(), is_header_word);
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
  // A UTF-8 byte order mark (spreadsheet exports) is not part of the first value.
  const std::size_t start = std::string_view(text).starts_with("\xEF\xBB\xBF") ? 3 : 0;
  for (std::size_t begin = start; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view line = std::string_view(text).substr(begin, end - begin);
    ++line_number;
    if (table.rows > 0 || !is_csv_header(line)) read_csv_line(path, line_number, line, table);
    begin = end + 1;
  }
  COATFFT_REQUIRE(table.rows > 0, path.string(), ": no data");
  Field field(static_cast<Eigen::Index>(table.cols), static_cast<Eigen::Index>(table.rows));
  std::copy(table.values.begin(), table.values.end(), field.data());
  return field;
}

}  // namespace coatfft::io
