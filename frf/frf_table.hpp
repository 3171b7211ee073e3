#pragma once
// A log-spaced table of an FRF against wavenumber, for the `coatfft frf` command and plots.
#include <vector>

#include "../layers/layer_stack.hpp"
#include "frf.hpp"

namespace coatfft {

struct FrfTableRow {
  double k;                   ///< wavenumber [rad/m]
  double kh_total;            ///< k times the total coating thickness [-] (0 for a half-space)
  double frf;                 ///< H(k) [m/Pa]
  double ratio_to_substrate;  ///< H(k) / (2 / (E*_substrate k)) [-]; 1 for a half-space
};

/// nb_points >= 2 rows, k log-spaced over [k_min, k_max] [rad/m] (0 < k_min < k_max, finite),
/// endpoints included exactly; `frf` is normally make_frf(stack). Throws InvalidArgument otherwise.
std::vector<FrfTableRow> frf_table(const LayerStack& stack, const Frf& frf, double k_min,
                                   double k_max, int nb_points);

}  // namespace coatfft
