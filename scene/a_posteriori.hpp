#pragma once
// A cheap a-posteriori check of a computed displacement (summary.json "a_posteriori"): for an
// axisymmetric analytic load (hertz, uniform_disk) centred on the domain, the displacement of
// the cell nearest the load's centre against the continuous Hankel reference of the scene's own
// (unreduced) body, hankel_displacement (validation/). It costs a few one-dimensional integrals.
// What it measures is the whole error at that point: the operator's, a reduced body's and the
// piecewise-constant load's (docs/auto.md, section 4).
#include <nlohmann/json.hpp>

#include "core/types.hpp"
#include "scene/scene.hpp"

namespace coatfft::scene {

/// {"error": |u - u_ref| / max |u| at the centre cell, "measure": what was compared}, or
/// {"error": null, "measure": why none} for loads without a reference (files, contacts) and for a
/// coating so much thinner than the load that the reference would exceed reduce_body's limit of
/// that work (accurate_work_limit, model/body_reduction.hpp).
nlohmann::json a_posteriori_check(const Scene& scene, const Field& uz);

/// The same from the two numbers it reads: uz at the centre cell (Grid::centre_i, centre_j) and
/// max |uz| [m] (a distributed run's, gathered over the ranks).
nlohmann::json a_posteriori_check(const Scene& scene, double uz_at_centre, double max_abs_uz);

}  // namespace coatfft::scene
