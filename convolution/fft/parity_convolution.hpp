#pragma once
// Linear convolutions of up to three loads with influence coefficients that are even or odd along
// each axis (the stress kernels of a plane, Cerruti's and Love's surface coefficients), each
// output the sum over the loads, computed exactly (to rounding) as circular convolutions on a
// zero-padded grid, as DC-FFT does (Liu, Wang & Liu 2000); or, for a periodic surface, circular
// convolutions on the grid itself, whose kernels are given by their periodic coefficients or
// by their spectra on the period's lattice. A kernel's spectrum is then real or
// imaginary and is stored as a real quarter (convolution/fft/parity_transform.hpp); the loads are
// transformed once per apply, and each output costs one pruned inverse transform: half a
// surface application.
#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "../../core/grid.hpp"
#include "../../core/types.hpp"
#include "planning.hpp"

namespace coatfft {

/// Influence coefficients K(i dx, j dy) for 0 <= i < nx, 0 <= j < ny (`quarter`, (nx, ny)), the
/// other quadrants by the parity: K(-x, y) = -K(x, y) when odd_x, likewise in y. An empty quarter
/// is a zero kernel.
struct ParityKernel {
  Field quarter;
  bool odd_x = false;
  bool odd_y = false;
};

/// A kernel given by its spectrum on the convolution's lattice: `quarter` (lattice_quarter())
/// holds G(kx, ky) = i^(odd_x + odd_y) F(kx, ky) for 0 <= kx, ky up to Nyquist, F the spectrum of
/// the coefficients (forward transform exp(-i k.x), real G by the parity); F at -kx, -ky follows
/// from the parity. An empty quarter is a zero kernel.
struct ParitySpectrum {
  Field quarter;
  bool odd_x = false;
  bool odd_y = false;
};

class ParityConvolution {
 public:
  /// Plans the transforms of `nb_loads` (1..3) loads on `grid`: linear convolutions (on a padded
  /// lattice), or circular ones over the grid's period when `periodic` (nx, ny even).
  ParityConvolution(const Grid& grid, int nb_loads, Planning planning = Planning::estimate,
                    bool periodic = false);
  ~ParityConvolution();
  ParityConvolution(ParityConvolution&&) noexcept;
  ParityConvolution& operator=(ParityConvolution&&) noexcept;

  /// Adds an output: the sum over the loads l of kernels[l] convolved with load l (kernels has
  /// nb_loads entries, each empty or of shape (nx, ny)). Throws InvalidArgument otherwise. For a
  /// periodic convolution a kernel's (nx, ny) entries are its periodic coefficients at the
  /// offsets (i dx, j dy) modulo the period (those past nx/2, ny/2 follow from the parity).
  void add_output(std::span<const ParityKernel> kernels);
  /// Adds an output given by its kernels' spectra (one per load, each empty or of shape
  /// lattice_quarter()).
  void add_spectral_output(std::span<const ParitySpectrum> spectra);

  /// The quarter (mx/2 + 1, my/2 + 1) of the lattice the spectra are given on: (mx, my) the
  /// padded lengths, or (nx, ny) for a periodic convolution.
  std::array<std::ptrdiff_t, 2> lattice_quarter() const { return {hx_, hy_}; }
  bool periodic() const { return periodic_; }

  const Grid& grid() const { return grid_; }
  int nb_loads() const { return nb_loads_; }
  std::size_t nb_outputs() const { return spectra_.size(); }

  /// Every output under the loads (nb_loads pointers; null: a zero load, which costs nothing),
  /// each (nx, ny) and finite (InvalidArgument otherwise). `out` is resized to nb_outputs()
  /// fields (nx, ny). With `first` < nb_outputs(), only the outputs 0 .. first - 1 are computed
  /// (each one pruned inverse transform less); the others are left as they were.
  void apply(std::span<const Field* const> loads, std::vector<Field>& out,
             std::size_t first = static_cast<std::size_t>(-1));

  /// Bytes held: the kernels' spectrum quarters and the buffers.
  std::size_t memory_bytes() const;

 private:
  struct Transforms;  // FFTW plans and buffers: FFTW stays out of the public headers

  void plan_transforms(Planning planning);
  void transform_load(int load, const Field* field);
  void multiply_block(std::size_t output, std::ptrdiff_t c0, std::ptrdiff_t width);
  void inverse_into(std::size_t output, Field& out);

  Grid grid_;
  int nb_loads_;
  bool periodic_;
  std::ptrdiff_t mx_, my_, hx_, hy_;  // padded lengths, mx/2 + 1, my/2 + 1
  // spectra_[output][load]: the padded spectrum quarter of the coefficients, transposed to
  // (hy, hx), real: the spectrum is (-i)^(odd_x + odd_y) times it (parity_transform); empty for
  // a zero kernel. odd_[output][load]: its parities.
  std::vector<std::vector<Field>> spectra_;
  std::vector<std::vector<std::array<bool, 2>>> odd_;
  std::unique_ptr<Transforms> transforms_;
};

}  // namespace coatfft
