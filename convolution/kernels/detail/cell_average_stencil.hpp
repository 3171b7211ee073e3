#pragma once
// A 9-point stencil that turns point values into cell averages:
//
//   (1/d) \int_{-d/2}^{d/2} f(x + s) ds  ~=  sum_{j=-4..4} c_|j| f(x + j d),
//
// exact for polynomials of degree 9: the weights match the moments
// sum_j c_|j| j^(2n) = \int_{-1/2}^{1/2} s^(2n) ds = 1 / ((2n + 1) 4^n), n = 0..4 (exact
// rationals, solved once). In Fourier terms sum_j c_|j| cos(j t) = sinc(t/2) + E t^10 + ...,
// E = 1.06e-5, t = k d: relative error 2.8e-13 at t = 0.175, 2.8e-10 at t = 0.35, 2.7e-7 at
// t = 0.7. For f = 1/r (singular at distance r) the error is ~E 10! (d/r)^10 f, 3e-16 of Love's
// K(0, 0) at r = 32 d. Applied along x and then along y it gives the cell average over a
// rectangle of a function that is smooth on the scale of a few cells, from one point value per
// cell (the split kernel's far field, docs/split_kernel.md section 5).
#include <array>

namespace coatfft::detail {

inline constexpr int cell_average_half_width = 4;
/// c_0 .. c_4 of the stencil above (c_-j = c_j); they sum (with c_-j) to 1.
inline constexpr std::array<double, 5> cell_average_weights = {
    41208059.0 / 46448640.0, 3629953.0 / 58060800.0, -801973.0 / 116121600.0, 49879.0 / 58060800.0,
    -27859.0 / 464486400.0};

}  // namespace coatfft::detail
