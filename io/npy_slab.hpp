#pragma once
// A distributed field (distributed/slab.hpp) read from and written as one .npy file without
// gathering it: every rank reads or writes its rows at their offset (the file's rows are the
// field's, io/npy.hpp) in one collective MPI-IO call; rank 0 writes the preamble. Built with
// COATFFT_MPI.
#include <filesystem>
#include <string_view>

#include "core/types.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"

namespace coatfft::io {

/// Writes this rank's rows `rows` (nx, slab.rows) of the (nx, ny) field as `path`: the file
/// write_npy writes of the whole field, byte for byte. Collective; InvalidArgument on every rank
/// when any rank cannot open or write the file.
void write_npy_slab(const Communicator& comm, const std::filesystem::path& path, const Field& rows,
                    const Slab& slab);

/// Writes every rank's `text` one after the other in rank order as `path` (a CSV file of the
/// ranks' rows, rank 0's text starting with its header). Collective; InvalidArgument on every
/// rank when any rank cannot open or write the file.
void write_text_slab(const Communicator& comm, const std::filesystem::path& path,
                     std::string_view text);

/// This rank's rows (nx, slab.rows) of the 2-D .npy file at `path`: any dtype read_npy reads, in
/// C order (Fortran's keeps a row's values apart), of the slab's grid's shape (ny, nx), every value
/// finite (a `value_word`: "height"). Collective; InvalidArgument with the same one-line message
/// on every rank for a file read_npy refuses (each rank checks the header, agreed as
/// distributed/detail/agreed_refusal.hpp agrees) and for the first value in the file's order that
/// is not finite (named with the rank that read it and that rank's path).
Field read_npy_slab(const Communicator& comm, const std::filesystem::path& path, const Slab& slab,
                    std::string_view value_word);

}  // namespace coatfft::io
