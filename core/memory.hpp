#pragma once
// Memory refused before it is spent: a front end estimates what a computation needs (the
// operators' estimated_* functions) and asks require_memory before allocating, so that a grid
// too large for the machine ends in one line naming what drives the need, not in std::bad_alloc
// or the kernel's OOM killer half-way through.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace coatfft {

/// What a computation needs [bytes], and what drives it ("grid 16384 x 16384 (padded
/// 32768 x 32768 transform)"), for the refusal's message.
struct MemoryNeed {
  double bytes = 0.0;
  std::string drivers;
};

/// The memory this process may use [bytes]: MemAvailable of /proc/meminfo, or the cgroup's
/// memory.max, or what an address-space limit (ulimit -v) leaves beyond what the process has
/// mapped, whichever is smallest; nullopt when none can be read.
std::optional<double> available_memory();

/// Throws InvalidArgument "<who> needs about X GB of memory, driven by <drivers>, but Y GB is
/// available (<how to change the limit>): <remedy>" when `need` exceeds `limit`, or the available
/// memory when no limit is given (nothing is checked when neither is known). `limit_name`
/// ("--max-memory") names the caller's way to set a limit; empty when it has none.
void require_memory(const MemoryNeed& need, std::optional<double> limit, std::string_view who,
                    std::string_view limit_name, std::string_view remedy);

/// require_memory for a computation whose peak is `fields` arrays of doubles on an nx x ny grid
/// (a height map, a load, a surface and its spectrum), before the first is allocated; `who` names
/// it ("self_affine_surface"). No limit of the caller's: the available memory.
void require_grid_memory(std::ptrdiff_t nx, std::ptrdiff_t ny, double fields, std::string_view who);

}  // namespace coatfft
