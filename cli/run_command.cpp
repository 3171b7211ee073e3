#include "cli/run_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli/npy.hpp"
#include "cli/operator_from_scene.hpp"
#include "cli/scene.hpp"
#include "cli/staged_output.hpp"
#include "core/error.hpp"
#include "loads/hertz_pressure.hpp"
#include "loads/uniform_disk_pressure.hpp"
#include "validation/hertz.hpp"

namespace coatfft::cli {

namespace {

Field read_pressure_file(const std::filesystem::path& file, const Grid& grid) {
  const std::string ext = file.extension().string();
  COATFFT_REQUIRE(ext == ".npy" || ext == ".csv", "[pressure] path = ", file.string(),
                  ": must end in .npy or .csv");
  Field p = ext == ".npy" ? read_npy(file) : read_csv_matrix(file);
  COATFFT_REQUIRE(p.rows() == grid.nx() && p.cols() == grid.ny(), file.string(), ": shape (",
                  p.cols(), ", ", p.rows(), ") but the grid needs (ny, nx) = (", grid.ny(), ", ",
                  grid.nx(), ")");
  for (Eigen::Index j = 0; j < p.cols(); ++j)
    for (Eigen::Index i = 0; i < p.rows(); ++i)
      COATFFT_REQUIRE(std::isfinite(p(i, j)), file.string(), ": value at row ", j, ", column ", i,
                      " is ", p(i, j), "; pressures must be finite");
  return p;
}

Field pressure_from_scene(const Scene& scene) {
  const PressureSpec& spec = *scene.pressure;
  if (spec.kind == "file") return read_pressure_file(spec.file, scene.grid);
  const Sampling sampling = spec.sampling == "cell_average" ? Sampling::cell_average : Sampling::centre;
  if (spec.kind == "hertz") return hertz_pressure(scene.grid, spec.amplitude, spec.radius, sampling);
  return uniform_disk_pressure(scene.grid, spec.amplitude, spec.radius, sampling);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Index of the cell centre nearest the origin; for an even count the two middle cells tie and
// the lower index (centre at -d/2) is taken.
Eigen::Index centre_index(std::ptrdiff_t n) { return static_cast<Eigen::Index>((n - 1) / 2); }

void write_displacement_csv(const std::filesystem::path& path, const Grid& grid, const Field& p,
                            const Field& uz) {
  std::ofstream out(path);
  COATFFT_REQUIRE(out.good(), "cannot open ", path.string(), " for writing");
  out << "x,y,pressure,uz\n" << std::setprecision(17);
  for (Eigen::Index j = 0; j < grid.ny(); ++j)
    for (Eigen::Index i = 0; i < grid.nx(); ++i)
      out << grid.x(i) << ',' << grid.y(j) << ',' << p(i, j) << ',' << uz(i, j) << '\n';
  COATFFT_REQUIRE(out.good(), "failed writing ", path.string());
}

}  // namespace

void run_command(const RunOptions& options) {
  COATFFT_REQUIRE(options.repeat >= 1, "--repeat = ", options.repeat, " must be >= 1");
  const Scene scene = read_scene(options.scene);
  const Grid& grid = scene.grid;
  const Field pressure = pressure_from_scene(scene);
  BuiltOperator built = operator_from_scene(scene);

  Field uz;
  std::vector<double> apply_seconds;
  for (int r = 0; r < options.repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    built.op->apply(pressure, uz);
    apply_seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  COATFFT_REQUIRE(uz.allFinite(), "internal error: the displacement has non-finite values");

  nlohmann::json summary;
  summary["method"] = built.op->name();
  summary["nx"] = grid.nx();
  summary["ny"] = grid.ny();
  summary["lx"] = grid.lx();
  summary["ly"] = grid.ly();
  summary["setup_seconds"] = built.setup_seconds;
  summary["apply_seconds"] = median(apply_seconds);
  summary["repeat"] = options.repeat;
  summary["total_load"] = pressure.sum() * grid.dx() * grid.dy();
  summary["uz_center"] = uz(centre_index(grid.nx()), centre_index(grid.ny()));
  summary["uz_max"] = uz.maxCoeff();
  for (const auto& [key, value] : built.report.items()) summary[key] = value;

  const PressureSpec& load = *scene.pressure;
  if (load.kind == "hertz" && scene.body.is_homogeneous()) {
    // The seed's error measure (section 5): (u_num - u_exact) / u_exact(0).
    const double E_star = scene.body.substrate().plane_strain_modulus();
    const double u0 = hertz_displacement(0.0, load.amplitude, load.radius, E_star);
    double max_error = 0;
    for (Eigen::Index j = 0; j < grid.ny(); ++j)
      for (Eigen::Index i = 0; i < grid.nx(); ++i) {
        const double exact =
            hertz_displacement(std::hypot(grid.x(i), grid.y(j)), load.amplitude, load.radius, E_star);
        max_error = std::max(max_error, std::abs(uz(i, j) - exact) / u0);
      }
    summary["max_error_vs_hertz"] = max_error;
  }

  StagedOutput out(options.outdir);
  write_npy(out.path("uz.npy"), uz);
  write_npy(out.path("pressure.npy"), pressure);
  write_displacement_csv(out.path("displacement.csv"), grid, pressure, uz);
  {
    std::ofstream json(out.path("summary.json"));
    json << std::setw(2) << summary << '\n';
    COATFFT_REQUIRE(json.good(), "failed writing summary.json");
  }
  out.commit();
}

}  // namespace coatfft::cli
