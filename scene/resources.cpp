#include "scene/resources.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include "convolution/operators/operator_memory.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "scene/scene_stress.hpp"
#include "stress/stress_operator.hpp"

namespace coatfft::scene {

namespace {

// The keys that drive the operator's memory: the grid, and the lattice the method transforms.
std::string lattice_drivers(const Scene& scene, const OperatorMemory& m) {
  const Grid& grid = scene.grid;
  const std::string sizes = detail::concat("[grid] nx = ", grid.nx(), ", ny = ", grid.ny());
  if (scene.periodic()) return detail::concat(sizes, " (periodic: no padding)");
  switch (scene.method.options.method) {
    case Method::direct:
      return sizes;
    case Method::frf_spectral:
      return detail::concat(sizes, ", [method] alpha = ", scene.method.options.alpha, " (extended ",
                            m.lattice_nx, " x ", m.lattice_ny, " lattice)");
    default:
      return detail::concat(sizes, " (padded ", m.lattice_nx, " x ", m.lattice_ny, " transform)");
  }
}

}  // namespace

// The program, the operator and the fields on the grid: 4 for a known pressure, a contact's
// (contact_field_bytes) for a contact.
MemoryNeed operator_and_fields(const Scene& scene, bool contact) {
  const Grid& grid = scene.grid;
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  const OperatorMemory op = estimated_memory(grid, scene.method.options);
  const bool hardness = contact && scene.contact->hardness.has_value();
  return {program_bytes + op.bytes +
              (contact ? contact_field_bytes(cells, scene.periodic(), hardness) : 4.0 * 8.0 * cells),
          lattice_drivers(scene, op)};
}

MemoryNeed estimate_memory(const Scene& scene) {
  const Grid& grid = scene.grid;
  const double cells = static_cast<double>(grid.nx()) * static_cast<double>(grid.ny());
  MemoryNeed need = operator_and_fields(scene, scene.contact.has_value());
  if (scene.contact && !scene.contact->sweep.empty()) {
    // A sweep keeps pressure, displacement and gap of every value, and writes them stacked.
    const double values = static_cast<double>(scene.contact->sweep.size());
    need.bytes += 2 * 3.0 * 8.0 * cells * values;
    need.drivers += detail::concat(", a sweep of ", scene.contact->sweep.size(), " values");
  }
  if (scene.contact && scene.contact->partial_slip()) {
    // The tangential iteration's fields (about twenty: q, u, s, the direction and its image, the
    // state before the step), and the five fields kept of every step of a path (shear, slip,
    // stick) with the pressure, displacement and gap of the last.
    const double steps = static_cast<double>(scene.contact->tangential.size());
    need.bytes += (20.0 + 5.0 * steps) * 8.0 * cells + estimated_cerruti_bytes(grid);
    need.drivers += detail::concat(", partial slip over ", scene.contact->tangential.size(),
                                   scene.contact->tangential.size() == 1 ? " step" : " steps");
  }
  if (scene.method.options.method == Method::frf_dcfft && !scene.periodic())
    need.drivers += detail::concat(", [method] alpha = ", scene.method.options.alpha);
  if (scene.stress && scene.body) {
    const std::size_t planes = stress_planes(*scene.stress, *scene.body).depths.size();
    const bool tangential = scene.shear || (scene.contact && scene.contact->friction > 0.0);
    need.bytes +=
        estimated_stress_bytes(grid, planes, scene.stress->alpha, tangential, scene.boundary);
    need.drivers += scene.periodic() ? detail::concat(", [stress] ", planes, " periodic planes")
                                     : detail::concat(", [stress] ", planes,
                                                      " planes at alpha = ", scene.stress->alpha);
  }
  if (scene.output.in_plane) {
    need.bytes += estimated_cerruti_bytes(grid);
    need.drivers += ", ux.npy and uy.npy";
  }
  return need;
}

double parse_memory_size(std::string_view text, std::string_view option) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  std::string unit(end, text.data() + text.size());
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  double scale = 0;
  const std::string_view units[] = {"", "K", "M", "G", "T"};
  for (int n = 0; n < 5; ++n) {
    const std::string u(units[n]);
    if (unit == u || (!u.empty() && (unit == u + "B" || unit == u + "IB")))
      scale = std::pow(1024.0, n);
  }
  COATFFT_REQUIRE(ec == std::errc() && scale > 0 && std::isfinite(value) && value > 0, option,
                  " = \"", detail::shorten(text),
                  "\": expected a size such as 512M, 4G or "
                  "1000000 (bytes)");
  // A 64-bit machine addresses at most 2^64 bytes: a larger limit is a typing error (and one
  // beyond the doubles, such as 1e300T, would be infinite).
  const double bytes = value * scale;
  COATFFT_REQUIRE(bytes <= max_memory_bytes, option, " = \"", detail::shorten(text), "\" is ",
                  bytes, " bytes, above the 2^64 bytes (16 EiB) a 64-bit machine can address");
  return bytes;
}

void check_memory(const Scene& scene, std::optional<double> limit) {
  require_memory(estimate_memory(scene), limit, "the scene", "--max-memory",
                 scene.method.options.method == Method::frf_spectral
                     ? "use fewer cells or a smaller alpha"
                     : "use fewer cells");
}

void check_pad_memory(const Scene& scene, const Field& map, std::int64_t pad,
                      std::optional<double> limit) {
  MemoryNeed need = operator_and_fields(scene, true);
  need.drivers = detail::concat("[grid] pad = ", pad, " (the map's ", map.rows(), " x ", map.cols(),
                                " points and ", pad, " cells on each side): ", need.drivers);
  require_memory(need, limit, "the scene", "--max-memory", "use a smaller pad");
}

}  // namespace coatfft::scene
