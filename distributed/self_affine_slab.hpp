#pragma once
// A periodic self-affine random surface (surfaces/self_affine_surface.hpp) made in row slabs by
// the ranks of a communicator: each rank draws its rows of the random half spectrum from the same
// sequence as the serial generator and the ranks transform together, so no rank holds the whole
// surface and a seed gives the same surface at any rank count. Collective.
#include "../core/grid.hpp"
#include "../core/types.hpp"
#include "../surfaces/self_affine_surface.hpp"
#include "communicator.hpp"
#include "slab.hpp"

namespace coatfft {

/// This rank's rows of the surface, (nx, rows) (slab_of(comm, nx, ny)). InvalidArgument for a bad
/// spec, as self_affine_surface.
Field self_affine_slab(const Communicator& comm, const Grid& grid, const SelfAffineSpec& spec);

/// spectral_rms_slope of a distributed field from this rank's rows (nx, rows) [-]. Collective.
double spectral_rms_slope(const Communicator& comm, const Grid& grid, const Field& rows);

}  // namespace coatfft
