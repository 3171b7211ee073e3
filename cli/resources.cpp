#include "cli/resources.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>

#include "cli/scene_stress.hpp"
#include "convolution/dcfft_operator.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "core/fft_size.hpp"

namespace coatfft::cli {

namespace {

std::string gigabytes(double bytes) {
  return detail::concat(std::round(bytes / 1e7) / 100, " GB");
}

// The transform lattice of the method: its size in cells and a description naming its keys.
std::pair<double, std::string> transform_lattice(const Scene& scene) {
  const Grid& grid = scene.grid;
  const OperatorOptions& o = scene.method.options;
  const double nx = static_cast<double>(grid.nx());
  const double ny = static_cast<double>(grid.ny());
  const std::string sizes = detail::concat("[grid] nx = ", grid.nx(), ", ny = ", grid.ny());
  // A periodic operator transforms the grid itself (convolution/periodic_operator.hpp).
  if (scene.periodic) return {nx * ny, detail::concat(sizes, " (periodic: no padding)")};
  switch (o.method) {
    case Method::direct:
      return {0.0, sizes};
    case Method::frf_spectral:
      return {o.alpha * o.alpha * nx * ny,
              detail::concat(sizes, ", [method] alpha = ", o.alpha, " (extended ", o.alpha * nx,
                             " x ", o.alpha * ny, " lattice)")};
    default: {
      // DC-FFT's padded lattice: frf-dcfft at alpha = 2 hands it a spectrum (exactly 2n).
      const auto form = o.method == Method::frf_dcfft && o.alpha == 2.0
                            ? InfluenceKernel::Form::spectrum
                            : InfluenceKernel::Form::coefficients;
      const std::ptrdiff_t mx = DcfftOperator::padded_size(grid.nx(), form);
      const std::ptrdiff_t my = DcfftOperator::padded_size(grid.ny(), form);
      return {static_cast<double>(mx) * static_cast<double>(my),
              detail::concat(sizes, " (padded ", mx, " x ", my, " transform)")};
    }
  }
}

}  // namespace

MemoryEstimate estimate_memory(const Scene& scene) {
  const double cells = static_cast<double>(scene.grid.nx()) * static_cast<double>(scene.grid.ny());
  const double fields = scene.contact ? 12.0 : 4.0;
  auto [lattice, drivers] = transform_lattice(scene);
  // A real input array, its complex half spectrum and the kernel's half spectrum: 2.5 doubles per
  // lattice cell; the kernel construction of frf-split and frf-dcfft holds one more lattice.
  double per_lattice_cell = 2.5 * 8.0;
  const Method method = scene.method.options.method;
  if (method == Method::frf_split || method == Method::frf_dcfft) per_lattice_cell += 8.0;
  double bytes = program_bytes + 8.0 * fields * cells + per_lattice_cell * lattice;
  // A contact's preconditioner: a real field, its half spectrum and the multiplier on the grid.
  if (scene.contact) bytes += 20.0 * cells;
  if (method == Method::frf_dcfft) {
    const double alpha = scene.method.options.alpha;
    bytes += 16.0 * alpha * alpha * cells;  // the FRF sampled on the alpha-extended lattice
    drivers += detail::concat(", [method] alpha = ", alpha);
  }
  if (scene.stress && scene.body) {
    bytes += stress_memory_bytes(*scene.stress, *scene.body, scene.grid);
    drivers += detail::concat(", [stress] ", stress_plane_depths(*scene.stress, *scene.body).size(),
                              " planes at alpha = ", scene.stress->alpha);
  }
  if (scene.output.in_plane) {
    // CerrutiOperator (convolution/parity_convolution.hpp): nine spectrum quarters, three load
    // spectra of the padded lattice and the three outputs; while it is built, six coefficient
    // fields and four lattice quarters of the layered remainders plus their long-range band.
    const double hx = double(fast_even_fft_size(2 * scene.grid.nx() - 1)) / 2 + 1;
    const double my = double(fast_even_fft_size(2 * scene.grid.ny() - 1));
    bytes +=
        8.0 * (9 * hx * (my / 2 + 1) + 3 * 2 * hx * my + 9 * cells +
               4 * (scene.grid.nx() + 1.0) * (scene.grid.ny() + 1.0) + 4 * std::pow(34.0 * 16, 2));
    drivers += ", ux.npy and uy.npy";
  }
  return {bytes, drivers};
}

std::optional<double> available_memory() {
  std::optional<double> bytes;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kib = 0;
    std::string unit;
    meminfo >> kib >> unit;
    if (key == "MemAvailable:") bytes = kib * 1024.0;
  }
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  double limit = 0;
  if (cgroup >> limit && (!bytes || limit < *bytes)) bytes = limit;  // "max" fails to parse
  return bytes;
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
  const MemoryEstimate need = estimate_memory(scene);
  const std::optional<double> have = limit ? limit : available_memory();
  if (!have) return;
  COATFFT_REQUIRE(need.bytes <= *have, "the scene needs about ", gigabytes(need.bytes),
                  " of memory, driven by ", need.drivers, ", but ", gigabytes(*have), " ",
                  limit ? "is the limit (--max-memory)" : "is available (--max-memory to change)",
                  ": use fewer cells",
                  scene.method.options.method == Method::frf_spectral ? " or a smaller alpha" : "");
}

}  // namespace coatfft::cli
