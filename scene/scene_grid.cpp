#include "scene/detail/scene_grid.hpp"

#include <toml++/toml.h>

#include "core/error.hpp"
#include "model/grid_refinement.hpp"
#include "scene/detail/scene_loads.hpp"
#include "scene/detail/section_reader.hpp"
#include "surfaces/detrend.hpp"
#include "topography/topography.hpp"

namespace coatfft::scene {

std::optional<SceneTopography> read_scene_topography(const toml::table& root,
                                                     const std::filesystem::path& scene_dir,
                                                     std::optional<double> max_memory) {
  if (!root.contains("contact")) return std::nullopt;
  SectionReader reader(section(root, "contact", true), "contact");
  if (!reader.has("topography")) return std::nullopt;
  return in_section("contact", [&] {
    // The keys' own mistakes first, before the file is read.
    COATFFT_REQUIRE(!reader.has("indenter"), reader.where("topography"),
                    " is pressed by a rigid flat: give it or an indenter, not both");
    detrend_from_name(reader.choice("detrend", "none", {"none", "mean", "plane"}),
                      reader.where("detrend"));
    SceneTopography t;
    t.file = reader.string("topography");
    if (t.file.is_relative()) t.file = scene_dir / t.file;
    topography::ReadOptions options;
    options.unit = reader.string("unit", "");
    options.missing = topography::missing_points_from_name(
        reader.choice("missing", "refuse", {"refuse", "fill"}), reader.where("missing"));
    options.max_memory = max_memory;
    t.map = topography::read_topography(t.file, options);
    return t;
  });
}

namespace {

// [grid] on a measured topography: the section and its nx, ny, lx, ly are optional (the file's
// unless given, checked against it), the boundary the file's periodic flag unless given.
GridSection read_topography_grid(SectionReader& reader, const SceneTopography& t) {
  COATFFT_REQUIRE(!reader.has("refine"), reader.where("refine"),
                  ": a measured topography's grid is its own (nx, ny of the file)");
  const auto integer = [&](const char* key) {
    return reader.has(key) ? std::optional(reader.integer(key)) : std::nullopt;
  };
  const auto number = [&](const char* key) {
    return reader.has(key) ? std::optional(reader.number(key)) : std::nullopt;
  };
  const TopographyGrid keys =
      topography_grid_keys(t, integer("nx"), integer("ny"), number("lx"), number("ly"));
  const char* file_boundary = t.map.periodic.value_or(false) ? "periodic" : "free";
  GridSection g{keys.lx,      keys.ly,        std::nullopt,
                std::nullopt, Boundary::free, reader.integer("pad", 0)};
  g.boundary = parse_boundary(reader.choice("boundary", file_boundary, {"free", "periodic"}));
  COATFFT_REQUIRE(g.boundary != Boundary::periodic || (keys.nx % 2 == 0 && keys.ny % 2 == 0),
                  "boundary = \"periodic\" needs even nx and ny: the topography has nx = ", keys.nx,
                  ", ny = ", keys.ny, " (boundary = \"free\" takes any)");
  // The map and `pad` cells of out-of-reach gap on each side, at the map's spacing.
  const std::int64_t nx = keys.nx + 2 * g.pad, ny = keys.ny + 2 * g.pad;
  COATFFT_REQUIRE(g.pad >= 0 && nx <= Grid::max_cells_per_axis && ny <= Grid::max_cells_per_axis,
                  reader.where("pad"), " = ", g.pad, " must be >= 0, with at most ",
                  Grid::max_cells_per_axis, " cells per direction in all");
  g.lx = keys.lx * static_cast<double>(nx) / static_cast<double>(keys.nx);
  g.ly = keys.ly * static_cast<double>(ny) / static_cast<double>(keys.ny);
  g.grid = Grid(nx, ny, g.lx, g.ly);
  reader.finish();
  return g;
}

}  // namespace

GridSection read_grid(const toml::table& root, const SceneTopography* topography) {
  SectionReader reader(section(root, "grid", topography == nullptr), "grid");
  if (topography)
    return in_section("grid", [&] { return read_topography_grid(reader, *topography); });
  COATFFT_REQUIRE(!reader.has("pad"), reader.where("pad"),
                  " applies to a measured topography ([contact] topography = \"FILE\")");
  return in_section("grid", [&] {
    GridSection g{reader.number("lx"), reader.number("ly"), std::nullopt, std::nullopt,
                  Boundary::free};
    g.boundary = parse_boundary(reader.choice("boundary", "free", {"free", "periodic"}));
    if (reader.choice("refine", "none", {"none", "auto"}) == "auto") {
      COATFFT_REQUIRE(g.boundary != Boundary::periodic,
                      "refine = \"auto\" chooses grids for free boundaries: give nx "
                      "and ny with boundary = \"periodic\"");
      COATFFT_REQUIRE(!reader.has("nx") && !reader.has("ny"),
                      "refine = \"auto\" chooses nx and ny: remove them");
      const double t = reader.number("tolerance_total");
      COATFFT_REQUIRE(t > 0 && t <= 0.1, reader.where("tolerance_total"), " = ", t,
                      " must be in (0, 0.1]");
      g.tolerance_total = t;
      Grid(1, 1, g.lx, g.ly);  // checks lx and ly now
    } else {
      COATFFT_REQUIRE(!reader.has("tolerance_total"), reader.where("tolerance_total"),
                      ": applies only with refine = \"auto\"");
      const auto nx = reader.integer("nx");
      const auto ny = reader.integer("ny");
      // Grid's own limit (core/grid.hpp), said with the scene's keys.
      COATFFT_REQUIRE(nx <= Grid::max_cells_per_axis && ny <= Grid::max_cells_per_axis, "nx = ", nx,
                      ", ny = ", ny, ": at most ", Grid::max_cells_per_axis,
                      " cells per direction");
      COATFFT_REQUIRE(g.boundary != Boundary::periodic || (nx % 2 == 0 && ny % 2 == 0),
                      "boundary = \"periodic\" needs "
                      "even nx and ny (nx = ",
                      nx, ", ny = ", ny, ")");
      g.grid = Grid(nx, ny, g.lx, g.ly);
    }
    reader.finish();
    return g;
  });
}

Grid refine_grid(const toml::table& root, const GridSection& g, Scene& scene) {
  MethodSpec& m = scene.method;
  COATFFT_REQUIRE(m.automatic,
                  "[grid] refine = \"auto\" needs [method] name = \"auto\": the "
                  "total tolerance is shared between the load's cells and the operator");
  COATFFT_REQUIRE(root.contains("pressure"),
                  "[grid] refine = \"auto\" applies to a known "
                  "pressure ([pressure] kind = \"hertz\" or \"uniform_disk\")");
  const toml::table& method = section(root, "method", false);
  if (!method.contains("tolerance")) m.tolerance = *g.tolerance_total / 10;
  COATFFT_REQUIRE(m.tolerance < *g.tolerance_total, "[method] tolerance = ", m.tolerance,
                  " must be below [grid] tolerance_total = ", *g.tolerance_total);
  const PressureSpec p = in_section("pressure", [&] {
    return read_pressure(section(root, "pressure", true), Grid(1, 1, g.lx, g.ly), {});
  });
  COATFFT_REQUIRE(p.kind != PressureKind::file,
                  "[grid] refine = \"auto\" needs an analytic "
                  "load: [pressure] kind = \"hertz\" or \"uniform_disk\"");
  const AnalyticLoad load = analytic_load(p);
  GridRefinementOptions options;
  try {
    options.body_factor = load_error_body_factor(*body_frf(scene), load);
  } catch (const InvalidArgument&) {
    throw;
  } catch (const Error& e) {  // the factor's Hankel reference did not converge
    throw InvalidArgument(
        detail::concat("[grid] refine = \"auto\": the load's error on this "
                       "body cannot be estimated (",
                       e.what(), "); give nx and ny"));
  }
  // The search estimates on the grids it tries: at most 1024 cells a side keeps it to seconds
  // and a few hundred MB before the scene's memory is checked. Finer grids: give nx and ny.
  options.max_cells = max_refined_cells;
  const double share = m.tolerance / *g.tolerance_total;
  GridChoice choice = in_section("grid", [&] {
    return choose_grid_for_tolerance(g.lx, g.ly, load, *g.tolerance_total, share, options);
  });
  scene.refinement = GridRefinement{*g.tolerance_total, choice};
  return choice.grid;
}

}  // namespace coatfft::scene
