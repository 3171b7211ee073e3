// ISO 25178-72:2017 X3P (XML 3D surface profile, the container of ISO 5436-2): a zip archive
// holding main.xml (the record of the measurement), md5checksum.hex (the MD5 of main.xml), the
// point data as a little-endian binary file (bindata/data.bin) or inline <Datum> elements, and
// optionally a bit mask of the valid points (bindata/valid.bin).
//
// Only areal maps on a regular grid are read: FeatureType SUR, incremental CX and CY axes and a
// single layer (SizeZ = 1). Profiles (PRF), point clouds (PCL) and absolute lateral axes are
// refused by name, as are data that do not match their checksums or their declared size.
#include <tinyxml2.h>
#include <zip.h>

#include <array>
#include <bit>
#include <boost/uuid/detail/md5.hpp>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "core/error.hpp"
#include "io/input_file.hpp"
#include "topography/formats.hpp"
#include "topography/reader_support.hpp"
#include "topography/x3p_main_xml.hpp"

namespace coatfft::topography {
namespace {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

// ---------------------------------------------------------------------------------------------
// MD5 (RFC 1321), as lower-case hex. ISO 25178-72 checks main.xml and the binary point data by
// their MD5. Boost 1.74's MD5 returns the digest as four words whose values read the digest's
// bytes most significant first (on any host: it swaps the bytes for its name-based UUIDs), so
// the hex digits are taken from the words' values, high byte first.

using Md5 = boost::uuids::detail::md5;

std::string hex_digest(Md5& hash) {
  Md5::digest_type digest;
  static_assert(std::is_same_v<decltype(digest), unsigned int[4]>,
                "a Boost whose MD5 digest is not four words: check the byte order");
  hash.get_digest(digest);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (const unsigned int word : digest)
    for (int shift = 28; shift >= 0; shift -= 4) hex += kHex[(word >> shift) & 0xFU];
  return hex;
}

bool is_md5_hex(std::string_view text) {
  return text.size() == 32 &&
         text.find_first_not_of("0123456789abcdefABCDEF") == std::string_view::npos;
}

// ---------------------------------------------------------------------------------------------
// The zip container, read by libzip from the InputFile checked (a regular file within the size
// limit), so that libzip never opens the path itself, at the offsets it asks for: the archive is
// not held whole beside the map (a stored archive holds the map's values).

struct FileSource {
  io::InputFile* file;
  std::uint64_t position = 0;
  zip_error_t error;
};

zip_int64_t read_file_source(void* state, void* data, zip_uint64_t length,
                             zip_source_cmd_t command) {
  FileSource& source = *static_cast<FileSource*>(state);
  const std::uint64_t size = source.file->size();
  switch (command) {
    case ZIP_SOURCE_OPEN:
    case ZIP_SOURCE_CLOSE:
    case ZIP_SOURCE_FREE:
      return 0;
    case ZIP_SOURCE_READ: {
      const std::uint64_t count = std::min<std::uint64_t>(length, size - source.position);
      try {  // no exception may cross libzip's C frames
        source.file->read_at(source.position, data, static_cast<std::size_t>(count));
      } catch (const std::exception&) {
        zip_error_set(&source.error, ZIP_ER_READ, EIO);
        return -1;
      }
      source.position += count;
      return static_cast<zip_int64_t>(count);
    }
    case ZIP_SOURCE_STAT: {
      auto* stat = static_cast<zip_stat_t*>(data);
      zip_stat_init(stat);
      stat->size = size;
      stat->valid |= ZIP_STAT_SIZE;
      return sizeof(zip_stat_t);
    }
    case ZIP_SOURCE_ERROR:
      return zip_error_to_data(&source.error, data, length);
    case ZIP_SOURCE_SEEK: {
      const zip_int64_t at =
          zip_source_seek_compute_offset(source.position, size, data, length, &source.error);
      if (at < 0) return -1;
      source.position = static_cast<std::uint64_t>(at);
      return 0;
    }
    case ZIP_SOURCE_TELL:
      return static_cast<zip_int64_t>(source.position);
    case ZIP_SOURCE_SUPPORTS:
      return zip_source_make_command_bitmap(
          ZIP_SOURCE_OPEN, ZIP_SOURCE_READ, ZIP_SOURCE_CLOSE, ZIP_SOURCE_STAT, ZIP_SOURCE_ERROR,
          ZIP_SOURCE_FREE, ZIP_SOURCE_SEEK, ZIP_SOURCE_TELL, ZIP_SOURCE_SUPPORTS, -1);
    default:
      zip_error_set(&source.error, ZIP_ER_OPNOTSUPP, 0);
      return -1;
  }
}

struct ZipDiscard {
  void operator()(zip_t* archive) const { zip_discard(archive); }
};
struct ZipFileClose {
  void operator()(zip_file_t* file) const { zip_fclose(file); }
};

class Archive {
 public:
  Archive(const fs::path& path, io::InputFile& file)
      : path_(path), source_(std::make_unique<FileSource>(FileSource{&file, 0, {}})) {
    zip_error_init(&source_->error);
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_function_create(read_file_source, source_.get(), &error);
    if (source != nullptr) archive_.reset(zip_open_from_source(source, ZIP_RDONLY, &error));
    if (!archive_) {
      const std::string reason = zip_error_strerror(&error);
      if (source != nullptr) zip_source_free(source);
      zip_error_fini(&error);
      refuse(path_, "not an X3P file: not a zip archive (", reason, ")");
    }
    zip_error_fini(&error);
  }

  /// The size the archive declares for the entry `name` unpacked, or nothing if it holds no
  /// such entry.
  std::optional<std::uint64_t> size(const std::string& name) const {
    zip_stat_t stat;
    zip_stat_init(&stat);
    if (zip_stat(archive_.get(), name.c_str(), 0, &stat) != 0) return std::nullopt;
    if ((stat.valid & ZIP_STAT_SIZE) == 0) refuse(path_, name, ": its size is unknown");
    return stat.size;
  }

  /// Unpacks the entry `name` piece by piece into `consume`, to the end of the entry, where
  /// libzip checks the CRC-32 of what it unpacked: false if the archive holds no such entry.
  /// An entry declared larger than `max_bytes` is refused before anything is unpacked, and one
  /// that unpacks to more than its declared size (a zip header can lie) as soon as that shows.
  bool stream(const std::string& name, std::uintmax_t max_bytes,
              const std::function<void(std::string_view)>& consume) const {
    const auto declared = size(name);
    if (!declared) return false;
    if (*declared > max_bytes)
      refuse(path_, name, ": ", *declared, " bytes unpacked, more than the limit of ", max_bytes,
             " bytes");
    const std::unique_ptr<zip_file_t, ZipFileClose> file(
        zip_fopen(archive_.get(), name.c_str(), 0));
    if (!file) refuse(path_, name, ": cannot be unpacked (", zip_strerror(archive_.get()), ")");
    std::string piece(std::size_t{1} << 16, '\0');
    std::uint64_t total = 0;
    for (;;) {
      const zip_int64_t count = zip_fread(file.get(), piece.data(), piece.size());
      if (count < 0)
        refuse(path_, name, ": cannot be unpacked (", zip_file_strerror(file.get()),
               "): the file is damaged");
      if (count == 0) break;
      total += static_cast<std::uint64_t>(count);
      if (total > *declared)
        refuse(path_, name, ": unpacks to more than the ", *declared,
               " bytes the archive declares: the file is damaged");
      consume(std::string_view(piece.data(), static_cast<std::size_t>(count)));
    }
    if (total != *declared)
      refuse(path_, name, ": truncated, ", total, " of ", *declared, " bytes");
    return true;
  }

  /// The content of a small entry `name` (at most `max_bytes`), or a refusal naming it.
  std::string require(const std::string& name, std::uintmax_t max_bytes) const {
    std::string content;
    if (!stream(name, max_bytes, [&](std::string_view piece) { content.append(piece); }))
      refuse(path_, "not an X3P file: the archive holds no ", name);
    return content;
  }

 private:
  fs::path path_;
  std::unique_ptr<FileSource> source_;  // outlives archive_, which reads through it
  std::unique_ptr<zip_t, ZipDiscard> archive_;
};

// ---------------------------------------------------------------------------------------------
// main.xml. Its root is <p:ISO5436_2> in the namespace of ISO 5436-2; writers differ in whether
// the records below it carry the prefix, so elements are found by their local name.

std::string_view local_name(const char* name) {
  const std::string_view qualified(name);
  const auto colon = qualified.find(':');
  return colon == std::string_view::npos ? qualified : qualified.substr(colon + 1);
}

const XMLElement* child(const XMLElement* parent, std::string_view name) {
  if (parent == nullptr) return nullptr;
  for (const XMLElement* e = parent->FirstChildElement(); e; e = e->NextSiblingElement())
    if (local_name(e->Name()) == name) return e;
  return nullptr;
}

std::string text_of(const XMLElement* element) {
  if (element == nullptr || element->GetText() == nullptr) return {};
  return std::string(trimmed(element->GetText()));
}

/// The element at `where` ("Record1/Axes/CX"), or a refusal naming it.
const XMLElement& require(const fs::path& path, const XMLElement* root, std::string_view where) {
  const XMLElement* element = root;
  for (std::size_t begin = 0; element != nullptr && begin <= where.size();) {
    const auto end = std::min(where.find('/', begin), where.size());
    element = child(element, where.substr(begin, end - begin));
    begin = end + 1;
  }
  if (element == nullptr) refuse(path, "main.xml has no ", where);
  return *element;
}

double number_in(const fs::path& path, std::string_view text, std::string_view where) {
  const auto value = parse_number<double>(text);
  if (!value || !std::isfinite(*value))
    refuse(path, "main.xml: ", where, " = ", io::quoted_excerpt(trimmed(text)), " is not a number");
  return *value;
}

double number_of(const fs::path& path, const XMLElement& element, std::string_view where) {
  return number_in(path, element.GetText() ? element.GetText() : "", where);
}

/// A matrix dimension (ISO 25178-72: an unsigned integer), at least 1.
std::size_t size_of(const fs::path& path, const XMLElement* root, std::string_view where) {
  const std::string text = text_of(&require(path, root, where));
  const auto value =
      text.empty() || text.front() == '+' ? std::nullopt : parse_number<std::size_t>(text);
  if (!value || *value == 0)
    refuse(path, "main.xml: ", where, " = ", io::quoted_excerpt(text),
           " is not a positive integer");
  return *value;
}

// ---------------------------------------------------------------------------------------------
// Record1: the axes. ISO 25178-72 codes the z values as I (16-bit signed integer), L (32-bit
// signed integer), F (IEEE 754 binary32) or D (binary64), each little endian; a z value in
// metres is value * Increment + Offset (Increment 1 and Offset 0 when absent).

enum class ValueType { int16, int32, float32, float64 };

std::size_t bytes_of(ValueType type) {
  switch (type) {
    case ValueType::int16:
      return 2;
    case ValueType::int32:
    case ValueType::float32:
      return 4;
    case ValueType::float64:
      return 8;
  }
  return 8;
}

struct Axis {
  double increment = 1;
  double offset = 0;
  std::optional<ValueType> type;
};

std::optional<ValueType> value_type(const fs::path& path, const XMLElement& axis,
                                    std::string_view where) {
  const XMLElement* data_type = child(&axis, "DataType");
  if (data_type == nullptr) return std::nullopt;
  const std::string code = text_of(data_type);
  if (code == "I") return ValueType::int16;
  if (code == "L") return ValueType::int32;
  if (code == "F") return ValueType::float32;
  if (code == "D") return ValueType::float64;
  refuse(path, "main.xml: ", where, "/DataType = ", io::quoted_excerpt(code),
         " is not a data type of ISO 25178-72 (I, L, F or D)");
}

/// An axis of Record1/Axes. CX and CY must be incremental (a regular grid: ISO 25178-72 allows
/// absolute lateral axes, whose coordinates are listed per point, which this reader does not
/// resample); CZ is absolute by definition.
Axis read_axis(const fs::path& path, const XMLElement* root, std::string_view name) {
  const std::string where = detail::concat("Record1/Axes/", name);
  const XMLElement& axis = require(path, root, where);
  const std::string axis_type = text_of(&require(path, &axis, "AxisType"));
  const std::string expected = name == "CZ" ? "A" : "I";
  if (axis_type != expected)
    refuse(path, "main.xml: ", where, "/AxisType = ", io::quoted_excerpt(axis_type),
           name == "CZ" ? ", but the heights must be absolute (A)"
                        : ", but only incremental lateral axes (I, a regular grid) are read");
  Axis result;
  if (const XMLElement* increment = child(&axis, "Increment"))
    result.increment = number_of(path, *increment, where + "/Increment");
  if (const XMLElement* offset = child(&axis, "Offset"))
    result.offset = number_of(path, *offset, where + "/Offset");
  if (name == "CZ") result.type = value_type(path, axis, where);
  return result;
}

// ---------------------------------------------------------------------------------------------
// The whole record: what the reader needs of Record1 and Record3.

struct Record {
  Axis x, y, z;  ///< z.type is set (read_record refuses a record without it)
  std::size_t nx = 0, ny = 0;
  const XMLElement* data_link = nullptr;  ///< Record3/DataLink, or
  const XMLElement* data_list = nullptr;  ///< Record3/DataList (inline <Datum> values)
};

void read_matrix_dimension(const fs::path& path, const XMLElement* root, Record& record,
                           const ReadOptions& options) {
  record.nx = size_of(path, root, "Record3/MatrixDimension/SizeX");
  record.ny = size_of(path, root, "Record3/MatrixDimension/SizeY");
  const std::size_t nz = size_of(path, root, "Record3/MatrixDimension/SizeZ");
  if (nz != 1)
    refuse(path, "main.xml: SizeZ = ", nz, ", but only a single layer (SizeZ = 1) is read");
  // Every point becomes a double: bound the map by the file size limit before allocating.
  require_point_limit(path, "main.xml: SizeX * SizeY", record.nx, record.ny, options);
}

Record read_record(const fs::path& path, const XMLElement* root, const ReadOptions& options) {
  const std::string feature = text_of(&require(path, root, "Record1/FeatureType"));
  if (feature != "SUR")
    refuse(path, "main.xml: FeatureType = ", io::quoted_excerpt(feature),
           ", but only areal surfaces (SUR) are read");
  Record record;
  record.x = read_axis(path, root, "CX");
  record.y = read_axis(path, root, "CY");
  record.z = read_axis(path, root, "CZ");
  if (!record.z.type) refuse(path, "main.xml has no Record1/Axes/CZ/DataType");
  for (const auto& [axis, name] : {std::pair{&record.x, "CX"}, std::pair{&record.y, "CY"}})
    if (!(axis->increment > 0))
      refuse(path, "main.xml: Record1/Axes/", name, "/Increment = ", axis->increment,
             ", but the spacing must be > 0");
  if (record.z.increment == 0) refuse(path, "main.xml: Record1/Axes/CZ/Increment = 0");
  read_matrix_dimension(path, root, record, options);
  const XMLElement* record3 = child(root, "Record3");
  record.data_link = child(record3, "DataLink");
  record.data_list = child(record3, "DataList");
  if (record.data_link == nullptr && record.data_list == nullptr)
    refuse(path, "main.xml has neither Record3/DataLink nor Record3/DataList");
  return record;
}

// ---------------------------------------------------------------------------------------------
// Checksums. ISO 25178-72 stores the MD5 of main.xml in the checksum file (hex digits, which
// md5sum-style writers follow by " *main.xml"), and the MD5 of the point data and of the valid
// points in Record3/DataLink. A mismatch means a damaged or edited file: refused.

void verify_record_checksum(const fs::path& path, const Archive& archive, const XMLElement* root,
                            const std::string& actual) {
  std::string checksum_file = text_of(child(child(root, "Record4"), "ChecksumFile"));
  if (checksum_file.empty()) checksum_file = "md5checksum.hex";
  const std::string content = archive.require(checksum_file, 1024);
  const std::string_view line = trimmed(content);
  const std::string_view stated = line.substr(0, line.find_first_of(" \t\r\n"));
  if (!is_md5_hex(stated))
    refuse(path, checksum_file, " holds ", io::quoted_excerpt(stated),
           ", not the MD5 checksum of main.xml (32 hex digits)");
  if (lower_ascii(stated) != actual)
    refuse(path, "main.xml does not match its MD5 checksum in ", checksum_file, " (",
           lower_ascii(stated), "; the content's is ", actual, "): the file is damaged");
}

void verify_data_checksum(const fs::path& path, const XMLElement* checksum,
                          const std::string& entry, const std::string& actual) {
  if (checksum == nullptr) return;  // optional in ISO 25178-72
  const std::string stated = text_of(checksum);
  if (!is_md5_hex(stated))
    refuse(path, "main.xml: ", local_name(checksum->Name()), " = ", io::quoted_excerpt(stated),
           " is not an MD5 checksum (32 hex digits)");
  if (lower_ascii(stated) != actual)
    refuse(path, entry, " does not match its MD5 checksum in main.xml (", lower_ascii(stated),
           "; the content's is ", actual, "): the file is damaged");
}

// ---------------------------------------------------------------------------------------------
// The point data: SizeX * SizeY values, x fastest (ISO 25178-72: index = x + SizeX * y), which
// is the column-major order of a Field (nx, ny).

double decode(const char* bytes, ValueType type) {
  const std::uint64_t word = little_endian(bytes, bytes_of(type));
  switch (type) {
    case ValueType::int16:
      return static_cast<std::int16_t>(static_cast<std::uint16_t>(word));
    case ValueType::int32:
      return static_cast<std::int32_t>(static_cast<std::uint32_t>(word));
    case ValueType::float32:
      return std::bit_cast<float>(static_cast<std::uint32_t>(word));
    case ValueType::float64:
      return std::bit_cast<double>(word);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// Unpacks `entry`, which the archive declares `bytes` long, piece by piece into `consume`,
/// and checks it against its MD5 in main.xml (`checksum`), when stated.
void read_checked(const fs::path& path, const Archive& archive, const std::string& entry,
                  std::uint64_t bytes, const XMLElement* checksum,
                  const std::function<void(std::string_view)>& consume) {
  Md5 hash;
  archive.stream(entry, bytes, [&](std::string_view piece) {
    hash.process_bytes(piece.data(), piece.size());
    consume(piece);
  });
  verify_data_checksum(path, checksum, entry, hex_digest(hash));
}

/// The point data, decoded as it is unpacked: its declared size is checked against SizeX *
/// SizeY before anything is unpacked, so that a small archive cannot unpack to gigabytes first.
Field read_point_data(const fs::path& path, const Archive& archive, const Record& record,
                      const std::string& entry) {
  const std::size_t count = record.nx * record.ny;
  const ValueType type = *record.z.type;
  const std::size_t width = bytes_of(type);
  const auto bytes = archive.size(entry);
  if (!bytes) refuse(path, "the archive holds no ", entry, " (the point data main.xml links)");
  if (*bytes != count * width)
    refuse(path, entry, ": ", *bytes, " bytes, but SizeX * SizeY = ", record.nx, " * ", record.ny,
           " values of ", width, " bytes take ", count * width,
           *bytes < count * width ? " (truncated)" : "");
  Field heights(record.nx, record.ny);
  double* out = heights.data();   // column-major (nx, ny): x fastest, as in the file
  std::array<char, 8> partial{};  // a value split between two pieces
  std::size_t have = 0;
  read_checked(path, archive, entry, *bytes, child(record.data_link, "MD5ChecksumPointData"),
               [&](std::string_view piece) {
                 while (!piece.empty()) {
                   if (have == 0 && piece.size() >= width) {
                     *out++ = decode(piece.data(), type);
                     piece.remove_prefix(width);
                     continue;
                   }
                   partial[have++] = piece.front();
                   piece.remove_prefix(1);
                   if (have == width) *out++ = decode(partial.data(), type), have = 0;
                 }
               });
  return heights;
}

/// Marks the points valid.bin declares invalid as NaN. ISO 25178-72: one bit per point, in the
/// order of the point data, least significant bit first; a 0 marks an invalid point.
void read_valid_points(const fs::path& path, const Archive& archive, const Record& record,
                       const std::string& entry, Field& heights) {
  const std::size_t count = static_cast<std::size_t>(heights.size());
  const auto bytes = archive.size(entry);
  if (!bytes) refuse(path, "the archive holds no ", entry, " (the valid points)");
  if (*bytes != (count + 7) / 8)
    refuse(path, entry, ": ", *bytes, " bytes, but ", count, " points need ", (count + 7) / 8,
           *bytes < (count + 7) / 8 ? " (truncated)" : "");
  double* out = heights.data();
  std::size_t k = 0;
  read_checked(path, archive, entry, *bytes, child(record.data_link, "MD5ChecksumValidPoints"),
               [&](std::string_view piece) {
                 for (const char byte : piece)
                   for (unsigned bit = 0; bit < 8; ++bit, ++k)
                     if (k < count && ((static_cast<unsigned char>(byte) >> bit) & 1U) == 0)
                       out[k] = std::numeric_limits<double>::quiet_NaN();
               });
}

Field read_linked_data(const fs::path& path, const Archive& archive, const Record& record) {
  const std::string entry = text_of(child(record.data_link, "PointDataLink"));
  if (entry.empty()) refuse(path, "main.xml has no Record3/DataLink/PointDataLink");
  Field heights = read_point_data(path, archive, record, entry);
  const std::string valid_entry = text_of(child(record.data_link, "ValidPointsLink"));
  if (!valid_entry.empty()) read_valid_points(path, archive, record, valid_entry, heights);
  return heights;
}

/// Inline data: one <Datum> per point in the order of the point data; ISO 25178-72 marks an
/// invalid point by an empty <Datum/>. main.xml is unpacked a second time, now that its values
/// are counted and SizeX * SizeY checked, to store them in the map.
Field read_data_list(const fs::path& path, const Archive& archive, const Record& record,
                     std::uintmax_t max_bytes) {
  Field heights(record.nx, record.ny);
  double* out = heights.data();
  const std::size_t count = static_cast<std::size_t>(heights.size());
  std::size_t k = 0;
  MainXmlScanner scanner(path, [&](std::string_view text) {
    if (k == count)  // the first pass counted them: only if the archive changed since
      refuse(path, "main.xml: Record3/DataList holds more than SizeX * SizeY = ", count, " values");
    out[k++] = text.empty() ? std::numeric_limits<double>::quiet_NaN()
                            : number_in(path, text, "Record3/DataList/Datum");
  });
  archive.stream("main.xml", max_bytes, [&](std::string_view piece) { scanner.feed(piece); });
  scanner.finish();
  return heights;
}

// ---------------------------------------------------------------------------------------------
// Record2: who measured what and when, all optional.

void add_if_present(Topography& topography, const char* name, const XMLElement* element) {
  std::string value = text_of(element);
  if (!value.empty()) topography.metadata.emplace_back(name, std::move(value));
}

void read_metadata(const XMLElement* root, Topography& topography) {
  const XMLElement* record2 = child(root, "Record2");
  if (record2 == nullptr) return;
  add_if_present(topography, "date", child(record2, "Date"));
  add_if_present(topography, "creator", child(record2, "Creator"));
  const XMLElement* instrument = child(record2, "Instrument");
  std::string name;
  for (const char* part : {"Manufacturer", "Model"}) {
    const std::string text = text_of(child(instrument, part));
    if (text.empty() || text == "unknown") continue;
    name += (name.empty() ? "" : " ") + text;
  }
  if (!name.empty()) topography.metadata.emplace_back("instrument", name);
  add_if_present(topography, "instrument_serial", child(instrument, "Serial"));
  add_if_present(topography, "instrument_version", child(instrument, "Version"));
  add_if_present(topography, "calibration_date", child(record2, "CalibrationDate"));
  add_if_present(topography, "probing_system", child(child(record2, "ProbingSystem"), "Type"));
  add_if_present(topography, "probing_identification",
                 child(child(record2, "ProbingSystem"), "Identification"));
  add_if_present(topography, "comment", child(record2, "Comment"));
}

/// Unpacks main.xml: parses its record into `document` and returns the MD5 of main.xml and
/// the number of values of its DataList (MainXmlScanner keeps them out of the DOM).
std::pair<std::string, std::size_t> read_main_xml(const fs::path& path, const Archive& archive,
                                                  std::uintmax_t max_bytes,
                                                  tinyxml2::XMLDocument& document) {
  Md5 hash;
  MainXmlScanner scanner(path, [](std::string_view) {});
  if (!archive.stream("main.xml", max_bytes, [&](std::string_view piece) {
        hash.process_bytes(piece.data(), piece.size());
        scanner.feed(piece);
      }))
    refuse(path, "not an X3P file: the archive holds no main.xml");
  scanner.finish();
  if (document.Parse(scanner.record().data(), scanner.record().size()) != tinyxml2::XML_SUCCESS)
    refuse(path, "main.xml is not well-formed XML (", document.ErrorName(), " on line ",
           document.ErrorLineNum(), ")");
  return {hex_digest(hash), scanner.values()};
}

}  // namespace

Topography read_x3p_topography(const std::filesystem::path& path, const ReadOptions& options) {
  io::InputFile file(path, "an X3P file", options.max_bytes);
  const Archive archive(path, file);
  tinyxml2::XMLDocument document;
  const auto [main_md5, values] = read_main_xml(path, archive, options.max_bytes, document);
  const XMLElement* root = document.RootElement();
  if (root == nullptr || local_name(root->Name()) != "ISO5436_2")
    refuse(path, "main.xml: the root element is not ISO5436_2");
  // The record is trusted only once it matches its checksum.
  verify_record_checksum(path, archive, root, main_md5);
  const Record record = read_record(path, root, options);
  if (!record.data_link && values != record.nx * record.ny)
    refuse(path, "main.xml: Record3/DataList holds ", values,
           " values, but SizeX * SizeY = ", record.nx * record.ny,
           values < record.nx * record.ny ? " (truncated)" : "");

  Topography topography;
  topography.heights = record.data_link ? read_linked_data(path, archive, record)
                                        : read_data_list(path, archive, record, options.max_bytes);
  // Heights in metres, in place; NaN (an invalid point) stays NaN.
  topography.heights = topography.heights * record.z.increment + record.z.offset;
  topography.missing = static_cast<std::size_t>(topography.heights.isNaN().count());
  // Cell-centred grid: SizeX points at spacing Increment span SizeX * Increment.
  topography.lx = static_cast<double>(record.nx) * record.x.increment;
  topography.ly = static_cast<double>(record.ny) * record.y.increment;
  topography.format = "x3p";
  topography.unit = "m";
  read_metadata(root, topography);
  return topography;
}

}  // namespace coatfft::topography
