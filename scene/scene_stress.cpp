#include "scene/scene_stress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "stress/stress_invariants.hpp"
#include "stress/stress_operator.hpp"

namespace coatfft::scene {

namespace {

StressVector at(const PlaneStress& s, std::ptrdiff_t i, std::ptrdiff_t j) {
  return {s[0](i, j), s[1](i, j), s[2](i, j), s[3](i, j), s[4](i, j), s[5](i, j)};
}

// The largest value of f over the planes, with where it is.
struct Peak {
  double value = -INFINITY, x = 0, y = 0, z = 0;
  void take(double v, double xv, double yv, double zv) {
    if (v > value) *this = {v, xv, yv, zv};
  }
  nlohmann::json json(bool with_z = true) const {
    nlohmann::json j{{"value", value}, {"x", x}, {"y", y}};
    if (with_z) j["z"] = z;
    return j;
  }
};

// Appends plane s (6 components, then von Mises) in C order (ny, nx) rows, y slowest.
void append_plane(const PlaneStress& s, std::vector<double>& stress, std::vector<double>& vm) {
  for (const Field& c : s) stress.insert(stress.end(), c.data(), c.data() + c.size());
  for (std::ptrdiff_t j = 0; j < s[0].cols(); ++j)
    for (std::ptrdiff_t i = 0; i < s[0].rows(); ++i) vm.push_back(von_mises(at(s, i, j)));
}

// Appends the row j of plane s to the section arrays: (6, nx), then (nx).
void append_row(const PlaneStress& s, std::ptrdiff_t j, std::vector<double>& section,
                std::vector<double>& vm) {
  for (const Field& c : s)
    for (std::ptrdiff_t i = 0; i < c.rows(); ++i) section.push_back(c(i, j));
  for (std::ptrdiff_t i = 0; i < s[0].rows(); ++i) vm.push_back(von_mises(at(s, i, j)));
}

void check_finite(const PlaneStress& s, double z) {
  for (const Field& c : s)
    COATFFT_REQUIRE(c.allFinite(), "[stress] the stresses at z = ", z,
                    " m are not finite (an overflowing load?)");
}

// The largest von Mises, principal tensile and Tresca stresses of a set of points.
struct Peaks {
  Peak mises, tensile, tresca;
  void take(const StressVector& s, double x, double y, double z) {
    mises.take(von_mises(s), x, y, z);
    tensile.take(principal_stresses(s)[0], x, y, z);
    tresca.take(coatfft::tresca(s), x, y, z);
  }
  void take(const PlaneStress& plane, const Grid& grid, double z) {
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) take(at(plane, i, j), grid.x(i), grid.y(j), z);
  }
};

// "coating 1" (top) ... "substrate": a medium as the scene's sections name it.
std::string medium_name(const LayerStack& body, std::size_t layer) {
  return layer < body.coatings().size() ? detail::concat("coating ", layer + 1) : "substrate";
}

// summary.json's stress.layers: per medium, top first, the maxima over every plane in it (an
// interface's planes count on both of its sides).
nlohmann::json layer_maxima(const LayerStack& body, const Grid& grid, const StressPlanes& planes,
                            const std::vector<PlaneStress>& stress) {
  std::vector<Peaks> per_layer(body.coatings().size() + 1);
  std::vector<bool> seen(per_layer.size(), false);
  for (std::size_t p = 0; p < stress.size(); ++p) {
    const std::size_t layer = body.locate(planes.depths[p], planes.sides[p]).layer;
    per_layer[layer].take(stress[p], grid, planes.depths[p]);
    seen[layer] = true;
  }
  nlohmann::json layers = nlohmann::json::array();
  for (std::size_t l = 0; l < per_layer.size(); ++l) {
    if (!seen[l]) continue;  // a medium no plane reaches (never: each meets an interface plane)
    layers.push_back({{"medium", medium_name(body, l)},
                      {"max_von_mises", per_layer[l].mises.json()},
                      {"max_principal_tensile", per_layer[l].tensile.json()},
                      {"max_tresca", per_layer[l].tresca.json()}});
  }
  return layers;
}

// summary.json's stress.interfaces: the largest shear stress on each interface (continuous
// across it: taken on the side spec.side names).
nlohmann::json interface_shear(const StressSpec& spec, const Grid& grid, const StressPlanes& planes,
                               const std::vector<PlaneStress>& stress) {
  nlohmann::json interfaces = nlohmann::json::array();
  const std::size_t first = spec.depths.size() + std::size_t(spec.nz);
  for (std::size_t p = first; p < stress.size(); ++p) {
    if (planes.sides[p] != spec.side) continue;
    Peak shear;
    const PlaneStress& s = stress[p];
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i)
        shear.take(std::hypot(s[s_xz](i, j), s[s_yz](i, j)), grid.x(i), grid.y(j),
                   planes.depths[p]);
    interfaces.push_back({{"depth", planes.depths[p]}, {"max_shear", shear.json(false)}});
  }
  return interfaces;
}

nlohmann::json alias_warnings(const StressOperator& op) {
  nlohmann::json warnings = nlohmann::json::array();
  for (std::size_t p = 0; p < op.depths().size(); ++p)
    if (op.kernel_reports()[p].alias_capped)
      warnings.push_back(detail::concat("the alias series of the plane at z = ", op.depths()[p],
                                        " m was cut at order ", op.kernel_reports()[p].alias_order,
                                        ": its stresses near the loads' edges are approximate"));
  return warnings;
}

}  // namespace

StressRun compute_stress(const StressSpec& spec, const LayerStack& body, const Grid& grid,
                         const Field& pressure, const Tractions& q, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const StressPlanes planes = stress_planes(spec, body);
  StressOperatorOptions options;
  options.kernel.alpha = spec.alpha;
  options.kernel.threads = threads;
  options.boundary = spec.periodic ? Boundary::periodic : Boundary::free;
  options.sides = planes.sides;
  options.tangential = q.qx || q.qy;
  const std::unique_ptr<StressOperator> op =
      make_stress_operator(grid, body, planes.depths, options);
  const auto apply_start = std::chrono::steady_clock::now();
  std::vector<PlaneStress> stress;
  op->apply(pressure, q.qx ? &*q.qx : nullptr, q.qy ? &*q.qy : nullptr, stress);
  const double apply_seconds = detail::seconds_since(apply_start);
  for (std::size_t p = 0; p < stress.size(); ++p) check_finite(stress[p], planes.depths[p]);

  StressRun run;
  Peaks peaks;  // over the planes asked for, as before the media had their own
  const std::size_t n_requested = spec.depths.size() + std::size_t(spec.nz);
  for (std::size_t p = 0; p < n_requested; ++p) {
    peaks.take(stress[p], grid, planes.depths[p]);
    if (p < spec.depths.size())
      append_plane(stress[p], run.stress, run.von_mises);
    else
      append_row(stress[p], grid.centre_j(), run.section, run.section_von_mises);
  }
  run.summary = {{"warnings", alias_warnings(*op)},
                 {"depths", spec.depths},
                 {"at_interface", spec.side == InterfaceSide::below ? "below" : "above"},
                 {"alpha", spec.periodic ? nlohmann::json() : nlohmann::json(spec.alpha)},
                 {"periodic", spec.periodic},
                 {"max_von_mises", peaks.mises.json()},
                 {"max_principal_tensile", peaks.tensile.json()},
                 {"max_tresca", peaks.tresca.json()},
                 {"layers", layer_maxima(body, grid, planes, stress)},
                 {"interfaces", interface_shear(spec, grid, planes, stress)},
                 {"planes", planes.depths.size()},
                 {"tangential", options.tangential},
                 {"setup_seconds", op->setup_seconds()},
                 {"apply_seconds", apply_seconds},
                 {"seconds", detail::seconds_since(start)}};
  if (spec.section)
    run.summary["section"] = {
        {"y", grid.y(grid.centre_j())}, {"depth_max", spec.depth_max}, {"nz", spec.nz}};
  return run;
}

}  // namespace coatfft::scene
