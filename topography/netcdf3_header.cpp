#include "topography/netcdf3_header.hpp"

#include <cstddef>
#include <cstdint>

#include "topography/reader_support.hpp"

namespace coatfft::topography {

namespace {
// The bytes of one value of NetCDF type `type` (NC_BYTE = 1 ... NC_UINT64 = 11).
std::uint64_t value_bytes(std::uint64_t type) {
  switch (type) {
    case 3:  // NC_SHORT
    case 8:  // NC_USHORT
      return 2;
    case 4:  // NC_INT
    case 5:  // NC_FLOAT
    case 9:  // NC_UINT
      return 4;
    case 6:   // NC_DOUBLE
    case 10:  // NC_INT64
    case 11:  // NC_UINT64
      return 8;
    default:  // NC_BYTE, NC_CHAR, NC_UBYTE (any other type netcdf-c refuses)
      return 1;
  }
}

// The header read front to back; `ended` once a field would run past the file's end.
class HeaderCursor {
 public:
  HeaderCursor(const std::filesystem::path& path, std::string_view bytes, int version)
      : path_(path), bytes_(bytes), width_(version == 5 ? 8 : 4), offset_(version == 1 ? 4 : 8) {}

  bool ended() const { return ended_; }
  std::size_t width() const { return width_; }
  std::size_t offset_width() const { return offset_; }

  /// The big-endian unsigned integer of `size` (<= 8) bytes at the cursor.
  std::uint64_t take(std::size_t size) {
    const std::size_t at = at_;
    skip(size);
    std::uint64_t value = 0;
    for (std::size_t k = 0; k < size && !ended_; ++k)
      value = (value << 8) | static_cast<unsigned char>(bytes_[at + k]);
    return value;
  }
  void skip(std::uint64_t size) {
    if (ended_ || size > bytes_.size() - at_)
      ended_ = true;
    else
      at_ += static_cast<std::size_t>(size);
  }

  /// A count of elements of at least `least` bytes each, refused beyond the bytes left.
  std::uint64_t count(const char* what, std::uint64_t least) {
    const std::uint64_t n = take(width_);
    const std::uint64_t left = ended_ ? 0 : bytes_.size() - at_;
    if (!ended_ && n > left / least)
      refuse(path_, "the NetCDF header declares ", n, " ", what, " in the ", left,
             " bytes left: the file is damaged");
    return n;
  }
  /// A type (NC_BYTE = 1 ... NC_DOUBLE = 6, and to NC_UINT64 = 11 in CDF-5), refused otherwise:
  /// netcdf-c 4.9.0 gives a value of any other type no size, then divides by it (SIGFPE in
  /// NC_check_vlen, for a variable).
  std::uint64_t type(const char* of) {
    const std::uint64_t value = take(4);
    if (!ended_ && (value < 1 || value > (width_ == 8 ? 11u : 6u)))
      refuse(path_, "the NetCDF header gives ", of, " the type ", value,
             ", not one of NetCDF-3's: the file is damaged");
    return value;
  }
  /// A name: its length, then its characters padded to 4 bytes.
  void name() {
    const std::uint64_t length = count("characters of a name", 1);
    skip((length + 3) / 4 * 4);
  }
  /// An attribute list: ABSENT, or NC_ATTRIBUTE and the attributes.
  void attributes() {
    skip(4);
    const std::uint64_t n = count("attributes", 2 * width_ + 4);
    for (std::uint64_t k = 0; k < n && !ended_; ++k) {
      name();
      const std::uint64_t size = value_bytes(type("an attribute"));
      skip((count("attribute values", size) * size + 3) / 4 * 4);
    }
  }

 private:
  const std::filesystem::path& path_;
  std::string_view bytes_;
  std::size_t width_, offset_, at_ = 4;  // after "CDF" and the version
  bool ended_ = false;
};
}  // namespace

void require_netcdf3_header_fits(const std::filesystem::path& path, std::string_view bytes) {
  if (bytes.size() < 4 || bytes.substr(0, 3) != "CDF") return;
  const int version = static_cast<unsigned char>(bytes[3]);
  if (version != 1 && version != 2 && version != 5) return;
  HeaderCursor header(path, bytes, version);
  const std::size_t w = header.width();
  header.skip(w);  // the number of records
  header.skip(4);  // dimension list: NC_DIMENSION or ABSENT
  const std::uint64_t dims = header.count("dimensions", 2 * w);
  for (std::uint64_t k = 0; k < dims && !header.ended(); ++k) {
    header.name();
    header.skip(w);  // its length
  }
  header.attributes();  // global ones
  header.skip(4);       // variable list
  // A variable: name, dimensions, attributes (each at least a count), type, size and start.
  const std::uint64_t vars = header.count("variables", 4 * w + 8 + header.offset_width());
  for (std::uint64_t k = 0; k < vars && !header.ended(); ++k) {
    header.name();
    header.skip(header.count("dimensions of a variable", w) * w);
    header.attributes();
    header.type("a variable");
    header.skip(w + header.offset_width());  // size, start
  }
}

}  // namespace coatfft::topography
