#pragma once
// Reading 2-D arrays from plain CSV files (pressure and height maps). A Field (nx, ny) is read
// from ny lines of nx values: row j is y_j, as in the .npy files (io/npy.hpp, whose rules for
// messages this reader follows: "PATH:LINE: row j, column i: ...", 1-based lines, 0-based rows
// and columns, values quoted and shortened).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "core/types.hpp"
#include "io/input_file.hpp"

namespace coatfft::io {

/// Reads a CSV matrix (rows separated by newlines, values by commas, semicolons, tabs or blanks;
/// '#' starts a comment; lines without values are skipped; a UTF-8 byte order mark at the start
/// and header lines before the first row, lines of words without a number, are skipped too) into
/// a Field (cols, rows). Values are
/// decimal numbers as std::from_chars reads them, with an optional leading '+' ("inf" and "nan"
/// included); a value too small for float64 reads as 0 or a subnormal, as strtod gives it, a value
/// too large is refused. Throws InvalidArgument on ragged rows, non-numbers or an empty file.
Field read_csv_matrix(const std::filesystem::path& path,
                      std::uintmax_t max_bytes = kMaxArrayFileBytes);

/// The values of one line of a CSV file as read_csv_matrix splits it: the text before '#', cut at
/// commas, semicolons and blanks; empty for a line without values. For readers of CSV files with
/// a header line (scene/frf_table_file.hpp).
std::vector<std::string_view> csv_tokens(std::string_view line);

/// One value as read_csv_matrix reads it; refused with "PATH:LINE: row R, column C: \"...\" is
/// not a number" (or out of the range of float64).
double csv_value(const std::filesystem::path& path, std::size_t line, std::size_t row,
                 std::size_t column, std::string_view token);

}  // namespace coatfft::io
