#pragma once
// Resources bounded before they are spent (docs/scene_format.md, "Limits"): the memory a scene
// needs is estimated from its sizes and refused, naming the keys that drive it, when it exceeds
// what the machine has (or --max-memory); counts given on the command line have caps.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/memory.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// Caps of the command-line counts.
inline constexpr int max_repeat = 100000;         ///< coatfft run --repeat
inline constexpr long max_frf_points = 10000000;  ///< coatfft frf --points

/// The memory of a contact's fields on `cells` grid cells [bytes] (docs/scale.md, "Memory per
/// cell"): the heights and five iterate fields (pressure, gap, direction, its image, the previous
/// gap), two more under a hardness (the displacement in two parts), one byte of cell sets, and
/// the preconditioner's quarter multiplier with, unless it shares a periodic operator's, its own
/// half spectrum; and two fields' worth of transients (the set-up's kernel and planner buffer,
/// and arrays of 32 MiB or less, which the allocator keeps for reuse: a periodic 2048^2 contact
/// peaks 12 bytes a cell above its arrays).
inline double contact_field_bytes(double cells, bool periodic, bool hardness) {
  return ((hardness ? 10.0 : 8.0) * 8.0 + 1.0 + 2.0 + (periodic ? 0.0 : 8.0)) * cells;
}

/// An upper estimate of the peak memory of `coatfft run` on `scene`: the grid's fields (4 for a
/// known pressure, a contact's: contact_field_bytes), the operators' own
/// (convolution/operators/operator_memory.hpp, estimated_stress_bytes) and the program's
/// (docs/scene_format.md gives the formula). `drivers` names the scene keys that drive it.
MemoryNeed estimate_memory(const Scene& scene);

/// What the program itself takes before any array of the scene (its code, the C++, FFTW, GSL and
/// TOML libraries, FFTW's plans and tables, the heap's start): the peak resident set of
/// `coatfft run` on the smallest example scenes (65^2-128^2 cells: 9.6-10.5 MiB, less 0.5-2.3 MiB
/// of arrays; scripts/check_estimates_check.py) rounded up. Part of estimate_memory, so that small
/// scenes are not estimated at a fraction of what they take.
inline constexpr double program_bytes = 10.0 * 1024 * 1024;

/// The largest memory size parse_memory_size accepts [bytes]: 2^64, all a 64-bit machine can
/// address.
inline constexpr double max_memory_bytes = 18446744073709551616.0;

/// Parses a size such as "512M", "4G", "1.5GiB" or "1000000" (bytes; K, M, G, T are powers of
/// 1024), at most max_memory_bytes. Throws InvalidArgument naming `option`.
double parse_memory_size(std::string_view text, std::string_view option);

/// Refuses a measured topography's `pad` (cells of gap on each side of `map`) before its padded
/// gap is allocated, while the scene is read: the contact on the padded grid of `scene` (the
/// operator of its method and the contact's fields, as estimate_memory counts them) must fit
/// `limit`, or the available memory when it is not given. The message names the pad.
void check_pad_memory(const Scene& scene, const Field& map, std::int64_t pad,
                      std::optional<double> limit);

/// Refuses the scene (InvalidArgument naming the keys and both amounts) when its estimate
/// exceeds `limit`, or the available memory when `limit` is not given.
void check_memory(const Scene& scene, std::optional<double> limit);

}  // namespace coatfft::scene
