#pragma once
// A single output file a command writes (`coatfft topography -o`, `coatfft surface -o`): a file
// the user already has is theirs, and is replaced only when they say so
// (docs/measured_surfaces.md).
#include <filesystem>
#include <string_view>

namespace coatfft::cli {

/// Refuses (InvalidArgument, one line naming `target` and `flag`) a `target` that exists, unless
/// `overwrite`; what else may stand in its place is StagedFile's to check.
void refuse_existing_output(const std::filesystem::path& target, bool overwrite,
                            std::string_view flag = "--overwrite");

}  // namespace coatfft::cli
