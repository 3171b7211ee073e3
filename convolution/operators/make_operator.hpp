#pragma once
// The one operator factory: a grid, a body (a LayerStack, or any Frf) and OperatorOptions in; the
// SurfaceOperator that computes the surface displacement and a report of what was built out; and
// the tangential operator (the 3 x 3 surface response under pressure and tractions). The scene
// layer, the benchmarks, the validation tables and the tests all build operators here; nothing
// else maps a Method to a class. Each kind's memory estimate is in operator_memory.hpp.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "../../core/grid.hpp"
#include "../../frf/frf.hpp"
#include "../../layers/layer_stack.hpp"
#include "../fft/planning.hpp"
#include "../kernels/g0.hpp"
#include "../kernels/influence_kernel.hpp"
#include "../kernels/split_frf_kernel.hpp"
#include "../kernels/traction_kernels.hpp"
#include "../method.hpp"
#include "cerruti_operator.hpp"
#include "surface_operator.hpp"

namespace coatfft {

/// How to build an operator. The defaults are those of a scene file without [method] keys.
struct OperatorOptions {
  Method method = Method::dcfft;
  /// Boundary::periodic builds the exact periodic operator of the body's FRF
  /// (convolution/operators/periodic_operator.hpp) for method dcfft or frf-split (both convolve the
  /// same periodic coefficients); the other methods compute free surfaces only.
  Boundary boundary = Boundary::free;
  /// Domain extension ratio of frf-spectral (>= 1) and frf-dcfft (>= 2); alpha nx and alpha ny
  /// must be whole numbers. Ignored by the other methods.
  double alpha = 2.0;
  /// g(0) of frf-spectral and frf-dcfft (docs/theory.md section 3): how, and to which relative
  /// tolerance in (0, 1). G0Method::omitted builds them without g(0) (displacements then carry an
  /// unknown constant offset: enough for a load-controlled contact).
  G0Method g0 = G0Method::regularized;
  double g0_tolerance = 1e-10;
  /// FFTW planner effort of the operator's transforms.
  Planning planning = Planning::estimate;
  /// Threads of the setup and of apply(), in 1..max_threads (core/threads.hpp); the results do
  /// not depend on it.
  int threads = 1;
  /// Options of the frf-split kernel (its `threads` is replaced by `threads` above).
  SplitKernelOptions split;
};

/// What make_operator built, for reports (summary.json, benchmarks).
struct OperatorReport {
  Method method = Method::dcfft;  ///< the method that runs
  std::string frf;                ///< Frf::name() of the body's FRF; empty for Love's methods
  double setup_seconds = 0.0;     ///< wall time of make_operator (kernel, g(0), plans) [s]
  /// Of which the influence kernel (Love's, the split kernel, frf-dcfft's coefficients or sampled
  /// spectrum) [s]; 0 for frf-spectral, whose FRF sampling is part of the operator's setup.
  double kernel_seconds = 0.0;
  std::ptrdiff_t fft_nx = 0;  ///< transform lengths of apply() (padded or extended lattice)
  std::ptrdiff_t fft_ny = 0;
  std::optional<double> alpha;             ///< frf-spectral, frf-dcfft
  std::optional<G0Result> g0;              ///< frf-spectral, frf-dcfft
  std::optional<SplitKernelReport> split;  ///< frf-split
  /// frf-spectral, frf-dcfft: their predicted error max |u - u_exact| / max |u_exact| under a
  /// reference Hertz load, from predicted_pipeline_error with the body's FRF (docs/theory.md 4.6;
  /// convolution/operators/pipeline_error.hpp): a periodisation error that falls with alpha, not
  /// with N. Its computation is part of setup_seconds.
  std::optional<double> predicted_error;
};

struct BuiltOperator {
  std::unique_ptr<SurfaceOperator> op;
  OperatorReport report;
};

/// The method that is exact on any cells for `body`: dcfft (Love's closed-form coefficients) for
/// a homogeneous body, frf-split otherwise (and for a body given by its FRF alone). These are
/// also the two methods a periodic boundary takes.
Method exact_method(const LayerStack& body);

/// Throws InvalidArgument unless `method` can be used on `body`'s free surface: Love's coefficients
/// (dcfft, direct) exist for a homogeneous body only. make_operator checks it; so does a caller
/// that builds the operator otherwise (the distributed run).
void check_love_body(const LayerStack& body, Method method);

/// Throws InvalidArgument, with a message naming the option ("alpha = 1.5: ..."), unless
/// `options` can be used on `grid` (alpha, tolerances, threads, a method the boundary allows).
/// make_operator calls it first; a reader of user input calls it to refuse bad input before any
/// work starts. Direct summation is refused beyond max_direct_cells.
void check_operator_options(const Grid& grid, const OperatorOptions& options);

/// Direct summation costs (nx ny)^2 operations per application: hours beyond this many cells.
inline constexpr std::ptrdiff_t max_direct_cells = 1 << 16;

/// The operator of `options.method` for `body` on `grid`. Throws InvalidArgument for bad options
/// and for a method that cannot handle the body (direct and dcfft need a homogeneous body).
BuiltOperator make_operator(const Grid& grid, const LayerStack& body,
                            const OperatorOptions& options = {});

/// The same for a body given by its FRF alone (a user-supplied Frf): every FRF method applies;
/// direct and dcfft are refused (Love's coefficients need the material, not an FRF).
BuiltOperator make_operator(const Grid& grid, const Frf& frf, const OperatorOptions& options);

/// DC-FFT (or, with Method::direct in `options.method`, direct summation) of any influence
/// kernel: the operator for coefficients made outside the factory. Only `method`, `planning`
/// and `threads` of `options` are used; the operator reports the kernel's method.
BuiltOperator make_operator(const InfluenceKernel& kernel, const OperatorOptions& options = {});

/// How to build the tangential operator (CerrutiOperator).
struct TangentialOptions {
  /// FFTW planner effort of its transforms.
  Planning planning = Planning::estimate;
  /// Threads of a layered body's remainder lattices, in 1..max_threads (replaces
  /// kernel.lattice.threads); the results do not depend on it.
  int threads = 1;
  /// The kernels' options (convolution/kernels/traction_kernels.hpp).
  TractionKernelOptions kernel;
  /// Boundary::periodic: the surface repeats over the grid's domain (nx, ny even):
  /// periodic_traction_kernels, with `kernel.tolerance` as their tolerance (at most 1e-6) and
  /// `threads`.
  Boundary boundary = Boundary::free;
};

/// What make_tangential_operator built.
struct BuiltTangentialOperator {
  std::unique_ptr<CerrutiOperator> op;
  TractionKernelReport report;
  double setup_seconds = 0.0;  ///< wall time of the kernels and the plans [s]
};

/// The surface displacements (u_x, u_y, u_z) of `body` under a pressure and tangential tractions
/// on `grid`: closed-form cell coefficients for a homogeneous body, the split of docs/theory.md
/// 2.9 for a bonded stack; on a periodic surface, the periodic kernels (zero-mean
/// displacements). Throws InvalidArgument for a frictionless interface (no finite
/// in-plane compliance), for threads out of range and where the remainders' lattice would exceed
/// options.kernel.lattice.max_evaluations. Its memory: estimated_cerruti_bytes.
BuiltTangentialOperator make_tangential_operator(const Grid& grid, const LayerStack& body,
                                                 const TangentialOptions& options = {});

}  // namespace coatfft
