#include "io/npy.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/detail/close_written.hpp"
#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::io {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "the .npy writer assumes little endian");

namespace {
constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicSize = 6;
// NumPy itself refuses headers over 10000 bytes by default; a 2-D float64 header takes ~120.
constexpr std::size_t kMaxHeaderBytes = 65536;

// ---- .npy header ---------------------------------------------------------------------------

// The value texts of a .npy header dict, as in the file ("'<f8'", "False", "(3, 4)").
struct NpyHeader {
  std::optional<std::string_view> descr, fortran_order, shape;
};

// A strict reader of the header dict {'key': value, ...}: keys are quoted strings, values are
// quoted strings, bracketed lists or tuples, or words (True, False); a trailing comma is allowed,
// then only blanks up to the end of the header. Python's other literals do not occur there.
class HeaderParser {
 public:
  explicit HeaderParser(std::string_view text) : text_(text) {}

  // Fills `header`; false if the text is malformed (reason() says why).
  bool parse(NpyHeader& header) {
    if (!eat('{')) return fail("it is not a dict");
    bool closed = eat('}');
    while (!closed) {
      if (!entry(header)) return false;
      if (eat(',')) {
        closed = eat('}');
      } else if (eat('}')) {
        closed = true;
      } else {
        return fail("expected ',' or '}' after a value");
      }
    }
    skip_blanks("\n");
    if (pos_ != text_.size()) return fail("text after the closing '}'");
    if (!header.descr || !header.fortran_order || !header.shape)
      return fail("'descr', 'fortran_order' or 'shape' is missing");
    return true;
  }
  const char* reason() const { return reason_; }

 private:
  bool fail(const char* why) {
    reason_ = why;
    return false;
  }
  // One 'key': value of the dict, stored in `header`.
  bool entry(NpyHeader& header) {
    const auto key = quoted_string();
    if (!key || !eat(':')) return fail("expected 'key': value");
    const auto value = this->value();
    if (!value) return fail("a value is malformed");
    const std::string_view name = key->substr(1, key->size() - 2);
    std::optional<std::string_view>* slot = name == "descr"           ? &header.descr
                                            : name == "fortran_order" ? &header.fortran_order
                                            : name == "shape"         ? &header.shape
                                                                      : nullptr;
    if (slot == nullptr) return fail("unknown key");
    if (slot->has_value()) return fail("duplicate key");
    *slot = value;
    return true;
  }
  void skip_blanks(std::string_view more = "") {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   more.find(text_[pos_]) != std::string_view::npos))
      ++pos_;
  }
  bool eat(char c) {
    skip_blanks();
    if (pos_ >= text_.size() || text_[pos_] != c) return false;
    ++pos_;
    return true;
  }
  // A quoted string with its quotes ('<f8' or "<f8"; no escapes occur in a .npy header).
  std::optional<std::string_view> quoted_string() {
    skip_blanks();
    if (pos_ >= text_.size() || (text_[pos_] != '\'' && text_[pos_] != '"')) return std::nullopt;
    const auto close = text_.find(text_[pos_], pos_ + 1);
    if (close == std::string_view::npos) return std::nullopt;
    return take(close + 1);
  }
  std::optional<std::string_view> value();
  std::string_view take(std::size_t end) {
    const auto taken = text_.substr(pos_, end - pos_);
    pos_ = end;
    return taken;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  const char* reason_ = "";
};

std::optional<std::string_view> HeaderParser::value() {
  skip_blanks();
  if (pos_ >= text_.size()) return std::nullopt;
  const char first = text_[pos_];
  if (first == '\'' || first == '"') return quoted_string();
  if (first == '(' || first == '[') {  // up to the matching bracket
    int depth = 0;
    for (std::size_t end = pos_; end < text_.size(); ++end) {
      const char c = text_[end];
      depth += (c == '(' || c == '[') - (c == ')' || c == ']');
      if (depth == 0) return take(end + 1);
    }
    return std::nullopt;
  }
  std::size_t end = pos_;
  while (end < text_.size() &&
         (std::isalnum(static_cast<unsigned char>(text_[end])) != 0 || text_[end] == '_'))
    ++end;
  if (end == pos_) return std::nullopt;
  return take(end);
}

// A string value without its quotes; empty for anything else.
std::string_view unquoted(std::string_view value) {
  if (value.size() < 2 || (value.front() != '\'' && value.front() != '"') ||
      value.back() != value.front())
    return {};
  return value.substr(1, value.size() - 2);
}

struct Shape {
  std::uint64_t rows = 0, cols = 0;
  std::string_view text;  // as in the header, "(3, 4)"
};

// Reads a number of a shape at `pos`; false unless it is a positive decimal integer. Numbers too
// large for 64 bits read as the largest one, which no file can hold.
bool shape_number(std::string_view text, std::size_t& pos, std::uint64_t& value) {
  pos = std::min(text.find_first_not_of(" \t", pos), text.size());
  const char* begin = text.data() + pos;
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range) value = UINT64_MAX;
  if (end == begin || value == 0) return false;
  pos = static_cast<std::size_t>(end - text.data());
  pos = std::min(text.find_first_not_of(" \t", pos), text.size());
  return true;
}

// The shape of a 2-D array: "(rows, cols)", with an optional trailing comma and blanks
// anywhere between the parts; nullopt for anything else.
std::optional<Shape> parse_shape(std::string_view text) {
  if (text.size() < 2 || text.front() != '(' || text.back() != ')') return std::nullopt;
  Shape shape{0, 0, text};
  text = text.substr(1, text.size() - 2);
  std::size_t pos = 0;
  if (!shape_number(text, pos, shape.rows) || pos == text.size() || text[pos] != ',')
    return std::nullopt;
  ++pos;
  if (!shape_number(text, pos, shape.cols)) return std::nullopt;
  if (pos < text.size() && text[pos] == ',')
    pos = std::min(text.find_first_not_of(" \t", pos + 1), text.size());
  if (pos != text.size()) return std::nullopt;
  return shape;
}

// The header text as echoed in messages: as in the file, less NumPy's padding (trailing blanks
// and the final newline).
std::string header_for_message(std::string_view header) {
  const auto end = header.find_last_not_of(" \n");
  return quoted_excerpt(header.substr(0, end == std::string_view::npos ? 0 : end + 1));
}

// The layout of the array's values: IEEE floats of 8, 4 or 2 bytes (float32 exports are common,
// float16 ones rarer: three digits), in either byte order ('=' and no mark are this machine's,
// little endian), in C or Fortran order.
struct NpyLayout {
  Shape shape;
  std::size_t bytes = 8;  // of one value
  bool big_endian = false;
  bool fortran = false;
};

std::optional<NpyLayout> parse_dtype(std::string_view descr) {
  NpyLayout layout;
  if (!descr.empty() && (descr[0] == '<' || descr[0] == '>' || descr[0] == '=')) {
    layout.big_endian = descr[0] == '>';
    descr.remove_prefix(1);
  }
  if (descr == "f8") return layout;
  layout.bytes = 4;
  if (descr == "f4") return layout;
  layout.bytes = 2;
  if (descr == "f2") return layout;
  return std::nullopt;
}

// The layout of the array the header describes, once its dtype and order are checked.
NpyLayout npy_layout(const fs::path& path, std::string_view text) {
  NpyHeader header;
  HeaderParser parser(text);
  COATFFT_REQUIRE(parser.parse(header), path.string(), ": malformed .npy header (", parser.reason(),
                  "): ", header_for_message(text));
  std::optional<NpyLayout> layout = parse_dtype(unquoted(*header.descr));
  COATFFT_REQUIRE(layout, path.string(),
                  ": dtype must be float64, float32 or float16 ('<f8', '>f8', '<f4', '>f4', '<f2', "
                  "'>f2'), header is ",
                  header_for_message(text));
  COATFFT_REQUIRE(*header.fortran_order == "False" || *header.fortran_order == "True",
                  path.string(), ": fortran_order must be False or True, header is ",
                  header_for_message(text));
  layout->fortran = *header.fortran_order == "True";
  const std::optional<Shape> shape = parse_shape(*header.shape);
  COATFFT_REQUIRE(shape, path.string(),
                  ": array must be 2-D with a shape of two positive integers, shape is ",
                  quoted_excerpt(*header.shape), " in header ", header_for_message(text));
  layout->shape = *shape;
  return *layout;
}

// Value n of `data` (the file's bytes) as a double, in the layout's type and byte order.
double npy_value(const unsigned char* data, std::size_t n, const NpyLayout& layout) {
  unsigned char bytes[8];
  std::memcpy(bytes, data + n * layout.bytes, layout.bytes);
  if (layout.big_endian) std::reverse(bytes, bytes + layout.bytes);
  if (layout.bytes == 4) {
    float f;
    std::memcpy(&f, bytes, 4);
    return f;
  }
  if (layout.bytes == 2) {
    std::uint16_t bits;
    std::memcpy(&bits, bytes, 2);
    return static_cast<float>(Eigen::numext::bit_cast<Eigen::half>(bits));  // IEEE binary16
  }
  double d;
  std::memcpy(&d, bytes, 8);
  return d;
}

// The header of a .npy file and where its data starts.
struct NpyStart {
  std::string header;
  std::uintmax_t data_offset = 0;
};

// Reads the magic string, version and header, checking each length against the file's size
// before anything is allocated.
NpyStart read_npy_start(InputFile& file) {
  const std::string name = file.path().string();
  char start[kMagicSize + 2] = {};
  COATFFT_REQUIRE(file.size() >= sizeof start + 2, name, ": not a .npy file (", file.size(),
                  " bytes)");
  file.read_exact(start, sizeof start);
  COATFFT_REQUIRE(std::string_view(start, kMagicSize) == std::string_view(kMagic, kMagicSize), name,
                  ": not a .npy file");
  const int major = static_cast<unsigned char>(start[kMagicSize]);
  COATFFT_REQUIRE(major >= 1 && major <= 3, name, ": unsupported .npy version ", major);
  const std::size_t length_bytes = major == 1 ? 2 : 4;
  const std::uintmax_t preamble = sizeof start + length_bytes;
  COATFFT_REQUIRE(file.size() >= preamble, name, ": truncated .npy header");
  unsigned char length[4] = {};
  file.read_exact(length, length_bytes);
  std::size_t header_size = 0;
  for (std::size_t k = length_bytes; k-- > 0;) header_size = header_size << 8 | length[k];
  COATFFT_REQUIRE(header_size <= kMaxHeaderBytes, name, ": .npy header of ", header_size,
                  " bytes, more than the limit of ", kMaxHeaderBytes);
  COATFFT_REQUIRE(header_size <= file.size() - preamble, name, ": truncated .npy header of ",
                  header_size, " bytes: the file has ", file.size() - preamble,
                  " bytes after the header length");
  NpyStart npy{std::string(header_size, '\0'), preamble + header_size};
  file.read_exact(npy.header.data(), header_size);
  return npy;
}

// Checks that the data after the header is exactly the rows x cols values of the layout;
// returns their size in bytes.
std::size_t npy_data_bytes(const fs::path& path, const NpyStart& npy, const NpyLayout& layout,
                           std::uintmax_t file_size) {
  const Shape& shape = layout.shape;
  const std::uintmax_t have = file_size - npy.data_offset;
  std::uintmax_t need = 0;
  const bool overflow = __builtin_mul_overflow(shape.rows, shape.cols, &need) ||
                        __builtin_mul_overflow(need, std::uintmax_t{layout.bytes}, &need);
  if (!overflow && need == have) return static_cast<std::size_t>(need);
  const std::string needs = overflow ? std::string("more than 2^64") : std::to_string(need);
  throw InvalidArgument(detail::concat(
      path.string(), ": ", overflow || need > have ? "truncated data: " : "", "shape ",
      quoted_excerpt(shape.text), " needs ", needs, " bytes of float", 8 * layout.bytes,
      " values after the ", npy.data_offset, "-byte header, the file has ", have));
}

}  // namespace

std::string npy_preamble(std::span<const std::size_t> shape, std::string_view descr) {
  std::string dims;
  for (std::size_t n : shape) dims += std::to_string(n) + ", ";
  if (shape.size() > 1) dims.resize(dims.size() - 2);  // a 1-tuple keeps its comma: (n,)
  std::string header =
      "{'descr': '" + std::string(descr) + "', 'fortran_order': False, 'shape': (" + dims + "), }";
  // NumPy format 1.0: magic(6) + version(2) + header length(2) + header, padded with blanks and
  // terminated by '\n' so that the data starts on a 64-byte boundary.
  const std::size_t unpadded = kMagicSize + 4 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header.push_back('\n');
  const auto header_size = static_cast<std::uint16_t>(header.size());
  std::string preamble(kMagic, kMagicSize);
  preamble +=
      {'\x01', '\x00', static_cast<char>(header_size & 0xff), static_cast<char>(header_size >> 8)};
  return preamble + header;
}

namespace {

// The preamble of `descr` and `count` items of `item_bytes` each at `data`.
void write_npy_items(const std::filesystem::path& path, std::span<const std::size_t> shape,
                     std::string_view descr, const char* data, std::size_t count,
                     std::size_t item_bytes) {
  std::size_t cells = 1;
  for (std::size_t n : shape) cells *= n;
  COATFFT_REQUIRE(cells == count, "write_npy: the shape does not match the data");
  std::ofstream out(path, std::ios::binary);
  COATFFT_REQUIRE(out.good(), "cannot open ", path.string(), " for writing");
  out << npy_preamble(shape, descr);
  out.write(data, static_cast<std::streamsize>(count * item_bytes));
  detail::close_written(out, path);
}

}  // namespace

void write_npy_array(const std::filesystem::path& path, std::span<const std::size_t> shape,
                     std::span<const double> data) {
  write_npy_items(path, shape, "<f8", reinterpret_cast<const char*>(data.data()), data.size(),
                  sizeof(double));
}

void write_npy_bytes(const std::filesystem::path& path, std::span<const std::size_t> shape,
                     std::span<const std::uint8_t> data) {
  write_npy_items(path, shape, "|u1", reinterpret_cast<const char*>(data.data()), data.size(), 1);
}

void write_npy(const std::filesystem::path& path, const Field& field) {
  const std::size_t shape[2] = {static_cast<std::size_t>(field.cols()),
                                static_cast<std::size_t>(field.rows())};
  write_npy_array(path, shape, std::span<const double>(field.data(), std::size_t(field.size())));
}

NpyArray read_npy_header(const fs::path& path, std::uintmax_t max_bytes) {
  InputFile file(path, "a .npy file", max_bytes);
  const NpyStart npy = read_npy_start(file);
  const NpyLayout layout = npy_layout(path, npy.header);
  npy_data_bytes(path, npy, layout, file.size());
  return {layout.shape.rows, layout.shape.cols, npy.data_offset,
          layout.bytes,      layout.big_endian, layout.fortran};
}

NpyArray read_npy_row_header(const fs::path& path, std::size_t ny, std::size_t nx) {
  const NpyArray array = read_npy_header(path, std::numeric_limits<std::uintmax_t>::max());
  COATFFT_REQUIRE(array.rows == ny && array.cols == nx, path.string(), ": shape (", array.rows,
                  ", ", array.cols, ") but the grid needs (ny, nx) = (", ny, ", ", nx, ")");
  COATFFT_REQUIRE(!array.fortran, path.string(),
                  ": fortran_order is True; a distributed run reads C-order rows: save it with "
                  "numpy.ascontiguousarray");
  return array;
}

void npy_to_doubles(const NpyArray& array, const unsigned char* bytes, std::size_t count,
                    double* out) {
  NpyLayout layout;
  layout.bytes = array.value_bytes;
  layout.big_endian = array.big_endian;
  for (std::size_t n = 0; n < count; ++n) out[n] = npy_value(bytes, n, layout);
}

Field read_npy(const fs::path& path, std::uintmax_t max_bytes) {
  InputFile file(path, "a .npy file", max_bytes);
  const NpyStart npy = read_npy_start(file);
  const NpyLayout layout = npy_layout(path, npy.header);
  const std::size_t bytes = npy_data_bytes(path, npy, layout, file.size());
  // rows x cols x (2, 4 or 8) equals the data's size: both fit an Eigen::Index.
  const auto rows = static_cast<Eigen::Index>(layout.shape.rows);
  const auto cols = static_cast<Eigen::Index>(layout.shape.cols);
  Field field(cols, rows);
  if (layout.bytes == 8 && !layout.big_endian && !layout.fortran) {
    file.read_exact(field.data(), bytes);  // the Field's own layout: row j is y_j
    return field;
  }
  std::vector<unsigned char> data(bytes);
  file.read_exact(data.data(), bytes);
  // Value (r, c) of the (rows, cols) array: at r cols + c in C order, r + c rows in Fortran's.
  for (Eigen::Index r = 0; r < rows; ++r)
    for (Eigen::Index c = 0; c < cols; ++c) {
      const auto n = static_cast<std::size_t>(layout.fortran ? r + c * rows : r * cols + c);
      field(c, r) = npy_value(data.data(), n, layout);
    }
  return field;
}

}  // namespace coatfft::io
