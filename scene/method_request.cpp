#include "scene/method_request.hpp"

#include <algorithm>
#include <array>
#include <thread>

#include "convolution/fft/planning.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/method.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/parse_name.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"

namespace coatfft::scene {
namespace {

// The value of the key `key` by `parse`, its error naming the key ("... planning = ...").
template <typename Parse>
auto parse_key(const KeyNames& keys, std::string_view key, const std::string& value,
               Parse&& parse) {
  try {
    return parse(value);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(detail::concat(keys.where(key), " = ", e.what()));
  }
}

// Keys that the chosen method would ignore are refused: a user who sets alpha for dcfft believes
// it does something.
void refuse_keys_not_applying(const MethodRequest& r, const KeyNames& keys, bool automatic,
                              Method method) {
  const bool pipeline =
      !automatic && (method == Method::frf_spectral || method == Method::frf_dcfft);
  const std::string quoted = detail::concat(keys.name, " = \"", r.name, "\"");
  for (const auto& [given, key] :
       {std::pair{r.alpha.has_value(), "alpha"}, std::pair{r.g0.has_value(), "g0"},
        std::pair{r.g0_tol.has_value(), "g0_tol"}})
    COATFFT_REQUIRE(pipeline || !given, keys.where(key),
                    ": applies only to the FRF pipelines \"frf-spectral\" and \"frf-dcfft\", not "
                    "to ",
                    quoted, automatic ? " (which chooses them)" : "");
  COATFFT_REQUIRE(automatic || !r.tolerance, keys.where("tolerance"), ": applies only to ",
                  keys.name, " = \"auto\", not to ", quoted);
  for (const auto& [given, key] :
       {std::pair{r.planning.has_value(), "planning"}, std::pair{r.wisdom, "wisdom"}})
    COATFFT_REQUIRE(automatic || method != Method::direct || !given, keys.where(key),
                    ": FFTW settings do not apply to ", quoted, ", which uses no FFT");
}

// A periodic boundary takes the exact periodic operator (convolution/operators/make_operator.hpp,
// docs/theory.md 4.8), which convolves the periodic coefficients as dcfft and frf-split do.
void check_periodic_request(const MethodRequest& r, const KeyNames& keys, MethodSpec& spec) {
  spec.options.boundary = Boundary::periodic;
  if (spec.automatic) {
    COATFFT_REQUIRE(!r.tolerance, keys.where("tolerance"),
                    ": applies only to free boundaries: on a periodic one ", keys.name,
                    " = \"auto\" takes the body's exact method (dcfft or frf-split)");
    spec.automatic = false;
    spec.auto_periodic = true;
    return;
  }
  const Method method = spec.options.method;
  COATFFT_REQUIRE(method == Method::dcfft || method == Method::frf_split, keys.where("name"),
                  " = \"", to_string(method),
                  "\" computes free (non-periodic) surfaces: on a periodic boundary use "
                  "\"frf-split\" (any body), \"dcfft\" (homogeneous) or \"auto\"");
}

}  // namespace

void resolve_periodic_method(MethodSpec& spec, const LayerStack* body) {
  if (spec.auto_periodic) spec.options.method = body ? exact_method(*body) : Method::frf_split;
}

OperatorRequest operator_request(const MethodSpec& spec) {
  OperatorRequest request;
  request.automatic = spec.automatic || spec.auto_periodic;
  request.options = spec.options;
  request.automatic_request.tolerance = spec.tolerance;
  request.automatic_request.max_threads = spec.options.threads;
  request.automatic_request.planning = spec.options.planning;
  return request;
}

MethodSpec method_from_request(const MethodRequest& r, const KeyNames& keys) {
  MethodSpec spec;
  OperatorOptions& o = spec.options;
  spec.automatic = r.name == "auto";
  if (!spec.automatic)
    o.method = parse_key(keys, "name", r.name, [](const std::string& name) {
      try {
        return parse_method(name);
      } catch (const InvalidArgument& e) {
        throw InvalidArgument(detail::concat(e.what(), " or \"auto\""));
      }
    });
  refuse_keys_not_applying(r, keys, spec.automatic, o.method);
  if (spec.automatic) {
    spec.tolerance = r.tolerance.value_or(spec.tolerance);
    COATFFT_REQUIRE(spec.tolerance >= 1e-12 && spec.tolerance <= 0.1, keys.where("tolerance"),
                    " = ", spec.tolerance, " must be in [1e-12, 0.1]");
    // The threads the choice may use: all the machine's, unless the request caps them.
    o.threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, max_threads);
  }
  o.alpha = r.alpha.value_or(o.alpha);
  if (r.g0)
    o.g0 = parse_key(keys, "g0", *r.g0, [](const std::string& name) {
      return detail::parse_name(
          name, std::array{G0Method::regularized, G0Method::quadrature, G0Method::omitted});
    });
  o.g0_tolerance = r.g0_tol.value_or(o.g0_tolerance);
  COATFFT_REQUIRE(o.g0_tolerance > 0 && o.g0_tolerance < 1, keys.where("g0_tol"), " = ",
                  o.g0_tolerance, " must be in (0, 1)");
  if (r.planning) o.planning = parse_key(keys, "planning", *r.planning, parse_planning);
  spec.planning_given = r.planning.has_value();
  const std::int64_t threads = r.threads.value_or(o.threads);
  COATFFT_REQUIRE(threads >= 1 && threads <= max_threads, keys.where("threads"), " = ", threads,
                  " must be in 1..", max_threads);
  o.threads = static_cast<int>(threads);
  if (r.boundary == Boundary::periodic) check_periodic_request(r, keys, spec);
  return spec;
}

}  // namespace coatfft::scene
