#include "stress/stress_operator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "core/detail/fft_size.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "frf/stress_frf.hpp"

namespace coatfft {

namespace {

void refuse_sliding_tangential(const LayerStack& stack) {
  for (std::size_t i = 0; i < stack.coatings().size(); ++i)
    if (stack.coatings()[i].interface_below == Interface::frictionless)
      throw InvalidArgument(
          "stress operator: tangential tractions on a body with a frictionless "
          "interface (below coating " +
          std::to_string(i + 1) +
          ") are not supported: a net tangential force has no equilibrium "
          "there");
}

// Stress component c's kernels, one per load, with their parities: ParityKernel (coefficients)
// or ParitySpectrum (spectra), each {field, odd_x, odd_y}. The fields are moved from.
template <typename Kernel>
std::vector<Kernel> per_load(std::array<Field, 3>& fields, int c, int nb_loads) {
  std::vector<Kernel> kernels;
  for (int l = 0; l < nb_loads; ++l) {
    const auto odd = stress_frf_odd(c, l);
    kernels.push_back({std::move(fields[l]), odd[0], odd[1]});
  }
  return kernels;
}

}  // namespace

void require_stress_depths(const std::vector<double>& depths) {
  if (depths.empty()) throw InvalidArgument("stress operator: no depth given");
  COATFFT_REQUIRE(depths.size() <= StressOperator::max_planes, "stress operator: ", depths.size(),
                  " depths given; at most ", StressOperator::max_planes, " planes");
  for (double z : depths)
    if (!std::isfinite(z) || z <= 0.0)
      throw InvalidArgument(detail::concat(
          "stress operator: depth z = ", z,
          " m: every depth must be finite and > 0 [m] (z points into the body; the surface plane "
          "z = 0 is not computed)"));
}

double estimated_stress_bytes(const Grid& grid, std::size_t planes, int alpha, bool tangential,
                              Boundary boundary) {
  const double n = static_cast<double>(planes);
  const double loads = tangential ? 3.0 : 1.0;
  const double cells = double(grid.nx()) * double(grid.ny());
  if (boundary == Boundary::periodic) {
    // Per plane: six spectrum quarters per load and the six output fields; the load spectra.
    const double quarter = (grid.nx() / 2 + 1.0) * (grid.ny() / 2 + 1.0);
    return 8.0 * (n * (6 * loads * quarter + 7 * cells) + 4 * loads * quarter);
  }
  const double hx = double(detail::fast_even_fft_size(2 * grid.nx() - 1)) / 2 + 1;
  const double hy = double(detail::fast_even_fft_size(2 * grid.ny() - 1)) / 2 + 1;
  // Per plane: six spectrum quarters per load and the six output fields (plus von Mises on
  // output); while a group of up to 8 planes is built: six quarters of DC-FFT's lattice and six
  // of the long-range band, about (34 alpha)^2 entries (sqrt(45) 32 alpha/(2 pi) per side); the
  // load spectra of the padded lattice.
  const double group = std::min(n, 8.0);
  const double short_quarter = (grid.nx() + 1.0) * (grid.ny() + 1.0);
  const double band = std::pow(34.0 * alpha, 2);
  return 8.0 * (n * (6 * loads * hx * hy + 7 * cells) + group * 6 * (short_quarter + band) +
                12 * loads * hx * hy);
}

StressOperator::StressOperator(const Grid& grid, const LayerStack& stack,
                               std::vector<double> depths, const StressOperatorOptions& options)
    : depths_(std::move(depths)),
      tangential_(options.tangential),
      convolution_(grid, options.tangential ? 3 : 1, options.planning,
                   options.boundary == Boundary::periodic) {
  const auto start = std::chrono::steady_clock::now();
  require_stress_depths(depths_);
  COATFFT_REQUIRE(options.sides.empty() || options.sides.size() == depths_.size(),
                  "stress operator: ", options.sides.size(), " sides given for ", depths_.size(),
                  " depths");
  if (tangential_) refuse_sliding_tangential(stack);
  const auto side = [&](std::size_t p) {
    return options.sides.empty() ? options.side : options.sides[p];
  };
  // The planes' kernels are made in groups of consecutive planes on the same side: one FRF
  // solve per wavevector serves a group, and a group's lattice quarters (six per plane) bound
  // the memory.
  constexpr std::size_t kGroup = 8;
  for (std::size_t first = 0, count = 0; first < depths_.size(); first += count) {
    count = 1;
    while (count < kGroup && first + count < depths_.size() && side(first + count) == side(first))
      ++count;
    if (options.on_planes) options.on_planes(first, count, depths_.size());
    add_planes(grid, stack, first, count, side(first), options);
  }
  setup_seconds_ = detail::seconds_since(start);
}

// The six outputs of each plane first..first + count - 1: from the coefficients of a free
// surface, or from the spectra of a periodic one.
void StressOperator::add_planes(const Grid& grid, const LayerStack& stack, std::size_t first,
                                std::size_t count, InterfaceSide side,
                                const StressOperatorOptions& options) {
  const int nb_loads = convolution_.nb_loads();
  const auto depths = std::span<const double>(depths_).subspan(first, count);
  std::vector<StressKernelReport> reports;
  if (options.boundary == Boundary::periodic) {
    for (StressPlaneSpectrum& plane :
         periodic_stress_spectra(grid, stack, depths, side, tangential_, options.kernel, &reports))
      for (int c = 0; c < 6; ++c)
        convolution_.add_spectral_output(per_load<ParitySpectrum>(plane.quarters[c], c, nb_loads));
  } else {
    for (StressPlaneKernel& kernel :
         stress_plane_kernels(grid, stack, depths, side, tangential_, options.kernel, &reports))
      for (int c = 0; c < 6; ++c)
        convolution_.add_output(per_load<ParityKernel>(kernel.coefficients[c], c, nb_loads));
  }
  reports_.insert(reports_.end(), reports.begin(), reports.end());
}

void StressOperator::apply(const Field& pressure, const Field* qx, const Field* qy,
                           std::vector<PlaneStress>& stress) {
  if (!tangential_ && (qx || qy))
    throw InvalidArgument(
        "stress operator: tractions given to an operator built for pressure only");
  const Field* loads[3] = {&pressure, qx, qy};
  try {
    convolution_.apply(std::span<const Field* const>(loads, tangential_ ? 3 : 1), fields_);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("stress operator: ") + e.what());
  }
  stress.resize(depths_.size());
  for (std::size_t p = 0; p < depths_.size(); ++p)
    for (int c = 0; c < 6; ++c) std::swap(stress[p][c], fields_[6 * p + c]);
}

std::unique_ptr<StressOperator> make_stress_operator(const Grid& grid, const LayerStack& body,
                                                     std::vector<double> depths,
                                                     const StressOperatorOptions& options) {
  return std::make_unique<StressOperator>(grid, body, std::move(depths), options);
}

}  // namespace coatfft
