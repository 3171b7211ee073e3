#pragma once
// A run's fields as one NetCDF file ([output] format = "netcdf"; docs/measured_surfaces.md,
// "NetCDF layout"): each array a variable named as its .npy file would be, over x and y with
// coordinates, units and long names, the stress planes' depths and components and a sweep's
// values as their own dimensions, and summary.json's object as the file's attribute `summary`.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string_view>

#include "io/netcdf_writer.hpp"
#include "scene/scene.hpp"
#include "scene/scene_run.hpp"

namespace coatfft::scene {

/// The file's name in the output folder.
inline constexpr const char* netcdf_output_name = "fields.nc";

/// A run's file before its variables: the grid's axes, periodic or not as summary.json's
/// "boundary" says, and summary.json's object as the file's attribute `summary`.
io::NetcdfDataset run_dataset(const Grid& grid, const nlohmann::json& summary);

/// The variable of a run's surface field "uz", "pressure", "gap", "ux" or "uy" over (x, y), with
/// its units and long name, holding `values`.
io::NetcdfVariable field_variable(std::string_view name, std::span<const double> values,
                                  std::vector<std::string> leading = {});
/// The same of one map (nx, ny), or of a slab's rows of it (nx, rows).
io::NetcdfVariable field_variable(std::string_view name, const Field& field);

/// Writes the arrays of `run` that `spec` asks for (the .npy files' arrays) into the new file
/// `path`.
void write_run_netcdf(const std::filesystem::path& path, const OutputSpec& spec,
                      const SceneRun& run);

}  // namespace coatfft::scene
