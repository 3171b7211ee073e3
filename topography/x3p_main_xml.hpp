#pragma once
// main.xml of an X3P archive (ISO 25178-72), scanned as it is unpacked. The record of the
// measurement (Record1 to Record4) is a few kilobytes and is parsed into a DOM by tinyxml2; an
// inline Record3/DataList holds one <Datum> element a point, which in a DOM takes about a
// hundred bytes of nodes each (tens of times the text: a DataList that deflates to 1 MB becomes
// gigabytes). So the scanner keeps the record without the DataList's content, bounded in size,
// and hands the values of the DataList one by one to the caller, which counts them (a first
// pass) or stores them in the map (a second pass, once the record's SizeX * SizeY is known and
// matches the count).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coatfft::topography {

class MainXmlScanner {
 public:
  /// Receives the text of each <Datum> of Record3/DataList, without the blanks around it; an
  /// empty <Datum/> (an invalid point) gives "".
  using DatumSink = std::function<void(std::string_view text)>;

  /// The most bytes of main.xml outside the DataList's content (and of one tag or comment):
  /// a record of a measurement takes a few kilobytes.
  static constexpr std::size_t kMaxRecordBytes = std::size_t{1} << 20;
  /// The most bytes of the DataList's content a value of SizeX * SizeY, beyond kMaxRecordBytes
  /// (for comments): a <Datum> of a 17-digit number with a prefix and indentation takes under
  /// 80, so that the work is bounded by the points declared, not by blanks the file pads with.
  static constexpr std::size_t kMaxBytesPerValue = 256;

  MainXmlScanner(const std::filesystem::path& path, DatumSink on_datum);

  /// The next piece of main.xml, as unpacked.
  void feed(std::string_view piece);
  /// The end of main.xml: refuses a file that ends inside a tag.
  void finish();

  /// main.xml without the content of Record3/DataList (an empty <DataList></DataList>).
  const std::string& record() const { return record_; }
  /// The <Datum> elements of Record3/DataList seen so far.
  std::size_t values() const { return values_; }

 private:
  void scan(bool at_end);
  void markup(std::string_view unit);
  void list_markup(std::string_view unit, bool end_tag, std::string_view name);
  void text(std::string_view run);
  void datum(std::string_view text);
  void count_list_bytes(std::size_t bytes);
  void open_list();
  void append_record(std::string_view part);
  bool at(std::initializer_list<std::string_view> names) const;

  std::filesystem::path path_;
  DatumSink on_datum_;
  std::string pending_;               ///< an unfinished tag or comment
  std::string record_;                ///< main.xml less the DataList's content
  std::vector<std::string> open_;     ///< the local names of the open elements, root first
  bool in_list_ = false;              ///< inside Record3/DataList
  std::optional<std::string> datum_;  ///< the text of an open <Datum>
  std::string size_x_, size_y_;       ///< Record3/MatrixDimension's SizeX and SizeY, as written
  std::optional<std::size_t> max_values_;  ///< SizeX * SizeY, once known
  std::size_t values_ = 0;
  std::size_t list_bytes_ = 0;  ///< of the DataList's content so far
  std::size_t max_list_bytes_ = std::numeric_limits<std::size_t>::max();
};

}  // namespace coatfft::topography
