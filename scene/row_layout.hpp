#pragma once
// The rows of the grid a run holds, and how its numbers combine with those of the rows it does
// not hold (docs/scale.md): the whole grid in a serial run (RowLayout{}), one slab of a
// distributed run, whose sums and maxima go over the ranks (scene/distributed_run.cpp). What a
// run reports of its fields is written once over it, for the serial and the distributed run.
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>

#include "convolution/operators/surface_operator.hpp"
#include "core/types.hpp"
#include "scene/run_summary.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

struct RowLayout {
  std::ptrdiff_t y0 = 0;  ///< the first row held
  /// A number's sum and maximum over every holder of rows (itself alone in a serial run).
  std::function<double(double)> sum = [](double value) { return value; };
  std::function<double(double)> max = [](double value) { return value; };
};

/// summary.json's numbers of the fields (this holder's rows (nx, rows) of `grid`): the total
/// load, uz at the centre cell (from the holder of its row), the largest uz.
FieldNumbers field_numbers(const Grid& grid, const RowLayout& rows, const Field& pressure,
                           const Field& uz);

/// A known load's reports, added to `summary`: the a-posteriori error (free boundaries), the
/// load's discretisation estimate (its difference's displacement by `op`, the rows' 2 x 2 blocks
/// across holders sampled again: loads/discretization_error.hpp), the grid refinement and the
/// error against Hertz's closed form. `numbers` are field_numbers' of the same fields.
void add_known_load_reports(nlohmann::json& summary, const Scene& scene, const RowLayout& rows,
                            const FieldNumbers& numbers, SurfaceOperator& op, const Field& pressure,
                            const Field& uz);

}  // namespace coatfft::scene
