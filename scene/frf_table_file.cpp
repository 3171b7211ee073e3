#include "scene/frf_table_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/input_file.hpp"

namespace coatfft::scene {

namespace fs = std::filesystem;

namespace {

// The columns of the header line: where k and H are, how many there are, and the line, for
// messages.
struct Header {
  std::size_t line = 0;
  std::size_t k = 0, H = 0, columns = 0;
  std::string_view H_name;  // "H", or "frf" in a table written by `coatfft frf`
};

// Columns are found by name: k, and the FRF as H or as frf (the column of `coatfft frf`, whose
// table is read back as it is written). Other columns, such as kh_total, are skipped.
Header read_header(const fs::path& path, std::size_t line, std::string_view text) {
  const std::vector<std::string_view> names = io::csv_tokens(text);
  std::optional<std::size_t> k, H;
  std::string_view H_name;
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::string_view name = names[c];
    if (name != "k" && name != "H" && name != "frf") continue;
    std::optional<std::size_t>& slot = name == "k" ? k : H;
    COATFFT_REQUIRE(!slot, path.string(), ':', line, ": column ", name, " is named twice",
                    name == "k" ? "" : " (H and frf both name the FRF [m/Pa]: give one)");
    slot = c;
    if (name != "k") H_name = name;
  }
  COATFFT_REQUIRE(k, path.string(), ':', line,
                  ": the header names no column k [rad/m] (it must name k and H, e.g. \"k,H\")");
  COATFFT_REQUIRE(H, path.string(), ':', line,
                  ": the header names no column H [m/Pa] (or frf, as coatfft frf writes it; e.g. "
                  "\"k,H\")");
  return {line, *k, *H, names.size(), H_name};
}

struct Rows {
  std::vector<double> k, H;
};

// One data line: one value per column of the header, k and H finite and > 0, k above the previous
// row's. The values of other columns are not read.
void read_row(const fs::path& path, std::size_t line, std::string_view text, const Header& header,
              Rows& rows) {
  const std::vector<std::string_view> tokens = io::csv_tokens(text);
  if (tokens.empty()) return;
  const std::size_t row = rows.k.size();
  COATFFT_REQUIRE(tokens.size() == header.columns, path.string(), ':', line, ": row ", row, " has ",
                  tokens.size(), " values, but the header (line ", header.line, ") names ",
                  header.columns, " columns");
  const double k = io::csv_value(path, line, row, header.k, tokens[header.k]);
  const double H = io::csv_value(path, line, row, header.H, tokens[header.H]);
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, path.string(), ':', line, ": row ", row, ": k = ", k,
                  " rad/m, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(H) && H > 0, path.string(), ':', line, ": row ", row, ": ",
                  header.H_name, " = ", H, " m/Pa, but it must be finite and > 0");
  COATFFT_REQUIRE(row == 0 || k > rows.k.back(), path.string(), ':', line, ": row ", row,
                  ": k = ", k, " rad/m is not above the previous row's k = ", rows.k.back(),
                  ": k must be strictly ascending");
  rows.k.push_back(k);
  rows.H.push_back(H);
}

}  // namespace

std::shared_ptr<const TabulatedFrf> read_frf_table(const fs::path& path, std::optional<double> c0,
                                                   std::optional<double> c_inf) {
  const std::string text = io::read_input_file(path, "an FRF table", kMaxFrfTableBytes);
  std::optional<Header> header;
  Rows rows;
  std::size_t line = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view content = std::string_view(text).substr(begin, end - begin);
    ++line;
    begin = end + 1;
    if (header)
      read_row(path, line, content, *header, rows);
    else if (!io::csv_tokens(content).empty())
      header = read_header(path, line, content);
  }
  COATFFT_REQUIRE(header, path.string(), ": empty; the first line must name the columns (\"k,H\")");
  COATFFT_REQUIRE(rows.k.size() >= TabulatedFrf::min_points, path.string(), ": ", rows.k.size(),
                  " rows, but an FRF table needs at least ", TabulatedFrf::min_points);
  try {
    return std::make_shared<const TabulatedFrf>(std::move(rows.k), std::move(rows.H), c0, c_inf);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(detail::concat(path.string(), ": ", e.what()));
  }
}

nlohmann::json frf_table_json(const fs::path& path, const TabulatedFrf& table) {
  return {{"path", path.string()},
          {"points", table.size()},
          {"c0", table.c0()},
          {"c_inf", table.c_inf()},
          {"c0_estimated", table.c0_estimated()},
          {"c_inf_estimated", table.c_inf_estimated()}};
}

}  // namespace coatfft::scene
