#include "scene/scene_stress.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "core/detail/huge_pages.hpp"
#include "core/detail/timing.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "stress/detail/closed_form_screen.hpp"
#include "stress/stress_invariants.hpp"
#include "stress/stress_operator.hpp"

namespace coatfft::scene {

namespace {

StressVector at(const PlaneStress& s, std::ptrdiff_t i, std::ptrdiff_t j) {
  return {s[0](i, j), s[1](i, j), s[2](i, j), s[3](i, j), s[4](i, j), s[5](i, j)};
}

// The largest value of a quantity over a set of points, with where it is: (x, y, z) and the
// medium (LayerStack layer index) of the plane it lies on.
struct Peak {
  double value = -INFINITY, x = 0, y = 0, z = 0;
  std::size_t layer = 0;
  void take(double v, double xv, double yv, double zv, std::size_t l) {
    if (v > value) *this = {v, xv, yv, zv, l};
  }
  void take(const Peak& other) {
    if (other.value > value) *this = other;
  }
  nlohmann::json json(bool with_z = true) const {
    nlohmann::json j{{"value", value}, {"x", x}, {"y", y}};
    if (with_z) j["z"] = z;
    return j;
  }
};

// Appends the rows j0 .. j1 - 1 of plane s's 6 components, each in C order (rows, nx), y
// slowest: a whole plane (ny, nx) or the section's one row (nx).
void append_components(const PlaneStress& s, std::ptrdiff_t j0, std::ptrdiff_t j1,
                       std::vector<double>& out) {
  // A Field is column-major (x fastest): rows j0 .. j1 - 1 are one run of values, in C order.
  for (const Field& c : s)
    out.insert(out.end(), c.data() + j0 * c.rows(), c.data() + j1 * c.rows());
}

// The largest von Mises, principal tensile and Tresca stresses of a set of points.
struct Peaks {
  Peak mises, tensile, tresca;
  void take(const Peaks& other) {
    mises.take(other.mises);
    tensile.take(other.tensile);
    tresca.take(other.tresca);
  }
};

// `v` with room for `n` values, allocated on huge pages where the kernel agrees, before their
// first touch (core/detail/huge_pages.hpp: 4 KiB pages' faults cost about what the values' work
// does).
void reserve_advised(std::vector<double>& v, std::size_t n) {
  v.reserve(n);
  detail::advise_huge_pages(v.data(), n * sizeof(double));
}

// The maxima of the rows j0 .. j1 - 1 of plane s at depth z in medium `layer`, in the order of
// the cells (the first of equal values is the one reported), with principal_stresses' values;
// their von Mises stresses appended to `von_mises_out` (C order, y slowest) when it is given.
// The closed forms screen the cells (docs/stress.md, "Summary maxima"): only those within their
// error of the largest values get the iterative solver. Refuses a plane with a value that is not
// finite.
Peaks plane_peaks(const PlaneStress& s, const Grid& grid, std::ptrdiff_t j0, std::ptrdiff_t j1,
                  double z, std::size_t layer, std::vector<double>* von_mises_out) {
  const std::ptrdiff_t nx = grid.nx();
  const auto cells = static_cast<std::size_t>(nx * (j1 - j0));
  double* mises_out = nullptr;
  if (von_mises_out) {
    von_mises_out->resize(von_mises_out->size() + cells);
    mises_out = von_mises_out->data() + von_mises_out->size() - cells;
  }
  const std::ptrdiff_t offset = j0 * nx;
  const detail::ClosedFormScreen screen =
      detail::screen_cells({s[0].data() + offset, s[1].data() + offset, s[2].data() + offset,
                            s[3].data() + offset, s[4].data() + offset, s[5].data() + offset},
                           cells, mises_out);
  COATFFT_REQUIRE(screen.finite, "[stress] the stresses at z = ", z,
                  " m are not finite (an overflowing load?)");
  // Cell k of the rows: (k mod nx, j0 + k / nx).
  const auto i_of = [nx](std::size_t k) { return static_cast<std::ptrdiff_t>(k) % nx; };
  const auto j_of = [nx, j0](std::size_t k) { return j0 + static_cast<std::ptrdiff_t>(k) / nx; };
  Peaks peaks;
  const std::size_t m = screen.mises_cell;
  peaks.mises = {screen.mises, grid.x(i_of(m)), grid.y(j_of(m)), z, layer};
  for (const std::size_t k : screen.candidates) {
    const std::ptrdiff_t i = i_of(k), j = j_of(k);
    const std::array<double, 3> principal = principal_stresses(at(s, i, j));
    peaks.tensile.take(principal[0], grid.x(i), grid.y(j), z, layer);
    peaks.tresca.take(0.5 * (principal[0] - principal[2]), grid.x(i), grid.y(j), z,
                      layer);  // coatfft::tresca
  }
  return peaks;
}

// "coating 1" (top) ... "substrate": a medium as the scene's sections name it.
std::string medium_name(const LayerStack& body, std::size_t layer) {
  return layer < body.coatings().size() ? detail::concat("coating ", layer + 1) : "substrate";
}

// summary.json's maxima: per medium (stress.layers, top first) those of the planes in it (an
// interface's planes count on the side each is computed on), and overall those of the media, so
// that the overall maxima are the largest of the media's and lie on the same planes.
void add_maxima(nlohmann::json& summary, const LayerStack& body, const std::vector<Peaks>& planes) {
  std::vector<std::optional<Peaks>> media(body.coatings().size() + 1);
  for (const Peaks& plane : planes) {
    std::optional<Peaks>& medium = media[plane.mises.layer];
    if (!medium) medium = Peaks{};
    medium->take(plane);
  }
  Peaks overall;
  nlohmann::json layers = nlohmann::json::array();
  for (std::size_t l = 0; l < media.size(); ++l) {
    if (!media[l]) continue;  // a medium no plane reaches (never: each meets an interface plane)
    layers.push_back({{"medium", medium_name(body, l)},
                      {"max_von_mises", media[l]->mises.json()},
                      {"max_principal_tensile", media[l]->tensile.json()},
                      {"max_tresca", media[l]->tresca.json()}});
    overall.take(*media[l]);
  }
  const auto located = [&](const Peak& peak) {
    nlohmann::json j = peak.json();
    j["medium"] = medium_name(body, peak.layer);
    return j;
  };
  summary["max_von_mises"] = located(overall.mises);
  summary["max_principal_tensile"] = located(overall.tensile);
  summary["max_tresca"] = located(overall.tresca);
  summary["layers"] = layers;
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
        shear.take(std::hypot(s[s_xz](i, j), s[s_yz](i, j)), grid.x(i), grid.y(j), planes.depths[p],
                   0);
    interfaces.push_back({{"depth", planes.depths[p]}, {"max_shear", shear.json(false)}});
  }
  return interfaces;
}

// The planes in the arrays of `run` that `arrays` asks for, each checked finite: the depths'
// (whole), the section's (its row y = y_centre), the interfaces' (whole, above then below each);
// their maxima over the points written, one per plane, each plane reported to `progress`.
std::vector<Peaks> write_planes(const StressSpec& spec, const LayerStack& body, const Grid& grid,
                                const StressPlanes& planes, const std::vector<PlaneStress>& stress,
                                const StressArrays& arrays, StressRun& run,
                                ProgressObserver& progress) {
  const std::size_t n_depths = spec.depths.size(), n_requested = n_depths + std::size_t(spec.nz);
  run.depth_planes = n_depths;
  run.section_rows = std::size_t(spec.nz);
  run.interface_count = (stress.size() - n_requested) / 2;
  // Per kind of plane (the depths', the section's rows, the interfaces' sides): its arrays, null
  // where not asked for, and the values each holds, reserved at once (growing them would copy
  // each several times).
  struct Kind {
    std::vector<double>*components, *von_mises;
    std::size_t values;
  };
  const auto plane = static_cast<std::size_t>(grid.nb_cells());
  const std::array<Kind, 3> kinds{
      {{arrays.stress ? &run.stress : nullptr, arrays.von_mises ? &run.von_mises : nullptr,
        n_depths * plane},
       {arrays.section ? &run.section : nullptr,
        arrays.section_von_mises ? &run.section_von_mises : nullptr,
        run.section_rows * std::size_t(grid.nx())},
       {arrays.interfaces ? &run.interfaces : nullptr,
        arrays.interfaces_von_mises ? &run.interfaces_von_mises : nullptr,
        2 * run.interface_count * plane}}};
  for (const Kind& k : kinds) {
    if (k.components) reserve_advised(*k.components, 6 * k.values);
    if (k.von_mises) reserve_advised(*k.von_mises, k.values);
  }
  std::vector<Peaks> peaks;
  for (std::size_t p = 0; p < stress.size(); ++p) {
    progress.step(detail::concat("maxima of plane ", p + 1, " of ", stress.size()));
    check_interrupt();  // keeps the progress line going, and Ctrl-C prompt
    const double z = planes.depths[p];
    const std::size_t layer = body.locate(z, planes.sides[p]).layer;
    const bool row = p >= n_depths && p < n_requested;
    const std::ptrdiff_t j0 = row ? grid.centre_j() : 0, j1 = row ? j0 + 1 : grid.ny();
    const Kind& kind = kinds[p < n_depths ? 0 : row ? 1 : 2];
    peaks.push_back(plane_peaks(stress[p], grid, j0, j1, z, layer, kind.von_mises));
    if (kind.components) append_components(stress[p], j0, j1, *kind.components);
  }
  return peaks;
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
                         const Field& pressure, const Tractions& q, int threads,
                         ProgressObserver& progress, const StressArrays& arrays) {
  const auto start = std::chrono::steady_clock::now();
  const StressPlanes planes = stress_planes(spec, body);
  StressOperatorOptions options;
  options.kernel.alpha = spec.alpha;
  options.kernel.threads = threads;
  options.boundary = spec.boundary;
  options.sides = planes.sides;
  options.tangential = q.qx || q.qy;
  options.on_planes = [&progress](std::size_t first, std::size_t count, std::size_t n) {
    progress.step(count == 1 ? detail::concat("kernels of plane ", first + 1, " of ", n)
                             : detail::concat("kernels of planes ", first + 1, " to ",
                                              first + count, " of ", n));
  };
  const std::unique_ptr<StressOperator> op =
      make_stress_operator(grid, body, planes.depths, options);
  progress.step("convolutions");
  const auto apply_start = std::chrono::steady_clock::now();
  std::vector<PlaneStress> stress;
  op->apply(pressure, q.qx ? &*q.qx : nullptr, q.qy ? &*q.qy : nullptr, stress);
  const double apply_seconds = detail::seconds_since(apply_start);

  StressRun run;
  const auto maxima_start = std::chrono::steady_clock::now();
  const std::vector<Peaks> peaks =
      write_planes(spec, body, grid, planes, stress, arrays, run, progress);
  const double maxima_seconds = detail::seconds_since(maxima_start);
  run.summary = {{"warnings", alias_warnings(*op)},
                 {"depths", spec.depths},
                 {"at_interface", spec.side == InterfaceSide::below ? "below" : "above"},
                 {"alpha", spec.boundary == Boundary::periodic ? nlohmann::json()
                                                               : nlohmann::json(spec.alpha)},
                 {"periodic", spec.boundary == Boundary::periodic},
                 {"interfaces", interface_shear(spec, grid, planes, stress)},
                 {"planes", planes.depths.size()},
                 {"tangential", options.tangential},
                 {"setup_seconds", op->setup_seconds()},
                 {"apply_seconds", apply_seconds},
                 {"maxima_seconds", maxima_seconds}};
  add_maxima(run.summary, body, peaks);
  run.summary["seconds"] = detail::seconds_since(start);
  if (spec.section)
    run.summary["section"] = {
        {"y", grid.y(grid.centre_j())}, {"depth_max", spec.depth_max}, {"nz", spec.nz}};
  return run;
}

}  // namespace coatfft::scene
