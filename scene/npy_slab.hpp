#pragma once
// A distributed field (distributed/slab.hpp) written as one .npy file without gathering it: rank
// 0 writes the preamble, every rank its rows at their offset (the file's rows are the field's,
// scene/npy.hpp), in one collective MPI-IO write. Built with COATFFT_MPI.
#include <filesystem>

#include "core/types.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"

namespace coatfft::scene {

/// Writes this rank's rows `rows` (nx, slab.rows) of the (nx, ny) field as `path`: the file
/// write_npy writes of the whole field, byte for byte. Collective; InvalidArgument on every rank
/// when any rank cannot open or write the file.
void write_npy_slab(const Communicator& comm, const std::filesystem::path& path, const Field& rows,
                    const Slab& slab);

}  // namespace coatfft::scene
