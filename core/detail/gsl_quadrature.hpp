#pragma once
// Adaptive 1-D quadrature by GSL's QUADPACK routines (Piessens et al. 1983), for the library's
// integrals (g(0), the Hankel-transform reference). GSL's default error handler aborts the
// process; while any integral of coatfft runs it is switched off (GslHandlerOff) and the routines'
// status codes are returned to the caller instead.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cstddef>
#include <functional>
#include <memory>

namespace coatfft::detail {

/// Switches GSL's process-global error handler off for its lifetime. A reference count under a
/// mutex lets concurrent integrals overlap: the first one in saves the caller's handler, the last
/// one out restores it.
class GslHandlerOff {
 public:
  GslHandlerOff();
  ~GslHandlerOff();
  GslHandlerOff(const GslHandlerOff&) = delete;
  GslHandlerOff& operator=(const GslHandlerOff&) = delete;
};

struct GslWorkspaceDeleter {
  void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
/// An owned gsl_integration_workspace of `intervals` subintervals.
using GslWorkspace = std::unique_ptr<gsl_integration_workspace, GslWorkspaceDeleter>;
GslWorkspace make_gsl_workspace(std::size_t intervals);

/// A gsl_function that calls `f`, for GSL routines without a wrapper here (qagiu, qawf, ...);
/// `f` must outlive its use.
gsl_function as_gsl_function(const std::function<double(double)>& f);

/// A GSL integral: value, QUADPACK's error estimate and GSL's status (GSL_SUCCESS, or e.g.
/// GSL_EROUND when rounding stops the refinement, GSL_EMAXITER when the workspace is full).
struct GslIntegral {
  double value = 0.0;
  double error = 0.0;
  int status = GSL_SUCCESS;
};

/// gsl_integration_qag of f over [a, b] with Gauss-Kronrod rule `key` (GSL_INTEG_GAUSS15 ... 61)
/// to max(epsabs, epsrel |I|), using at most the workspace's size of subintervals. The rule's
/// nodes are interior: f is never called at a or b. Throws coatfft::Error where GSL computed no
/// result (bad tolerance or arguments); other statuses are returned with the estimate.
GslIntegral gsl_qag(const std::function<double(double)>& f, double a, double b, double epsabs,
                    double epsrel, int key, gsl_integration_workspace* ws);

/// gsl_integration_qags (21-point Gauss-Kronrod with Wynn's epsilon extrapolation): for
/// integrable end-point singularities such as log or inverse square root. Errors as gsl_qag.
GslIntegral gsl_qags(const std::function<double(double)>& f, double a, double b, double epsabs,
                     double epsrel, gsl_integration_workspace* ws);

}  // namespace coatfft::detail
