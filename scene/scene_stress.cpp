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

}  // namespace

StressRun compute_stress(const StressSpec& spec, const LayerStack& body, const Grid& grid,
                         const Field& pressure, const Tractions& q, int threads) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> depths = stress_plane_depths(spec, body);
  StressOperatorOptions options;
  options.kernel.alpha = spec.alpha;
  options.kernel.threads = threads;
  options.side = spec.side;
  options.tangential = q.qx || q.qy;
  const std::unique_ptr<StressOperator> op = make_stress_operator(grid, body, depths, options);
  const auto apply_start = std::chrono::steady_clock::now();
  std::vector<PlaneStress> planes;
  op->apply(pressure, q.qx ? &*q.qx : nullptr, q.qy ? &*q.qy : nullptr, planes);
  const double apply_seconds = detail::seconds_since(apply_start);

  StressRun run;
  Peak mises, tensile;
  const std::size_t n_requested = spec.depths.size() + std::size_t(spec.nz);
  for (std::size_t p = 0; p < n_requested; ++p) {
    check_finite(planes[p], depths[p]);
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i) {
        const StressVector s = at(planes[p], i, j);
        mises.take(von_mises(s), grid.x(i), grid.y(j), depths[p]);
        tensile.take(principal_stresses(s)[0], grid.x(i), grid.y(j), depths[p]);
      }
    if (p < spec.depths.size())
      append_plane(planes[p], run.stress, run.von_mises);
    else
      append_row(planes[p], grid.centre_j(), run.section, run.section_von_mises);
  }
  nlohmann::json interfaces = nlohmann::json::array();
  for (std::size_t p = n_requested; p < depths.size(); ++p) {
    check_finite(planes[p], depths[p]);
    Peak shear;
    const PlaneStress& s = planes[p];
    for (std::ptrdiff_t j = 0; j < grid.ny(); ++j)
      for (std::ptrdiff_t i = 0; i < grid.nx(); ++i)
        shear.take(std::hypot(s[s_xz](i, j), s[s_yz](i, j)), grid.x(i), grid.y(j), depths[p]);
    interfaces.push_back({{"depth", depths[p]}, {"max_shear", shear.json(false)}});
  }
  nlohmann::json warnings = nlohmann::json::array();
  for (std::size_t p = 0; p < depths.size(); ++p)
    if (op->kernel_reports()[p].alias_capped)
      warnings.push_back(detail::concat("the alias series of the plane at z = ", depths[p],
                                        " m was cut at order ", op->kernel_reports()[p].alias_order,
                                        ": its stresses near the loads' edges are approximate"));
  run.summary = {{"warnings", warnings},
                 {"depths", spec.depths},
                 {"at_interface", spec.side == InterfaceSide::below ? "below" : "above"},
                 {"alpha", spec.alpha},
                 {"max_von_mises", mises.json()},
                 {"max_principal_tensile", tensile.json()},
                 {"interfaces", interfaces},
                 {"planes", depths.size()},
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
