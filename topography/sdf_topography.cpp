// ISO 25178-71:2012 SDF (Surface Data File, the format of the Surfstand project, first named
// BCR): a header, a data section and an optional trailer, in one of two variants.
//
//   ASCII ("aISO-1.0", "aBCR-1.0", ...): the header is "Keyword = value" lines ended by a line
//   "*"; the data section is NumPoints * NumProfiles numbers separated by white space, x fastest
//   (one profile after the other), ended by "*"; then the trailer, free text.
//   Binary ("bISO-1.0", "bBCR-1.0", ...): a fixed 81-byte header (below), then the values in
//   the little-endian binary form of DataType, then the trailer.
//
// A height in metres is value * Zscale; the lateral spacings Xscale and Yscale are in metres.
// Compressed or checksummed data sections (Compression, CheckType other than 0) are refused.
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/input_file.hpp"
#include "topography/formats.hpp"
#include "topography/reader_support.hpp"

namespace coatfft::topography {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::string_view kSpace = " \t\r\n\f\v";

// Without allocating: "BAD" is looked for in every value of a data section.
bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
    if (lower(a[k]) != lower(b[k])) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// The data types of ISO 25178-71 (codes 3 to 7) and of the BCR format before it (0 to 2), and
// the value each reserves for a point that was not measured: the most negative value of the
// signed and floating-point types (ISO 25178-71), the largest of the unsigned ones (BCR; as
// Gwyddion and SurfaceTopography read them). A floating-point NaN, and "BAD" in place of a
// number in the ASCII variant, mark such a point too.

struct DataType {
  const char* name;
  std::size_t bytes;
  bool is_signed;
  bool is_float;
  double min, max;  ///< the range of an integer type
};

constexpr std::array<DataType, 8> kDataTypes{{
    {"UINT8", 1, false, false, 0, 255},
    {"UINT16", 2, false, false, 0, 65535},
    {"UINT32", 4, false, false, 0, 4294967295.0},
    {"FLOAT", 4, true, true, 0, 0},
    {"INT8", 1, true, false, -128, 127},
    {"INT16", 2, true, false, -32768, 32767},
    {"INT32", 4, true, false, -2147483648.0, 2147483647},
    {"DOUBLE", 8, true, true, 0, 0},
}};

bool is_bad_point(double value, int code) {
  if (std::isnan(value)) return true;
  // -FLT_MAX and anything that rounds to it in binary32 (an ASCII rendition of it); -DBL_MAX
  // and -inf (what an ASCII rendition of -DBL_MAX rounded up overflows to).
  constexpr double kLowestFloat = -(double{std::numeric_limits<float>::max()} - 0x1p103);
  switch (code) {
    case 0:
      return false;  // UINT8 reserves no value
    case 1:
    case 2:
      return value == kDataTypes[code].max;
    case 3:
      return value <= kLowestFloat;
    case 7:
      return value <= std::numeric_limits<double>::lowest();
    default:
      return value == kDataTypes[code].min;
  }
}

// ---------------------------------------------------------------------------------------------
// The header, from either variant.

struct Header {
  std::string version;  ///< "aISO-1.0", "bBCR-1.0", ...
  std::size_t nx = 0, ny = 0;
  double xscale = 0, yscale = 0, zscale = 0;
  long long compression = 0, data_type = -1, check_type = 0;
  std::vector<std::pair<std::string, std::string>> metadata;
};

/// The first 8 bytes: 'a' (ASCII) or 'b' (binary), then the dialect, "ISO-" or "BCR-", and
/// its version ("1.0"; ISO 25178-71:2012 names 1.0, later revisions 2.0).
bool is_version(std::string_view text) {
  return text.size() == 8 && (text[0] == 'a' || text[0] == 'b') &&
         (text.substr(1, 4) == "ISO-" || text.substr(1, 4) == "BCR-") &&
         std::string_view("0123456789").find(text[5]) != std::string_view::npos && text[6] == '.' &&
         std::string_view("0123456789").find(text[7]) != std::string_view::npos;
}

void check_header(const fs::path& path, const Header& header, const ReadOptions& options) {
  if (header.nx == 0 || header.ny == 0)
    refuse(path, "NumPoints = ", header.nx, ", NumProfiles = ", header.ny,
           ", but both must be >= 1");
  require_point_limit(path, "NumPoints * NumProfiles", header.nx, header.ny, options);
  for (const auto& [name, value] :
       {std::pair{"Xscale", header.xscale}, std::pair{"Yscale", header.yscale},
        std::pair{"Zscale", header.zscale}})
    if (!(value > 0) || !std::isfinite(value))
      refuse(path, name, " = ", value, ", but a scale must be > 0 (ISO 25178-71)");
  if (header.data_type < 0 || header.data_type >= static_cast<long long>(kDataTypes.size()))
    refuse(path, "DataType = ", header.data_type,
           " is not a data type of ISO 25178-71 or BCR (0 to 7)");
  if (header.compression != 0)
    refuse(path, "Compression = ", header.compression, ": compressed data are not read");
  if (header.check_type != 0)
    refuse(path, "CheckType = ", header.check_type, ": checksummed data are not read");
}

// ---------------------------------------------------------------------------------------------
// The ASCII header: "Keyword = value" lines (in ISO 25178-71's order, but found by name here,
// ignoring case), comments starting with ';', ended by a line "*". Keywords the standard does
// not name are kept as metadata.

template <typename T>
T header_value(const fs::path& path, std::string_view keyword, std::string_view value) {
  const auto number = parse_number<T>(value);
  if (!number)
    refuse(path, keyword, " = ", io::quoted_excerpt(value), " is not ",
           std::is_integral_v<T> ? "an integer" : "a number");
  return *number;
}

/// Sets the field of `header` that `keyword` names; false for a keyword of no field.
bool set_field(const fs::path& path, Header& header, std::string_view keyword,
               std::string_view value) {
  const auto is = [&](std::string_view name) { return equal_ignoring_case(keyword, name); };
  if (is("NumPoints") || is("NumProfiles")) {
    const auto count = header_value<long long>(path, keyword, value);
    if (count <= 0) refuse(path, keyword, " = ", count, ", but it must be >= 1");
    (is("NumPoints") ? header.nx : header.ny) = static_cast<std::size_t>(count);
  } else if (is("Xscale")) {
    header.xscale = header_value<double>(path, keyword, value);
  } else if (is("Yscale")) {
    header.yscale = header_value<double>(path, keyword, value);
  } else if (is("Zscale")) {
    header.zscale = header_value<double>(path, keyword, value);
  } else if (is("Compression")) {
    header.compression = header_value<long long>(path, keyword, value);
  } else if (is("DataType")) {
    header.data_type = header_value<long long>(path, keyword, value);
  } else if (is("CheckType")) {
    header.check_type = header_value<long long>(path, keyword, value);
  } else {
    return false;
  }
  return true;
}

/// The next line of `text` from `pos` (without its end of line), advancing `pos` past it.
std::optional<std::string_view> next_line(std::string_view text, std::size_t& pos) {
  if (pos >= text.size()) return std::nullopt;
  const std::size_t end = std::min(text.find('\n', pos), text.size());
  const std::string_view line = text.substr(pos, end - pos);
  pos = end + 1;
  return line;
}

Header read_text_header(const fs::path& path, std::string_view text, std::size_t& pos) {
  Header header;
  header.version = std::string(trimmed(*next_line(text, pos)));
  std::vector<std::string> seen;
  for (auto line = next_line(text, pos);; line = next_line(text, pos)) {
    if (!line) refuse(path, "the header does not end with a line \"*\" (truncated)");
    const std::string_view entry = trimmed(*line);
    if (entry == "*") break;
    if (entry.empty() || entry.front() == ';') continue;
    const std::size_t key_end =
        std::min(entry.find_first_of(std::string(kSpace) + "="), entry.size());
    const std::string keyword(entry.substr(0, key_end));
    std::string_view value = trimmed(entry.substr(key_end));
    if (!value.empty() && value.front() == '=') value = trimmed(value.substr(1));
    for (const std::string& earlier : seen)
      if (equal_ignoring_case(earlier, keyword))
        refuse(path, "the header names ", keyword, " twice");
    seen.push_back(keyword);
    if (!set_field(path, header, keyword, value))
      header.metadata.emplace_back(keyword, std::string(value));
  }
  for (const char* required :
       {"NumPoints", "NumProfiles", "Xscale", "Yscale", "Zscale", "DataType"}) {
    bool found = false;
    for (const std::string& keyword : seen) found |= equal_ignoring_case(keyword, required);
    if (!found) refuse(path, "the header has no ", required);
  }
  return header;
}

// ---------------------------------------------------------------------------------------------
// The ASCII data section.

/// A value of the data section: "BAD" (any case) is a point not measured; an integer type
/// takes integers within its range only, so that a misread type does not pass unnoticed.
double parse_datum(const fs::path& path, std::string_view token, int code, std::size_t index) {
  if (equal_ignoring_case(token, "BAD")) return kNaN;
  const DataType& type = kDataTypes[code];
  if (!type.is_float) {
    const auto value = parse_number<long long>(token);
    if (!value || *value < type.min || *value > type.max)
      refuse(path, "value ", index + 1, " of the data section, ", io::quoted_excerpt(token),
             ", is not an integer of DataType ", code, " (", type.name, ")");
    return static_cast<double>(*value);
  }
  if (const auto value = parse_number<double>(token)) return *value;
  // Out of the range of a double (from_chars refuses it): an ASCII rendition of -DBL_MAX
  // rounded up, the mark of a missing point. strtod returns ±HUGE_VAL or 0 for it.
  const std::string copy(token);
  char* end = nullptr;
  const double value = std::strtod(copy.c_str(), &end);
  if (copy.empty() || end != copy.c_str() + copy.size())
    refuse(path, "value ", index + 1, " of the data section, ", io::quoted_excerpt(token),
           ", is not a number");
  return value;
}

/// The next value of the data section from `pos`, advancing `pos` past it; nothing at its end
/// (the end of the file or "*").
std::optional<std::string_view> next_value(std::string_view text, std::size_t& pos) {
  pos = std::min(text.find_first_not_of(kSpace, pos), text.size());
  const std::size_t end = std::min(text.find_first_of(kSpace, pos), text.size());
  const std::string_view token = text.substr(pos, end - pos);
  pos = end;
  if (token.empty() || token == "*") return std::nullopt;
  return token;
}

/// The values of the data section, counted (and checked) before the map is allocated: a header
/// may declare far more points than the file holds.
Field read_text_data(const fs::path& path, std::string_view text, std::size_t& pos,
                     const Header& header) {
  const std::size_t count = header.nx * header.ny;
  const int code = static_cast<int>(header.data_type);
  std::size_t held = 0;  // each checked as it is counted, so that a bad value is named first
  for (std::size_t end = pos; held <= count;) {
    const auto token = next_value(text, end);
    if (!token) break;
    if (held < count) parse_datum(path, *token, code, held);
    ++held;
  }
  if (held > count)
    refuse(path, "the data section holds more than NumPoints * NumProfiles = ", header.nx, " * ",
           header.ny, " values");
  if (held != count)
    refuse(path, "the data section holds ", held,
           " values, but NumPoints * NumProfiles = ", header.nx, " * ", header.ny, " = ", count,
           " (truncated)");
  Field values(header.nx, header.ny);
  double* out = values.data();  // column-major (nx, ny): x fastest, as in the file
  for (std::size_t k = 0; k < count; ++k)
    out[k] = parse_datum(path, *next_value(text, pos), code, k);
  next_value(text, pos);  // past the closing "*"
  return values;
}

/// The trailer, free text (ISO 25178-71; ended by "*" in the ASCII variant), kept as metadata.
void read_trailer(std::string_view trailer, Header& header) {
  trailer = trimmed(trailer);
  if (!trailer.empty() && trailer.back() == '*')
    trailer = trimmed(trailer.substr(0, trailer.size() - 1));
  for (const char c : trailer)
    if ((c < ' ' || c > '~') && kSpace.find(c) == std::string_view::npos) return;  // not text
  if (!trailer.empty()) header.metadata.emplace_back("trailer", std::string(trailer));
}

// ---------------------------------------------------------------------------------------------
// The binary variant. ISO 25178-71's fixed header, little endian, without padding:
//   version char[8], ManufacID char[10], CreateDate char[12], ModDate char[12],
//   NumPoints uint16, NumProfiles uint16, Xscale, Yscale, Zscale, Zresolution binary64,
//   Compression, DataType, CheckType uint8                                  (81 bytes in all)

constexpr std::size_t kBinaryHeaderBytes = 8 + 10 + 12 + 12 + 2 + 2 + 4 * 8 + 3;

std::uint64_t little_endian(std::string_view bytes, std::size_t offset, std::size_t width) {
  return topography::little_endian(bytes.data() + offset, width);
}

double binary_value(std::string_view bytes, std::size_t offset, int code) {
  const std::uint64_t word = little_endian(bytes, offset, kDataTypes[code].bytes);
  switch (code) {
    case 3:
      return std::bit_cast<float>(static_cast<std::uint32_t>(word));
    case 4:
      return static_cast<std::int8_t>(static_cast<std::uint8_t>(word));
    case 5:
      return static_cast<std::int16_t>(static_cast<std::uint16_t>(word));
    case 6:
      return static_cast<std::int32_t>(static_cast<std::uint32_t>(word));
    case 7:
      return std::bit_cast<double>(word);
    default:
      return static_cast<double>(word);  // the unsigned types
  }
}

/// A fixed-width text field: padded with spaces (ISO) or ended by NUL (BCR).
std::string text_field(std::string_view bytes, std::size_t offset, std::size_t width) {
  std::string_view field = bytes.substr(offset, width);
  field = field.substr(0, std::min(field.find('\0'), field.size()));
  return std::string(trimmed(field));
}

Header read_binary_header(std::string_view bytes) {
  Header header;
  header.version = std::string(bytes.substr(0, 8));
  const std::pair<const char*, std::string> texts[] = {{"ManufacID", text_field(bytes, 8, 10)},
                                                       {"CreateDate", text_field(bytes, 18, 12)},
                                                       {"ModDate", text_field(bytes, 30, 12)}};
  for (const auto& [name, value] : texts)
    if (!value.empty()) header.metadata.emplace_back(name, value);
  header.nx = static_cast<std::size_t>(little_endian(bytes, 42, 2));
  header.ny = static_cast<std::size_t>(little_endian(bytes, 44, 2));
  header.xscale = std::bit_cast<double>(little_endian(bytes, 46, 8));
  header.yscale = std::bit_cast<double>(little_endian(bytes, 54, 8));
  header.zscale = std::bit_cast<double>(little_endian(bytes, 62, 8));
  const double zresolution = std::bit_cast<double>(little_endian(bytes, 70, 8));
  header.metadata.emplace_back("Zresolution", detail::concat(zresolution));
  header.compression = static_cast<unsigned char>(bytes[78]);
  header.data_type = static_cast<unsigned char>(bytes[79]);
  header.check_type = static_cast<unsigned char>(bytes[80]);
  return header;
}

/// The values, read from the file piece by piece after the header (so that the map is held
/// once, not beside the file's bytes), then the trailer.
Field read_binary_data(const fs::path& path, io::InputFile& file, Header& header) {
  const int code = static_cast<int>(header.data_type);
  const std::size_t width = kDataTypes[code].bytes;
  const std::size_t count = header.nx * header.ny;
  std::uintmax_t offset = kBinaryHeaderBytes;
  // Olympus software writes bISO-1.0 files with 8 more header bytes (two 32-bit fields) than
  // the standard's; a file exactly that much longer than its data is read so (as Gwyddion
  // does), any other excess is the trailer.
  std::string piece(std::size_t{1} << 16, '\0');  // a whole number of values of any width
  if (header.version == "bISO-1.0" && file.size() == offset + count * width + 8) {
    file.read_exact(piece.data(), 8);
    offset += 8;
  }
  if (file.size() - offset < count * width)
    refuse(path, "the data section holds ", file.size() - offset, " bytes, but NumPoints * ",
           "NumProfiles = ", header.nx, " * ", header.ny, " values of ", width, " bytes (",
           kDataTypes[code].name, ") take ", count * width, " (truncated)");
  Field values(header.nx, header.ny);
  double* out = values.data();  // column-major (nx, ny): x fastest, as in the file
  for (std::size_t k = 0; k < count;) {
    const std::size_t n = std::min(count - k, piece.size() / width);
    file.read_exact(piece.data(), n * width);
    for (std::size_t m = 0; m < n; ++m) out[k + m] = binary_value(piece, m * width, code);
    k += n;
  }
  // The trailer, free text kept as metadata, when it is at most 1 MiB.
  const std::uintmax_t trailer_bytes = file.size() - offset - count * width;
  if (trailer_bytes <= (std::uintmax_t{1} << 20)) {
    std::string trailer(static_cast<std::size_t>(trailer_bytes), '\0');
    file.read_exact(trailer.data(), trailer.size());
    read_trailer(trailer, header);
  }
  return values;
}

/// The header and the values of either variant; `start` holds the first bytes of the file.
std::pair<Header, Field> read_header_and_values(const fs::path& path, io::InputFile& file,
                                                std::string start, const ReadOptions& options) {
  if (start.front() == 'b') {
    if (start.size() < kBinaryHeaderBytes)
      refuse(path, start.size(), " bytes, fewer than the ", kBinaryHeaderBytes,
             " of the binary header (truncated)");
    Header header = read_binary_header(start);
    check_header(path, header, options);
    Field values = read_binary_data(path, file, header);
    return {std::move(header), std::move(values)};
  }
  std::string text = std::move(start);
  const std::size_t read = text.size();
  text.resize(static_cast<std::size_t>(file.size()));
  file.read_exact(text.data() + read, text.size() - read);
  if (!file.at_end()) refuse(path, "the file changed while being read");
  std::size_t pos = 0;
  Header header = read_text_header(path, text, pos);
  check_header(path, header, options);
  Field values = read_text_data(path, text, pos, header);
  read_trailer(std::string_view(text).substr(std::min(pos, text.size())), header);
  return {std::move(header), std::move(values)};
}

}  // namespace

Topography read_sdf_topography(const std::filesystem::path& path, const ReadOptions& options) {
  io::InputFile file(path, "an SDF file", options.max_bytes);
  std::string start(
      static_cast<std::size_t>(std::min<std::uintmax_t>(file.size(), kBinaryHeaderBytes)), '\0');
  file.read_exact(start.data(), start.size());
  const std::string_view version = std::string_view(start).substr(0, 8);
  if (!is_version(version))
    refuse(path, "not an SDF file: it starts with ", io::quoted_excerpt(version),
           ", not a version of ISO 25178-71 such as aISO-1.0, bISO-1.0, aBCR-1.0");
  auto [header, heights] = read_header_and_values(path, file, std::move(start), options);

  // In place: a map is held once.
  for (double& value : heights.reshaped())
    value = is_bad_point(value, static_cast<int>(header.data_type)) ? kNaN : value * header.zscale;
  const auto missing = static_cast<std::size_t>(heights.isNaN().count());
  header.metadata.insert(header.metadata.begin(), {"version", header.version});
  // Cell-centred grid: NumPoints points at spacing Xscale span NumPoints * Xscale.
  Topography topography{.heights = std::move(heights),
                        .lx = static_cast<double>(header.nx) * header.xscale,
                        .ly = static_cast<double>(header.ny) * header.yscale,
                        .periodic = std::nullopt,
                        .format = "sdf",
                        .unit = "m",
                        .missing = missing,
                        .metadata = std::move(header.metadata)};
  return topography;
}

}  // namespace coatfft::topography
