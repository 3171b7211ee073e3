#pragma once
// A field a scene names as a file ([pressure] path, [shear] path_x and path_y, [contact] path):
// a .npy or .csv array of the grid's shape (ny, nx), every value finite.
#include <filesystem>
#include <string_view>

#include "core/grid.hpp"
#include "core/types.hpp"

namespace coatfft::io {

/// Reads `file` (.npy or .csv, by its extension) as a Field (nx, ny) of `grid`. Refuses, in one
/// line, another extension (naming the scene's `key`), another shape, or a value that is not
/// finite (called a `value_word`: "value", "height").
Field read_grid_file(const std::filesystem::path& file, const Grid& grid, std::string_view key,
                     std::string_view value_word);

/// The checks of read_grid_file that need no values: `file` is a .npy file (the only kind a
/// distributed run reads by rows) whose header is sound, in C order, and gives the grid's shape;
/// the values are left to the reader of each rank's rows (io/npy_slab.hpp). `what` names the
/// file's contents in the refusal ("a height map").
void check_grid_npy(const std::filesystem::path& file, const Grid& grid, std::string_view key,
                    std::string_view what);

}  // namespace coatfft::io
