#include "cli/frf_command.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

#include "cli/staged_output.hpp"
#include "core/detail/close_written.hpp"
#include "core/error.hpp"
#include "frf/frf.hpp"
#include "frf/frf_table.hpp"
#include "scene/resources.hpp"
#include "scene/scene.hpp"

namespace coatfft::cli {

void frf_command(const FrfOptions& options) {
  const LayerStack body = scene::read_scene_body(options.scene);
  const double h = body.total_thickness();
  // Coated: span the transition from the substrate (k h << 1) to the coating (k h >> 1).
  const double k_min = options.k_min.value_or(h > 0 ? 1e-3 / h : 1e2);
  const double k_max = options.k_max.value_or(h > 0 ? 1e3 / h : 1e8);
  COATFFT_REQUIRE(std::isfinite(k_min) && k_min > 0, "--k-min = ", k_min, " must be > 0");
  COATFFT_REQUIRE(std::isfinite(k_max) && k_max > k_min, "--k-max = ", k_max,
                  " must be finite and > --k-min = ", k_min);
  COATFFT_REQUIRE(options.points >= 2 && options.points <= scene::max_frf_points,
                  "--points = ", options.points, " must be in 2..", scene::max_frf_points);
  // The output is checked before any work: a table that cannot be written is refused at once.
  std::optional<StagedFile> file;
  if (!options.output.empty())
    file.emplace(options.output, "output file", std::vector{options.scene});

  const auto frf = make_frf(body);
  std::ostringstream table;
  table << "k,kh_total,frf,frf_over_substrate\n" << std::setprecision(17);
  for (const auto& row : frf_table(body, *frf, k_min, k_max, static_cast<int>(options.points)))
    table << row.k << ',' << row.kh_total << ',' << row.frf << ',' << row.ratio_to_substrate
          << '\n';

  if (!file) {
    std::cout << table.str();
    return;
  }
  // Whole-file write through a temporary name: no partial table on failure.
  {
    std::ofstream out(file->path());
    COATFFT_REQUIRE(out.good(), "cannot write ", file->path().string());
    out << table.str();
    detail::close_written(out, file->path());
  }
  file->commit();
}

}  // namespace coatfft::cli
