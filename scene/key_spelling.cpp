#include "scene/key_spelling.hpp"

#include <algorithm>

#include "core/detail/shorten.hpp"
#include "core/error.hpp"

namespace coatfft::scene {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // d[i][j]: the distance of a's first i and b's first j characters (Damerau's transpositions,
  // each substring edited once).
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string misspelling_hint(const std::vector<std::string>& present,
                             const std::vector<std::string_view>& expected) {
  for (const std::string& key : present)
    for (const std::string_view want : expected) {
      if (key.size() < 3 || want.size() < 3 || key.size() > 64) continue;
      const std::size_t reach = want.size() <= 4 ? 1 : 2;
      if (edit_distance(key, want) <= reach)
        return detail::concat(" (is \"", detail::shorten(key), "\" a misspelling of \"", want,
                              "\"?)");
    }
  return "";
}

}  // namespace coatfft::scene
