#include "frf/frf_table.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace coatfft {

std::vector<FrfTableRow> frf_table(const LayerStack& stack, const Frf& frf, double k_min,
                                   double k_max, int nb_points) {
  COATFFT_REQUIRE(std::isfinite(k_min) && k_min > 0, "frf_table: k_min = ", k_min,
                  " rad/m, but it must be finite and > 0");
  COATFFT_REQUIRE(std::isfinite(k_max) && k_max > k_min, "frf_table: k_max = ", k_max,
                  " rad/m, but it must be finite and > k_min = ", k_min, " rad/m");
  COATFFT_REQUIRE(nb_points >= 2, "frf_table: nb_points = ", nb_points, ", but it must be >= 2");
  const double h_total = stack.total_thickness();
  const double c_substrate = 2.0 / stack.substrate().plane_strain_modulus();
  const double log_min = std::log(k_min);
  const double step = (std::log(k_max) - log_min) / (nb_points - 1);
  const auto n = static_cast<std::size_t>(nb_points);
  std::vector<double> k(n);
  for (std::size_t i = 0; i < n; ++i) k[i] = std::exp(log_min + static_cast<double>(i) * step);
  k.front() = k_min;  // the endpoints exactly, not through exp(log)
  k.back() = k_max;
  // One batch for the whole table (an FRF may have a cost per call, Frf::evaluate).
  std::vector<double> h(n);
  frf.evaluate(k, h);
  std::vector<FrfTableRow> rows;
  rows.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    rows.push_back({k[i], k[i] * h_total, h[i], h[i] * k[i] / c_substrate});
  return rows;
}

}  // namespace coatfft
