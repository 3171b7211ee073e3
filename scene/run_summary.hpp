#pragma once
// The keys of summary.json that every run of a scene reports (docs/scene_format.md), from the
// scene, the operator's report and a few numbers of the fields: shared by the serial run
// (scene/scene_run.hpp) and the distributed one (scene/distributed_run.hpp), whose fields no rank
// holds whole.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "contact/contact_solver.hpp"
#include "convolution/operators/make_operator.hpp"
#include "scene/automatic_method.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// Why a contact on a free boundary that reaches the domain's edge (pressure on a border cell) is
/// refused: the domain truncates it.
inline constexpr const char* domain_edge_refusal =
    "[contact] the contact reaches the domain edge (pressure > 0 on a border cell): the domain is "
    "too small for this contact; enlarge [grid] lx and ly (and nx, ny to keep the cell size) or "
    "lower the load";

/// The numbers of the fields summary.json reports: total_load [N], uz_center and uz_max [m].
struct FieldNumbers {
  double total_load = 0.0, uz_center = 0.0, uz_max = 0.0;
};
/// (field_numbers: scene/row_layout.hpp, for the rows a run holds.)

/// The keys of every run: the method and its report, the body, the grid, the timings, the
/// fields' numbers, the memory estimate, the warnings (not printed), the automatic choice.
nlohmann::json common_summary(const Scene& scene, const std::optional<AutomaticChoice>& automatic,
                              const OperatorReport& report, double apply_seconds, int repeat,
                              const FieldNumbers& fields);

/// The progress stages of every run: "setting up the operator (dcfft)", "applying the operator
/// (5 times)".
std::string setup_stage(const Scene& scene);
std::string applications_stage(int repeat);

/// Refuses --repeat outside 1..max_repeat (scene/resources.hpp).
void check_repeat(int repeat);

/// The contact's keys of summary.json, after common_summary's: the result's numbers (the same on
/// every rank of a distributed solve), its warning, the Hertz solution where one applies (on the
/// homogeneous body, and on the bare substrate and top coating under one load: "hertz_bare").
/// summary.json's "plastic" of `result`, solved under [contact] hardness = `hardness` on `grid`
/// (contact/plastic_report.hpp): hardness, plastic_area, plastic_area_fraction,
/// max_plastic_depth, plastic_volume. Python's ContactResult.plastic is the same object.
nlohmann::json plastic_summary(const ContactResult& result, double hardness, const Grid& grid);

void add_contact_summary(nlohmann::json& summary, const Scene& scene, const ContactResult& result,
                         double solve_seconds);

/// Whether a known-load run reports max_error_vs_hertz: a Hertz load on a homogeneous body's free
/// surface, whose displacement has a closed form.
bool reports_hertz_error(const Scene& scene);

/// The error measure of Spinu (2021), section 5, max |u - u_Hertz| / u_Hertz(0), over the rows
/// [y0, y0 + uz.cols()) of the scene's grid (a distributed run takes the maximum over the ranks).
double hertz_error_rows(const Scene& scene, const Field& uz, std::ptrdiff_t y0);

}  // namespace coatfft::scene
