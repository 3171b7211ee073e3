#pragma once
// Measured topographies: a height map read from an instrument's or another program's file, in
// metres, with the physical size and periodicity the file carries (docs/measured_surfaces.md).
//
// Formats, chosen by the file's extension: .npy; text grids .csv, .txt, .asc (a matrix of
// heights, or "x y z" rows on a regular grid); NetCDF .nc in SurfaceTopography's layout; ISO
// 25178-72 X3P .x3p; ISO 25178-71 SDF .sdf. A Topography's heights follow coatfft's grid
// convention (docs/conventions.md): heights(i, j) at (x_i, y_j), x along a file's columns, y
// along its rows, and the size of the map is the number of points times the spacing (cell-
// centred points, as SurfaceTopography counts it).
//
// Refusals are one-line InvalidArgument messages that start with the path.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "io/input_file.hpp"

namespace coatfft::topography {

/// What becomes of points a file marks as missing (NaN, an X3P invalid mark, SDF's
/// BadPointMarker): refused, naming their count, or filled by the harmonic rule
/// (fill_missing_points).
enum class MissingPoints { refuse, fill };

/// "refuse" or "fill"; InvalidArgument naming `what` otherwise.
MissingPoints missing_points_from_name(std::string_view name, std::string_view what);

struct ReadOptions {
  /// The unit of a file that carries none (.npy, text grids, x y z rows: for x y z the unit of
  /// the coordinates too); "" reads such a file in metres. A file with a unit of its own is
  /// read in it, and a different `unit` given here is refused.
  std::string unit;
  MissingPoints missing = MissingPoints::refuse;
  std::uintmax_t max_bytes = io::kMaxArrayFileBytes;
  /// The memory reading the map may take [bytes] (`--max-memory`); by default what the machine
  /// has available. A file declaring a larger map is refused before anything is allocated.
  std::optional<double> max_memory{};
  /// How the caller's user asks for missing points to be filled, for the refusal that names
  /// them: a scene's key (the default), `--missing fill` of `coatfft topography`, Python's
  /// keyword.
  std::string fill_hint = "missing = \"fill\"";
};

/// A height map as read from a file.
struct Topography {
  Field heights;                 ///< (nx, ny) [m], finite (missing points filled or refused)
  std::optional<double> lx, ly;  ///< physical size [m] where the file carries its spacing
  std::optional<bool> periodic;  ///< where the file says (NetCDF's `periodic` attribute)
  std::string format;            ///< "npy", "csv", "xyz", "netcdf", "x3p", "sdf"
  std::string unit;              ///< the unit of the file's heights as it names it; "" if none
  std::size_t missing = 0;       ///< points the file marks as missing (filled if any)
  /// What else the file says about itself (instrument, date, ...), name and value, in its order.
  std::vector<std::pair<std::string, std::string>> metadata;
};

/// Reads the topography of `path` (format by extension, case-insensitive) into metres, applies
/// `options` and checks that every height is finite.
Topography read_topography(const std::filesystem::path& path, const ReadOptions& options = {});

/// The most multiply-adds a fill may take: its factorisation's, estimated from the holes' sizes
/// and then counted before it is made (about 35 s at the 0.6e9 a second measured on one core; a
/// map of 768^2 points with 99.9 % missing takes 9.6e9, one of 2048^2 about 15 times more).
inline constexpr double max_fill_operations = 2e10;
/// Each equation of the filled map's harmonic rule holds to this fraction of its scale (8 times
/// the largest height: the point's up to 4 times its height and its 4 neighbours), checked after
/// the solve.
inline constexpr double fill_tolerance = 1e-12;

/// Fills the NaN points of `heights` by the discrete harmonic rule: each missing point is the
/// mean of its neighbours along x and y (those inside the map; no wrap-around), the known points
/// held, which is the smoothest surface through them (a discrete Laplace equation, solved
/// exactly by a sparse Cholesky factorisation, to fill_tolerance). Returns the number of points
/// filled. Refuses (InvalidArgument starting with `where`, naming the count of missing points)
/// a map with no finite point, and before allocating it a fill whose memory exceeds
/// `max_memory` (else what the machine has available) or whose work exceeds
/// max_fill_operations.
std::size_t fill_missing_points(Field& heights, std::optional<double> max_memory = std::nullopt,
                                std::string_view where = "the topography");

}  // namespace coatfft::topography
