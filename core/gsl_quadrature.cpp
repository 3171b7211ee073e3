#include "core/detail/gsl_quadrature.hpp"

#include <mutex>

#include "core/error.hpp"

namespace coatfft::detail {
namespace {

std::mutex& handler_mutex() {
  static std::mutex m;
  return m;
}
int& handler_count() {
  static int n = 0;
  return n;
}
gsl_error_handler_t*& previous_handler() {
  static gsl_error_handler_t* handler = nullptr;
  return handler;
}

double call(double x, void* params) {
  return (*static_cast<const std::function<double(double)>*>(params))(x);
}

// The statuses after which GSL computed no result at all (bad arguments): a programming error of
// the caller, not a quadrature that fell short of its tolerance.
GslIntegral checked(GslIntegral r, const char* routine, double a, double b) {
  if (r.status == GSL_EBADTOL || r.status == GSL_EINVAL || r.status == GSL_ENOMEM)
    throw Error(detail::concat(routine, " on [", a, ", ", b, "]: ", gsl_strerror(r.status)));
  return r;
}

}  // namespace

gsl_function as_gsl_function(const std::function<double(double)>& f) {
  return gsl_function{&call, const_cast<std::function<double(double)>*>(&f)};
}

GslHandlerOff::GslHandlerOff() {
  const std::lock_guard<std::mutex> lock(handler_mutex());
  if (handler_count()++ == 0) previous_handler() = gsl_set_error_handler_off();
}

GslHandlerOff::~GslHandlerOff() {
  const std::lock_guard<std::mutex> lock(handler_mutex());
  if (--handler_count() == 0) gsl_set_error_handler(previous_handler());
}

GslWorkspace make_gsl_workspace(std::size_t intervals) {
  return GslWorkspace(gsl_integration_workspace_alloc(intervals));
}

GslIntegral gsl_qag(const std::function<double(double)>& f, double a, double b, double epsabs,
                    double epsrel, int key, gsl_integration_workspace* ws) {
  const GslHandlerOff off;
  gsl_function gf = as_gsl_function(f);
  GslIntegral r;
  r.status = gsl_integration_qag(&gf, a, b, epsabs, epsrel, ws->limit, key, ws, &r.value, &r.error);
  return checked(r, "gsl_integration_qag", a, b);
}

GslIntegral gsl_qags(const std::function<double(double)>& f, double a, double b, double epsabs,
                     double epsrel, gsl_integration_workspace* ws) {
  const GslHandlerOff off;
  gsl_function gf = as_gsl_function(f);
  GslIntegral r;
  r.status = gsl_integration_qags(&gf, a, b, epsabs, epsrel, ws->limit, ws, &r.value, &r.error);
  return checked(r, "gsl_integration_qags", a, b);
}

}  // namespace coatfft::detail
