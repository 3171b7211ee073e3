#pragma once
// The automatic method choice (docs/auto.md): a tolerance instead of a method. For a grid, a body
// and the number of applications a computation will make, every method of make_operator gets a
// predicted error (relative to max |u|, against the exact convolution of the cell-wise-constant
// pressure) and a predicted cost (model/cost_model.hpp); among those within the tolerance the
// cheapest is chosen, a single application weighing setup, a contact solve of many applications
// weighing the application.
#include <string>
#include <vector>

#include "../convolution/operators/make_operator.hpp"
#include "../core/grid.hpp"
#include "../frf/frf.hpp"
#include "../layers/layer_stack.hpp"

namespace coatfft {

struct AutoRequest {
  /// Largest admissible operator error, relative to max |u|, in [1e-12, 0.1].
  double tolerance = 1e-4;
  /// Applications the computation will make (1 for a known pressure; a contact solve's
  /// expected iterations), >= 1.
  double applications = 1.0;
  /// Threads the choice may use, in 1..max_threads; it picks fewer where they do not pay.
  int max_threads = 1;
  Planning planning = Planning::estimate;
  /// The operator is the first FFTW plan of its process (a command-line run): the methods that
  /// use FFTW then also pay fftw_start_seconds (model/cost_model.hpp).
  bool first_in_process = false;  /// The operator runs on the ranks of a communicator
                                  /// (distributed/make_distributed_operator.hpp):
  /// only dcfft and frf-split are candidates, and the lattice pipelines' error is not predicted.
  bool distributed = false;
};

/// One method as the model sees it.
struct MethodCandidate {
  Method method = Method::dcfft;
  double predicted_error = 0.0;  ///< relative to max |u|; +inf where it does not apply
  double setup_seconds = 0.0;    ///< predicted
  double apply_seconds = 0.0;    ///< predicted, one application
  double total_seconds = 0.0;    ///< setup + applications x apply
  bool admissible = false;       ///< applies to the body and is within the tolerance
  std::string note;              ///< why (not), for reports
};

struct MethodChoice {
  OperatorOptions options;                  ///< what make_operator is given
  MethodCandidate chosen;                   ///< its prediction
  std::vector<MethodCandidate> candidates;  ///< every method, in the order of all_methods
  std::string why;                          ///< one sentence, for reports
};

/// The cheapest admissible method for `body` on `grid` (Love's methods need `body` homogeneous;
/// the FRF methods use make_frf(body)). Throws InvalidArgument for a bad request.
MethodChoice choose_method(const Grid& grid, const LayerStack& body, const AutoRequest& request);

/// The same for a body given by its FRF alone (Love's methods do not apply).
MethodChoice choose_method(const Grid& grid, const Frf& frf, const AutoRequest& request);

/// The model's prediction for a method named with its `options` (what `coatfft check` reports
/// for a named method): costs, and the error where the model has one (Love's methods,
/// frf-split; +inf for the lattice pipelines, whose error convolution/operators/pipeline_error.hpp
/// predicts). Love's methods on a layered body are reported not admissible.
MethodCandidate predict_method(const Grid& grid, const LayerStack& body,
                               const OperatorOptions& options, double applications,
                               bool first_in_process = false);
MethodCandidate predict_method(const Grid& grid, const Frf& frf, const OperatorOptions& options,
                               double applications, bool first_in_process = false);

/// The alpha auto gives frf-spectral and frf-dcfft: 2, rounded up so that the extended lattice
/// alpha n is a fast FFT length (2^a 3^b 5^c 7^d, as DC-FFT's padding) where one alpha can make
/// both axes so: square grids (127^2: alpha = 256/127).
double lattice_alpha(const Grid& grid);

/// The split kernel's tolerance that keeps frf-split's operator error within `tolerance`, and
/// the error it is predicted to leave (docs/auto.md, section 1: at most 0.05 x the kernel's
/// tolerance in bench_auto_calibration's cases).
double split_tolerance_for(double tolerance);
double predicted_split_error(double split_tolerance);

}  // namespace coatfft
