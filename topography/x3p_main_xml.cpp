#include "topography/x3p_main_xml.hpp"

#include <array>
#include <limits>
#include <utility>

#include "io/input_file.hpp"
#include "topography/reader_support.hpp"

namespace coatfft::topography {
namespace {

constexpr auto npos = std::string_view::npos;

/// The local name of the element a tag opens or closes ("p:Record1" -> "Record1").
std::string_view tag_name(std::string_view unit, bool end_tag) {
  std::string_view name = unit.substr(end_tag ? 2 : 1);
  // Compared one by one: find_first_of would call memchr for every character (a tenth of the
  // time of a DataList's scan).
  const auto ends_name = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '/' || c == '>';
  };
  std::size_t length = 0;
  while (length < name.size() && !ends_name(name[length])) ++length;
  name = name.substr(0, length);
  const auto colon = name.find(':');
  return colon == npos ? name : name.substr(colon + 1);
}

/// The end of the markup `text` starts with ('<'), past its last character; npos while it is
/// unfinished. Comments, CDATA sections and processing instructions end at their own
/// delimiters; a tag at the first '>' outside quoted attribute values.
std::size_t markup_end(std::string_view text) {
  constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kDelimited{
      {{"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}}};
  for (const auto& [open, close] : kDelimited) {
    if (text.size() < open.size() && open.starts_with(text)) return npos;  // cannot tell yet
    if (!text.starts_with(open)) continue;
    const auto end = text.find(close, open.size());
    return end == npos ? npos : end + close.size();
  }
  char quote = 0;
  for (std::size_t k = 1; k < text.size(); ++k) {
    const char c = text[k];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return k + 1;
    }
  }
  return npos;
}

}  // namespace

MainXmlScanner::MainXmlScanner(const std::filesystem::path& path, DatumSink on_datum)
    : path_(path), on_datum_(std::move(on_datum)) {}

void MainXmlScanner::feed(std::string_view piece) {
  pending_.append(piece);
  scan(false);
}

void MainXmlScanner::finish() {
  scan(true);
}

void MainXmlScanner::scan(bool at_end) {
  const std::string_view buffer(pending_);
  std::size_t pos = 0;
  while (pos < buffer.size()) {
    if (buffer[pos] != '<') {  // text runs on to the next '<': what there is of it goes now
      const std::size_t end = std::min(buffer.find('<', pos), buffer.size());
      text(buffer.substr(pos, end - pos));
      pos = end;
      continue;
    }
    const std::size_t length = markup_end(buffer.substr(pos));
    if (length == npos) break;
    markup(buffer.substr(pos, length));
    pos += length;
  }
  pending_.erase(0, pos);
  if (pending_.size() > kMaxRecordBytes)
    refuse(path_, "main.xml: a tag or comment of more than ", kMaxRecordBytes, " bytes");
  if (at_end && !pending_.empty())
    refuse(path_, "main.xml ends inside ", io::quoted_excerpt(pending_), " (truncated)");
}

bool MainXmlScanner::at(std::initializer_list<std::string_view> names) const {
  if (open_.size() != names.size()) return false;
  std::size_t k = 0;
  for (const std::string_view name : names)
    if (open_[k++] != name) return false;
  return true;
}

void MainXmlScanner::markup(std::string_view unit) {
  const bool end_tag = unit.starts_with("</");
  const bool element = end_tag || (unit.size() > 1 && unit[1] != '!' && unit[1] != '?');
  const std::string_view name = element ? tag_name(unit, end_tag) : std::string_view{};
  if (in_list_) {
    count_list_bytes(unit.size());
    if (!end_tag || name != "DataList" || datum_) return list_markup(unit, end_tag, name);
    in_list_ = false;
  }
  append_record(unit);
  if (!element || unit.ends_with("/>")) return;
  if (end_tag) {
    if (!open_.empty()) open_.pop_back();  // a mismatch is tinyxml2's to refuse
    return;
  }
  open_.emplace_back(name);
  if (at({"ISO5436_2", "Record3", "DataList"})) open_list();
}

/// Inside Record3/DataList: <Datum> elements, blanks and comments only.
void MainXmlScanner::list_markup(std::string_view unit, bool end_tag, std::string_view name) {
  if (unit.starts_with("<!--") && !datum_) return;
  if (name == "Datum" && end_tag && datum_) {
    datum(*datum_);
    datum_.reset();
    return;
  }
  if (name == "Datum" && !end_tag && !datum_) {
    if (unit.ends_with("/>")) return datum("");
    datum_.emplace();
    return;
  }
  refuse(path_, "main.xml: Record3/DataList holds ", io::quoted_excerpt(unit),
         ", where only <Datum> elements belong");
}

void MainXmlScanner::text(std::string_view run) {
  if (in_list_) count_list_bytes(run.size());
  if (datum_) {
    datum_->append(run);
    if (datum_->size() > 1024)  // longer than any number with blanks around it
      refuse(path_, "main.xml: Record3/DataList/Datum = ", io::quoted_excerpt(*datum_),
             " is not a number");
  } else if (in_list_) {
    if (!trimmed(run).empty())
      refuse(path_, "main.xml: Record3/DataList holds the text ", io::quoted_excerpt(run),
             ", where only <Datum> elements belong");
  } else {
    append_record(run);
    // SizeX and SizeY precede the DataList (ISO 25178-72's schema): kept to stop at the first
    // value too many, rather than after a file's worth of them.
    for (auto [name, size] : {std::pair{"SizeX", &size_x_}, std::pair{"SizeY", &size_y_}})
      if (at({"ISO5436_2", "Record3", "MatrixDimension", name}) && size->size() < 64)
        size->append(run);
  }
}

void MainXmlScanner::append_record(std::string_view part) {
  record_.append(part);
  if (record_.size() > kMaxRecordBytes)
    refuse(path_, "main.xml: more than ", kMaxRecordBytes,
           " bytes besides the values of Record3/DataList");
}

void MainXmlScanner::open_list() {
  in_list_ = true;
  const auto nx = parse_number<std::size_t>(size_x_);
  const auto ny = parse_number<std::size_t>(size_y_);
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  if (!nx || !ny || *nx == 0 || *ny > kMax / *nx) return;  // the record's checks refuse these
  max_values_ = *nx * *ny;
  if (*max_values_ <= (kMax - kMaxRecordBytes) / kMaxBytesPerValue)
    max_list_bytes_ = kMaxRecordBytes + kMaxBytesPerValue * *max_values_;
}

void MainXmlScanner::count_list_bytes(std::size_t bytes) {
  list_bytes_ += bytes;
  if (list_bytes_ > max_list_bytes_)
    refuse(path_, "main.xml: Record3/DataList takes more than ", kMaxBytesPerValue,
           " bytes a value of SizeX * SizeY = ", *max_values_);
}

void MainXmlScanner::datum(std::string_view text) {
  if (max_values_ && values_ == *max_values_)
    refuse(path_, "main.xml: Record3/DataList holds more than SizeX * SizeY = ", *max_values_,
           " values");
  ++values_;
  on_datum_(trimmed(text));
}

}  // namespace coatfft::topography
