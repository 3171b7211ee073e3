#include "cli/surface_command.hpp"

#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cli/output_file.hpp"
#include "cli/staged_output.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "io/netcdf_writer.hpp"
#include "surfaces/self_affine_surface.hpp"
#ifdef COATFFT_WITH_MPI
#include "distributed/self_affine_slab.hpp"
#include "io/netcdf_collective.hpp"
#include "io/npy_slab.hpp"
#endif

namespace coatfft::cli {

std::uint64_t parse_seed(std::string_view text, std::string_view option) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  // from_chars takes no sign and stops at an exponent or a point: all of the text must be read.
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  COATFFT_REQUIRE(!text.empty() && ec == std::errc() && stop == end, option, " = \"",
                  detail::shorten(text), "\": expected an integer in [0, ",
                  std::numeric_limits<std::uint64_t>::max(), "]");
  return value;
}

namespace {

// The options checked into a grid and a spectrum, before any work.
struct SurfaceRequest {
  Grid grid;
  SelfAffineSpec spec;
  io::HeightsFormat format;
};

SurfaceRequest request(const SurfaceOptions& o) {
  const io::HeightsFormat format = io::heights_format(o.output);
  for (const auto& [name, n] : {std::pair{"--nx", o.nx}, std::pair{"--ny", o.ny}})
    COATFFT_REQUIRE(n >= 2 && n <= max_surface_cells && n % 2 == 0, name, " = ", n,
                    " must be even and in [2, ", max_surface_cells, "]");
  for (const auto& [name, l] : {std::pair{"--lx", o.lx}, std::pair{"--ly", o.ly}})
    COATFFT_REQUIRE(std::isfinite(l) && l > 0, name, " = ", l, " m must be finite and > 0");
  COATFFT_REQUIRE(o.rms_height.has_value() != o.rms_slope.has_value(),
                  "give exactly one of --rms-height and --rms-slope");
  const Grid grid(o.nx, o.ny, o.lx, o.ly);
  SelfAffineSpec spec;
  spec.hurst = o.hurst;
  spec.rms_height = o.rms_height;
  spec.rms_slope = o.rms_slope;
  spec.short_cutoff = o.short_cutoff;
  spec.long_cutoff = o.long_cutoff;
  spec.seed = parse_seed(o.seed, "--seed");
  check_self_affine_spec(grid, spec, "--rms-height", "--rms-slope");
  return {grid, spec, format};
}

// A NetCDF file in SurfaceTopography's layout says its size and that it is periodic; these say
// how it was made.
io::NetcdfAttributes surface_attributes(const SurfaceOptions& o) {
  return {{{"source", "coatfft surface"}, {"seed", o.seed}}, {{"hurst", o.hurst}}};
}

void report(const SurfaceOptions& o, double rms_height, double rms_slope) {
  std::cout << "wrote " << o.output.string() << ": " << o.ny << " x " << o.nx
            << " heights [m], rms height " << rms_height << " m, rms slope " << rms_slope << "\n";
}

}  // namespace

void surface_command(const SurfaceOptions& o) {
  const auto [grid, spec, format] = request(o);
  // The output is checked before any work: a file that cannot be written is refused at once.
  StagedFile file(o.output, "output file", {});
  refuse_existing_output(o.output, o.overwrite);
  const Field h = self_affine_surface(grid, spec);
  io::write_heights(file.path(), format, h, grid, true, surface_attributes(o));
  refuse_existing_output(o.output, o.overwrite);  // made while the surface was
  file.commit();
  report(o, std::sqrt(h.square().mean()), spectral_rms_slope(grid, h));
}

#ifdef COATFFT_WITH_MPI
void surface_command(const SurfaceOptions& o, const Communicator& comm) {
  const auto [grid, spec, format] = request(o);  // the same on every rank
  // Rank 0 checks and stages the file; its path, or its refusal, goes to every rank.
  std::optional<StagedFile> file;
  std::string staged, refusal;
  if (comm.rank() == 0) {
    try {
      file.emplace(o.output, "output file", std::vector<std::filesystem::path>{});
      refuse_existing_output(o.output, o.overwrite);
      staged = file->path().string();
    } catch (const InvalidArgument& e) {
      refusal = e.what();
    }
  }
  comm.broadcast(refusal);
  if (!refusal.empty()) throw InvalidArgument(refusal);
  comm.broadcast(staged);
  const Field h = self_affine_slab(comm, grid, spec);
  const Slab slab = slab_of(comm, grid.nx(), grid.ny());
  if (format == io::HeightsFormat::npy)
    io::write_npy_slab(comm, staged, h, slab);
  else
    io::write_heights_slab(comm, staged, h, grid, slab, true, surface_attributes(o));
  const double rms_height =
      std::sqrt(comm.sum(h.square().sum()) / static_cast<double>(grid.nb_cells()));
  const double rms_slope = spectral_rms_slope(comm, grid, h);
  if (comm.rank() != 0) return;
  file->commit();
  report(o, rms_height, rms_slope);
}
#endif

}  // namespace coatfft::cli
