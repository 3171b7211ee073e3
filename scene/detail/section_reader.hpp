#pragma once
// Private to the scene layer: the reading of one TOML section of a scene file, each key checked
// and named as the user wrote it, and the materials a section gives.
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "materials/material.hpp"
#include "scene/key_spelling.hpp"

namespace coatfft::scene {

// Reads the keys of one TOML table, remembering which were used so that unknown keys (typos)
// are refused instead of silently ignored.
class SectionReader {
 public:
  SectionReader(const toml::table& table, std::string name)
      : table_(table), name_(std::move(name)) {}

  bool has(std::string_view key) const { return table_.contains(key); }
  bool is_array(std::string_view key) const {
    const toml::node* node = table_.get(key);
    return node != nullptr && node->is_array();
  }

  double number(std::string_view key) {
    const toml::node& node = require(key);
    COATFFT_REQUIRE(node.is_number(), where(key), " must be a number, got ", describe(node));
    // An integer too large for an exact double (9007199254740993) is still a number: rounded.
    const double value = node.is_integer() ? static_cast<double>(node.as_integer()->get())
                                           : node.as_floating_point()->get();
    COATFFT_REQUIRE(std::isfinite(value), where(key), " = ", value, " must be finite");
    return value;
  }
  double number(std::string_view key, double fallback) { return has(key) ? number(key) : fallback; }

  std::int64_t integer(std::string_view key) { return typed<std::int64_t>(key, "an integer"); }
  std::int64_t integer(std::string_view key, std::int64_t fallback) {
    return has(key) ? integer(key) : fallback;
  }

  bool boolean(std::string_view key, bool fallback) {
    return has(key) ? typed<bool>(key, "true or false") : fallback;
  }

  std::string string(std::string_view key) { return typed<std::string>(key, "a string"); }
  std::string string(std::string_view key, std::string fallback) {
    return has(key) ? string(key) : fallback;
  }
  /// The list of finite numbers at `key` (possibly empty).
  std::vector<double> numbers(std::string_view key) {
    const toml::node& node = require(key);
    const toml::array* array = node.as_array();
    COATFFT_REQUIRE(array != nullptr, where(key), " must be a list of numbers, got ",
                    describe(node));
    std::vector<double> values;
    for (const toml::node& e : *array) {
      COATFFT_REQUIRE(e.is_number(), where(key),
                      " must be a list of numbers, got an entry of type ", describe(e));
      const double v = e.is_integer() ? static_cast<double>(e.as_integer()->get())
                                      : e.as_floating_point()->get();
      COATFFT_REQUIRE(std::isfinite(v), where(key), " holds ", v, ": every entry must be finite");
      values.push_back(v);
    }
    return values;
  }
  /// The list of strings at `key` (possibly empty).
  std::vector<std::string> strings(std::string_view key) {
    const toml::node& node = require(key);
    const toml::array* array = node.as_array();
    COATFFT_REQUIRE(array != nullptr, where(key), " must be a list of strings, got ",
                    describe(node));
    std::vector<std::string> values;
    for (const toml::node& element : *array) {
      COATFFT_REQUIRE(element.is_string(), where(key),
                      " must be a list of strings, got an entry of type ", describe(element));
      values.push_back(element.value<std::string>().value());
    }
    return values;
  }
  std::string choice(std::string_view key, std::string fallback,
                     std::initializer_list<std::string_view> allowed) {
    std::string value = string(key, std::move(fallback));
    std::string list;
    for (auto a : allowed) {
      if (a == value) return value;
      list += (list.empty() ? "\"" : ", \"") + std::string(a) + "\"";
    }
    throw InvalidArgument(
        detail::concat(where(key), " = \"", detail::shorten(value), "\" is not one of ", list));
  }

  /// A key of the section that nothing read and that looks like a misspelling of one of
  /// `expected` (scene/key_spelling.hpp), for a refusal that a missing key causes; "" if none.
  std::string misspelling(const std::vector<std::string_view>& expected) const {
    std::vector<std::string> unread;
    for (auto&& [key, node] : table_)
      if (!used_.count(std::string(key.str()))) unread.emplace_back(key.str());
    return misspelling_hint(unread, expected);
  }

  /// Refuses every key that was not read.
  void finish() const {
    for (auto&& [key, node] : table_) {
      COATFFT_REQUIRE(used_.count(std::string(key.str())), "[", name_, "] unknown key \"",
                      detail::shorten(key.str()), "\"", line_of(node));
    }
  }

  std::string where(std::string_view key) const {
    std::string line;
    if (const toml::node* node = table_.get(key)) line = line_of(*node);
    return detail::concat("[", name_, "] ", key, line);
  }

 private:
  const toml::node& require(std::string_view key) {
    const toml::node* node = table_.get(key);
    COATFFT_REQUIRE(node != nullptr, "[", name_, "] missing required key \"", key, "\"",
                    misspelling({key}));
    used_.insert(std::string(key));
    return *node;
  }
  // The value of type T (an integer, a boolean or a string) at `key`, refused as "must be `what`"
  // when the key holds another type.
  template <typename T>
  T typed(std::string_view key, std::string_view what) {
    const toml::node& node = require(key);
    COATFFT_REQUIRE(node.is<T>(), where(key), " must be ", what, ", got ", describe(node));
    return node.value<T>().value();
  }
  static std::string line_of(const toml::node& node) {
    return node.source().begin ? detail::concat(" (line ", node.source().begin.line, ")") : "";
  }
  static std::string describe(const toml::node& node) {
    std::ostringstream os;
    os << node.type();
    return os.str();
  }

  const toml::table& table_;
  std::string name_;
  std::set<std::string> used_;
};

// The table [name] of `root`; an empty table for a missing optional section.
const toml::table& section(const toml::table& root, std::string_view name, bool required);

// Library constructors validate values; prefix their messages with the section they came from.
template <typename Build>
auto in_section(std::string_view name, Build&& build) {
  try {
    return build();
  } catch (const InvalidArgument& e) {
    const std::string message = e.what();
    if (message.rfind("[", 0) == 0) throw;
    throw InvalidArgument(detail::concat("[", name, "] ", message));
  }
}

// Material(E, nu) from the keys `e_key` and `nu_key`: the library's limits, named by those keys.
Material material_from_moduli(SectionReader& reader, const char* e_key, const char* nu_key);

// [section] material = "NAME" (materials/catalog.hpp), or E and nu.
Material read_material(SectionReader& reader);

// The number at `key`, refused unless > 0.
double positive(SectionReader& reader, std::string_view key);

}  // namespace coatfft::scene
