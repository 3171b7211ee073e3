#pragma once
// A method as a user asks for it -- the keys of a scene's [method] section, or the keywords of the
// Python module's make_operator -- and the one check of which keys apply to which method and of
// their values, for both front ends (docs/scene_format.md [method], docs/python.md).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "model/operator_plan.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// Each key as given, or empty when it is not given. The keys are the scene's: a front end that
/// spells one otherwise (Python's `method` for `name`) says so in KeyNames.
struct MethodRequest {
  std::string name = "auto";            ///< "auto" or a method's name (convolution/method.hpp)
  std::optional<double> tolerance;      ///< auto only: the operator's error relative to max |u|
  std::optional<double> alpha;          ///< frf-spectral and frf-dcfft only
  std::optional<std::string> g0;        ///< frf-spectral and frf-dcfft only
  std::optional<double> g0_tol;         ///< frf-spectral and frf-dcfft only
  std::optional<std::string> planning;  ///< every method but direct
  std::optional<std::int64_t> threads;  ///< any method; for auto, the most the choice may use
  bool wisdom = false;                  ///< a wisdom file is named: every method but direct
  /// A scene's [grid] boundary, Python's `boundary`: on a periodic one only the exact periodic
  /// operator applies (dcfft, frf-split, or "auto", which takes the body's).
  Boundary boundary = Boundary::free;
};

/// How a front end names a key in its messages.
struct KeyNames {
  /// A key where it was given: "[method] alpha (line 4)" in a scene, "make_operator: alpha".
  std::function<std::string(std::string_view key)> where;
  /// How the front end spells `name` when it quotes the request: "name" (scene), "method".
  std::string name = "name";
};

/// The MethodSpec `request` asks for (its `options` complete but for the grid-dependent checks
/// of check_operator_options). Throws InvalidArgument with one line naming the key for an unknown
/// method, g(0) or planning name; a key that does not apply to the method ("alpha" for dcfft,
/// "tolerance" for a named method, "planning" for direct, ...); a tolerance outside [1e-12, 0.1], a
/// g(0) tolerance outside (0, 1), threads outside 1..max_threads. g0 = "omitted" is accepted here:
/// a scene refuses it on its own ground (its displacements would lose their level). On a periodic
/// boundary also a named method other than dcfft and frf-split, and "tolerance" with "auto"
/// (the automatic choice's error model is of free surfaces; "auto" takes the body's exact method,
/// set by resolve_periodic_method once the body is known).
MethodSpec method_from_request(const MethodRequest& request, const KeyNames& keys);

/// A periodic "auto" (MethodSpec::auto_periodic) resolved to the exact method of `body`
/// (exact_method: dcfft for a homogeneous body, frf-split otherwise), or frf-split for a body
/// given by its FRF alone (null `body`). Other specs are left as they are.
void resolve_periodic_method(MethodSpec& spec, const LayerStack* body);

/// The library's operator request (model/operator_plan.hpp) of a checked spec, the same for a
/// scene's [method] and Python's keywords: "auto" (free or periodic) with its tolerance, and
/// the spec's options (a named method's; for "auto" its threads cap and planning). The caller
/// adds what it knows of the run: applications, reference loads, first_in_process, distributed.
OperatorRequest operator_request(const MethodSpec& spec);

}  // namespace coatfft::scene
