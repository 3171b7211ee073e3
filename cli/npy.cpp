#include "cli/npy.hpp"

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace coatfft::cli {

static_assert(std::endian::native == std::endian::little, "the .npy writer assumes little endian");

namespace {
constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicSize = 6;
// The text after 'key': in a .npy header dict, up to the next top-level comma or the closing
// brace, blanks trimmed ("'<f8'", "False", "(3, 4)").
std::string header_value(const std::string& header, const std::string& key) {
  const auto at = header.find("'" + key + "'");
  if (at == std::string::npos) return "";
  auto begin = header.find(':', at);
  if (begin == std::string::npos) return "";
  ++begin;
  int depth = 0;
  auto end = begin;
  for (; end < header.size(); ++end) {
    const char c = header[end];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if ((c == ',' && depth == 0) || c == '}') break;
  }
  std::string value = header.substr(begin, end - begin);
  value.erase(0, value.find_first_not_of(' '));
  value.erase(value.find_last_not_of(' ') + 1);
  return value;
}

}  // namespace

void write_npy(const std::filesystem::path& path, const Field& field) {
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" +
                       std::to_string(field.cols()) + ", " + std::to_string(field.rows()) + "), }";
  // NumPy format 1.0: magic(6) + version(2) + header length(2) + header, padded with blanks and
  // terminated by '\n' so that the data starts on a 64-byte boundary.
  const std::size_t unpadded = kMagicSize + 4 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header.push_back('\n');
  std::ofstream out(path, std::ios::binary);
  COATFFT_REQUIRE(out.good(), "cannot open ", path.string(), " for writing");
  const auto header_size = static_cast<std::uint16_t>(header.size());
  out.write(kMagic, kMagicSize);
  out.put('\x01');
  out.put('\x00');
  out.put(static_cast<char>(header_size & 0xff));
  out.put(static_cast<char>(header_size >> 8));
  out << header;
  out.write(reinterpret_cast<const char*>(field.data()),
            static_cast<std::streamsize>(field.size() * sizeof(double)));
  COATFFT_REQUIRE(out.good(), "failed writing ", path.string());
}

Field read_npy(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  COATFFT_REQUIRE(in.good(), path.string(), ": cannot open file");
  char magic[kMagicSize + 2] = {};
  in.read(magic, kMagicSize + 2);
  COATFFT_REQUIRE(in.good() && std::string(magic, kMagicSize) == std::string(kMagic, kMagicSize),
                  path.string(), ": not a .npy file");
  const int major = static_cast<unsigned char>(magic[kMagicSize]);
  std::size_t header_size = 0;
  if (major == 1) {
    unsigned char len[2] = {};
    in.read(reinterpret_cast<char*>(len), 2);
    header_size = len[0] | (static_cast<std::size_t>(len[1]) << 8);
  } else {
    COATFFT_REQUIRE(major == 2 || major == 3, path.string(), ": unsupported .npy version ", major);
    unsigned char len[4] = {};
    in.read(reinterpret_cast<char*>(len), 4);
    header_size = len[0] | (static_cast<std::size_t>(len[1]) << 8) |
                  (static_cast<std::size_t>(len[2]) << 16) |
                  (static_cast<std::size_t>(len[3]) << 24);
  }
  COATFFT_REQUIRE(in.good() && header_size < (1u << 20), path.string(), ": corrupt .npy header");
  std::string header(header_size, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header_size));
  COATFFT_REQUIRE(in.good(), path.string(), ": truncated .npy header");

  const std::string descr = header_value(header, "descr");
  COATFFT_REQUIRE(descr == "'<f8'" || descr == "'=f8'" || descr == "'f8'", path.string(),
                  ": dtype must be float64 ('<f8'), header is ", header);
  COATFFT_REQUIRE(header_value(header, "fortran_order") == "False", path.string(),
                  ": array must be in C order (fortran_order False)");
  long rows = 0, cols = 0;
  char close = 0;
  std::istringstream shape(header_value(header, "shape"));
  shape >> close >> rows >> close >> cols >> close;
  COATFFT_REQUIRE(shape && (close == ')' || (close == ',' && (shape >> close) && close == ')')),
                  path.string(), ": array must be 2-D, header is ", header);
  COATFFT_REQUIRE(rows > 0 && cols > 0, path.string(), ": empty array of shape (", rows, ", ", cols,
                  ")");
  Field field(cols, rows);
  in.read(reinterpret_cast<char*>(field.data()),
          static_cast<std::streamsize>(field.size() * sizeof(double)));
  COATFFT_REQUIRE(in.gcount() == static_cast<std::streamsize>(field.size() * sizeof(double)),
                  path.string(), ": truncated data, expected ", rows, " x ", cols,
                  " float64 values");
  return field;
}

Field read_csv_matrix(const std::filesystem::path& path) {
  std::ifstream in(path);
  COATFFT_REQUIRE(in.good(), path.string(), ": cannot open file");
  std::vector<std::vector<double>> rows;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream fields(line);
    std::vector<double> row;
    std::string token;
    while (fields >> token) {
      std::size_t used = 0;
      double value = 0;
      try {
        value = std::stod(token, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      COATFFT_REQUIRE(used == token.size(), path.string(), ":", line_number, ": \"", token,
                      "\" is not a number");
      row.push_back(value);
    }
    if (row.empty()) continue;
    COATFFT_REQUIRE(rows.empty() || row.size() == rows.front().size(), path.string(), ":",
                    line_number, ": row has ", row.size(), " values, expected ",
                    rows.front().size());
    rows.push_back(std::move(row));
  }
  COATFFT_REQUIRE(!rows.empty(), path.string(), ": no data");
  Field field(static_cast<Eigen::Index>(rows.front().size()),
              static_cast<Eigen::Index>(rows.size()));
  for (std::size_t j = 0; j < rows.size(); ++j)
    for (std::size_t i = 0; i < rows[j].size(); ++i)
      field(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = rows[j][i];
  return field;
}

}  // namespace coatfft::cli
