#pragma once
// Reading and writing 2-D float64 arrays as NumPy .npy (format 1.0, C order) and plain CSV.
// A Field (nx, ny) is stored as shape (ny, nx): row j is y_j (docs/conventions.md), which is
// the Field's own memory layout, so no transposition happens.
#include <filesystem>

#include "core/types.hpp"

namespace coatfft::cli {

/// Writes `field` as a (ny, nx) little-endian float64 .npy file.
void write_npy(const std::filesystem::path& path, const Field& field);

/// Reads a 2-D '<f8' C-order .npy file of shape (rows, cols) into a Field (cols, rows).
/// Throws InvalidArgument naming the file for anything else.
Field read_npy(const std::filesystem::path& path);

/// Reads a CSV matrix (rows separated by newlines, values by commas or blanks; '#' starts a
/// comment) into a Field (cols, rows). Throws InvalidArgument on ragged rows or non-numbers.
Field read_csv_matrix(const std::filesystem::path& path);

}  // namespace coatfft::cli
