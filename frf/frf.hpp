#pragma once
// Frequency response function (FRF) of the surface normal displacement to a surface normal
// pressure, for a laterally homogeneous (possibly layered) half-space.
//
// Fourier convention (docs/conventions.md): f^(kx, ky) = \iint f(x, y) exp(-i (kx x + ky y)) dx dy,
// k in rad/m. With u^ = H(k) p^, H(k) is the 2-D transform of the point-force Green's function
// [m/Pa], radial, so it depends only on k = |k|. Homogeneous: H(k) = 2 / (E* k).
#include <memory>
#include <span>
#include <string>

namespace coatfft {

class LayerStack;

class Frf {
 public:
  virtual ~Frf() = default;
  /// H(k) [m/Pa] at wavenumber magnitude k > 0 [rad/m]; finite and > 0.
  virtual double operator()(double k) const = 0;
  /// H at every wavenumber of `k` (each finite and > 0) into `h` (same size) [m/Pa]: the form for
  /// callers that sample many wavenumbers at once (a lattice column, a table), so that an FRF
  /// whose evaluation has a large fixed cost per call (a Python callable of a numpy array, a
  /// solver) pays it once per batch rather than once per wavenumber. The pipelines call it from
  /// several worker threads at once, like operator(), and expect the values operator() gives
  /// (their results are then the same whichever form an FRF overrides). The default calls
  /// operator() for each, in order; throws InvalidArgument when the sizes differ.
  virtual void evaluate(std::span<const double> k, std::span<double> h) const;
  /// C0 = lim_{k->0} k H(k) [m/Pa * rad/m]: 2 / E*_substrate.
  virtual double c0() const = 0;
  /// Cinf = lim_{k->inf} k H(k): 2 / E*_top (the top coating, or the substrate).
  virtual double c_inf() const = 0;
  /// Short name for reports ("half_space", "coated_bonded", "multilayer", ...).
  virtual std::string name() const = 0;
};

/// The simplest exact FRF for `stack`: half-space, single coating closed form, or n-layer.
std::unique_ptr<Frf> make_frf(const LayerStack& stack);

}  // namespace coatfft
