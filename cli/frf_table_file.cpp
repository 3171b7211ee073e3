#include "cli/frf_table_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/csv.hpp"
#include "cli/input_file.hpp"
#include "core/error.hpp"

namespace coatfft::cli {

namespace fs = std::filesystem;

namespace {

// The columns of the header line: where k and H are, and the line, for messages.
struct Header {
  std::size_t line = 0;
  std::size_t k = 0, H = 0;
};

Header read_header(const fs::path& path, std::size_t line, std::string_view text) {
  const std::vector<std::string_view> names = csv_tokens(text);
  std::array<std::optional<std::size_t>, 2> found;  // k, H
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::string_view name = names[c];
    COATFFT_REQUIRE(name == "k" || name == "H", path.string(), ':', line, ": column ",
                    quoted_excerpt(name),
                    " is not k or H: the first line must name the columns k [rad/m] and H [m/Pa] "
                    "(\"k,H\"), and no others");
    std::optional<std::size_t>& slot = found[name == "k" ? 0 : 1];
    COATFFT_REQUIRE(!slot, path.string(), ':', line, ": column ", name, " is named twice");
    slot = c;
  }
  for (std::size_t i = 0; i < 2; ++i)
    COATFFT_REQUIRE(found[i], path.string(), ':', line, ": the header names no column ",
                    i == 0 ? "k" : "H", " (it must be \"k,H\")");
  return {line, *found[0], *found[1]};
}

struct Rows {
  std::vector<double> k, H;
};

// One data line: exactly the header's two values, finite and > 0, k above the previous row's.
void read_row(const fs::path& path, std::size_t line, std::string_view text, const Header& header,
              Rows& rows) {
  const std::vector<std::string_view> tokens = csv_tokens(text);
  if (tokens.empty()) return;
  const std::size_t row = rows.k.size();
  COATFFT_REQUIRE(tokens.size() == 2, path.string(), ':', line, ": row ", row, " has ",
                  tokens.size(), " values, but the header (line ", header.line,
                  ") names 2 columns, k and H");
  const double k = csv_value(path, line, row, header.k, tokens[header.k]);
  const double H = csv_value(path, line, row, header.H, tokens[header.H]);
  COATFFT_REQUIRE(std::isfinite(k) && k > 0, path.string(), ':', line, ": row ", row, ": k = ", k,
                  " rad/m, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(H) && H > 0, path.string(), ':', line, ": row ", row, ": H = ", H,
                  " m/Pa, but it must be finite and > 0");
  COATFFT_REQUIRE(row == 0 || k > rows.k.back(), path.string(), ':', line, ": row ", row,
                  ": k = ", k, " rad/m is not above the previous row's k = ", rows.k.back(),
                  ": k must be strictly ascending");
  rows.k.push_back(k);
  rows.H.push_back(H);
}

}  // namespace

std::shared_ptr<const TabulatedFrf> read_frf_table(const fs::path& path, std::optional<double> c0,
                                                   std::optional<double> c_inf) {
  const std::string text = read_input_file(path, "an FRF table", kMaxFrfTableBytes);
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
    else if (!csv_tokens(content).empty())
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

}  // namespace coatfft::cli
