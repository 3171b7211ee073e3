#pragma once
// A scene key the reader looked for and did not find, and a key of the same section that nothing
// read: when the two are one or two typing slips apart ("lod" for "load"), the refusal names the
// likely misspelling instead of only the missing key.
#include <string>
#include <string_view>
#include <vector>

namespace coatfft::scene {

/// The optimal-string-alignment distance of `a` and `b`: insertions, deletions, substitutions and
/// transpositions of adjacent characters, one each.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// " (is \"lod\" a misspelling of \"load\"?)" for the first of `present` (keys of a section that
/// nothing has read, in file order) within reach of one of `expected`, else "". Within reach: one
/// slip for keys of up to four characters, two for longer ones; keys of one or two characters
/// ("nx", "E") are never matched, since their neighbours are other valid keys ("ny", "a").
std::string misspelling_hint(const std::vector<std::string>& present,
                             const std::vector<std::string_view>& expected);

}  // namespace coatfft::scene
