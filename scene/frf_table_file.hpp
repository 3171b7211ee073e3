#pragma once
// The file of a body given by its FRF (the scene's [frf] section, docs/scene_format.md): a CSV
// table whose first line names the columns k [rad/m] and H [m/Pa] (or frf, the name `coatfft frf`
// gives it; in any order, other columns skipped), one wavenumber per line, values read as
// io/csv.hpp reads them. Every refusal is one line
// naming the file, the line and the value ("t.csv:12: k = 3 rad/m is not above ...").
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "frf/tabulated_frf.hpp"

namespace coatfft::scene {

/// Largest FRF table file: 64 MiB, about a million rows (a table needs hundreds).
inline constexpr std::uintmax_t kMaxFrfTableBytes = std::uintmax_t{64} << 20;

/// Reads the table at `path` into a TabulatedFrf with the limits c0 and c_inf [1/Pa] given, or
/// estimated from the table's ends (frf/tabulated_frf.hpp). Throws InvalidArgument: a missing
/// or repeated column, a value that is not a number, not finite or not > 0, k not strictly
/// ascending, fewer than TabulatedFrf::min_points rows, ends too far from flat for an estimate.
std::shared_ptr<const TabulatedFrf> read_frf_table(const std::filesystem::path& path,
                                                   std::optional<double> c0,
                                                   std::optional<double> c_inf);

/// summary.json's "frf_table": {path, points, c0, c_inf, c0_estimated, c_inf_estimated}.
nlohmann::json frf_table_json(const std::filesystem::path& path, const TabulatedFrf& table);

}  // namespace coatfft::scene
