#pragma once
// What `coatfft run` writes besides the fields' arrays, shared by the serial run
// (cli/run_command.cpp) and the distributed one (cli/distributed_run_command.cpp): the output
// names of a scene's [output], displacement.csv's lines, summary.json, the warnings on stderr and
// the lines of what the run found on stdout.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/types.hpp"
#include "scene/scene.hpp"

namespace coatfft::cli {

/// The files a run writes, in the order of the manifest (cli/staged_output.hpp): only these are
/// checked, staged and committed. With format = "netcdf", the .npy files' arrays go into one file
/// instead, named in the place of the first of them.
std::vector<std::string> output_names(const scene::OutputSpec& spec);

/// "a, b, c".
std::string joined(const std::vector<std::string>& names);

/// displacement.csv's lines "x,y,pressure,uz" of the rows y0 <= j < y0 + p.cols() (p and uz hold
/// those rows), after its header when `header`, at full precision.
void write_displacement_rows(std::ostream& out, const Grid& grid, std::ptrdiff_t y0, const Field& p,
                             const Field& uz, bool header);

/// summary.json: `summary` indented.
void write_summary(const std::filesystem::path& path, const nlohmann::json& summary);

/// Every warning of summary.json on stderr, as README promises: the operator's, the stress
/// planes', and the contact solver's note (why it did not converge; main.cpp adds the exit
/// status's line).
void print_warnings(const nlohmann::json& summary);

/// What the run found, in a few lines on stdout (scene/run_highlights.hpp): the contact's radius
/// and peak pressure against Hertz's, the largest stresses and where they are.
void print_highlights(const nlohmann::json& summary);

}  // namespace coatfft::cli
