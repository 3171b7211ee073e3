#pragma once
// The displacement methods of coatfft, listed once. Scene files, summary.json, the benchmarks and
// the validation tables name them by to_string(); make_operator
// (convolution/operators/make_operator.hpp) is the one place that maps a Method to the class that
// runs it.
#include <array>
#include <string_view>

namespace coatfft {

/// The surface's extent: free (an isolated load on a half-space, the grid a window of it), or
/// periodic (the grid one period of a surface repeated in x and y, docs/theory.md 4.8). Every
/// operator factory takes it: the surface's, the tangential and the stress operator.
enum class Boundary { free, periodic };

/// The boundary's name in scene files ([grid] boundary), Python's keyword and reports: "free",
/// "periodic".
std::string_view to_string(Boundary boundary);

/// The Boundary named `name` (as to_string writes it); throws InvalidArgument
/// ("\"x\" is not one of \"free\", \"periodic\"") otherwise.
Boundary parse_boundary(std::string_view name);

enum class Method {
  direct,        ///< brute-force sum of Love's coefficients (reference; homogeneous only)
  dcfft,         ///< DC-FFT of Love's coefficients (Liu, Wang & Liu 2000; homogeneous only)
  frf_spectral,  ///< FRF sampled on an alpha-extended periodic lattice (Spinu 2021, algorithm 1)
  frf_dcfft,     ///< coefficients from the sampled FRF, then DC-FFT (Spinu 2021, algorithm 2)
  frf_split,  ///< coefficients of any FRF by the split kernel, then DC-FFT (docs/split_kernel.md)
};

/// Every method, in the order above (what the benchmarks sweep over).
inline constexpr std::array<Method, 5> all_methods = {
    Method::direct, Method::dcfft, Method::frf_spectral, Method::frf_dcfft, Method::frf_split};

/// The name used in scene files and reports: "direct", "dcfft", "frf-spectral", "frf-dcfft",
/// "frf-split".
std::string_view to_string(Method method);

/// The Method named `name` (as to_string writes it); throws InvalidArgument
/// ("\"x\" is not one of \"direct\", ...") otherwise.
Method parse_method(std::string_view name);

/// True for the methods built on Love's closed-form coefficients, which exist only for a
/// homogeneous half-space (direct, dcfft).
bool uses_love_coefficients(Method method);

/// True for the methods of Spinu (2021) that sample the FRF on an alpha-extended lattice and so
/// take `alpha` and need g(0) (frf-spectral, frf-dcfft).
bool samples_frf_lattice(Method method);

}  // namespace coatfft
