#include "scene/run_highlights.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/detail/brief.hpp"
#include "core/error.hpp"

namespace coatfft::scene {

namespace {

struct Unit {
  const char* name;
  double size;
};

// `value` in the unit of `units` (ascending sizes) that brings its magnitude, rounded to three
// significant digits, into [1, 1000): the smallest unit below that, the largest above. 4.12e-5 m
// is "41.2 µm", 9.996e-4 m "1 mm" (not "1e+03 µm"), 0 "0".
std::string in_units(double value, const std::vector<Unit>& units) {
  if (value == 0.0) return "0";
  const double rounded = std::strtod(detail::brief(value).c_str(), nullptr);
  const Unit* unit = &units.front();
  for (const Unit& u : units)
    if (std::abs(rounded) >= u.size) unit = &u;
  return detail::concat(detail::brief(rounded / unit->size), " ", unit->name);
}

std::string length(double metres) {
  return in_units(metres, {{"nm", 1e-9}, {"µm", 1e-6}, {"mm", 1e-3}, {"m", 1.0}});
}

std::string stress(double pascals) {
  return in_units(pascals, {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}});
}

// A number of the summary at `key` of `object`; none when it is absent, not a number (null) or
// not finite, so that no line reports one.
std::optional<double> number(const nlohmann::json& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number()) return std::nullopt;
  const double value = object[key].get<double>();
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

// " (Hertz: 43.3 µm on the bare substrate, 35.3 µm on the bare top coating)": Hertz's values of
// `key` from the summary's "hertz_bare", each written by `format`; empty without it.
template <class Format>
std::string hertz_note(const nlohmann::json& summary, const char* key, Format format) {
  if (!summary.contains("hertz_bare")) return "";
  const nlohmann::json& bare = summary["hertz_bare"];
  const std::optional<double> substrate = number(bare.value("substrate", nlohmann::json()), key);
  if (!substrate) return "";
  if (!bare.contains("top_coating")) return " (Hertz: " + format(*substrate) + ")";
  const std::optional<double> coating = number(bare.value("top_coating", nlohmann::json()), key);
  return " (Hertz: " + format(*substrate) + " on the bare substrate" +
         (coating ? ", " + format(*coating) + " on the bare top coating)" : ")");
}

// The contact's lines: its radius (of the disk of equal area when the contact is not round) and
// its peak pressure, each with Hertz's values where the summary has them.
void add_contact_lines(const nlohmann::json& summary, std::vector<std::string>& lines) {
  if (summary.contains("sweep") && number(summary, "load")) {
    const nlohmann::json& rows = summary["sweep"];
    const bool unloaded = !rows.empty() && rows.back().value("phase", "load") == "unload";
    lines.push_back(
        std::string(unloaded ? "at the end of the unloading, " : "at the sweep's largest load, ") +
        detail::brief(*number(summary, "load")) + " N:");
  }
  const auto radius = number(summary, "contact_radius"),
             equivalent = number(summary, "equivalent_radius");
  if (radius)
    lines.push_back("contact radius " + length(*radius) +
                    hertz_note(summary, "contact_radius", length));
  else if (equivalent)
    lines.push_back("equivalent contact radius " + length(*equivalent) +
                    " (of the disk of the contact's area; the contact is not round)");
  if (const auto peak = number(summary, "max_pressure"))
    lines.push_back("peak pressure " + stress(*peak) + hertz_note(summary, "max_pressure", stress));
  if (summary.contains("adhesion")) {
    const nlohmann::json& adhesion = summary["adhesion"];
    if (const auto pull_off = number(adhesion, "pull_off_load"))
      lines.push_back("pull-off (the most tensile load) " + detail::brief(*pull_off) + " N");
    if (const auto jumped = number(adhesion, "jumped_off_at"))
      lines.push_back("the contact jumped off at the approach " + length(*jumped));
  }
  if (summary.contains("plastic")) {
    const nlohmann::json& plastic = summary["plastic"];
    if (const auto fraction = number(plastic, "plastic_area_fraction"))
      lines.push_back("plastic (at the hardness) on " + detail::brief(100 * *fraction) +
                      " % of the contact area");
    if (const auto depth = number(plastic, "max_plastic_depth"))
      lines.push_back("largest plastic depth " + length(*depth));
  }
}

// " (in the top coating, at the interface)": the medium a stress summary names ("coating 1" ...
// "substrate") in words, and whether the place is on an interface plane; empty for a body
// without coatings.
std::string medium_note(const nlohmann::json& summary, const nlohmann::json& peak) {
  const std::size_t coatings =
      summary.value("body", nlohmann::json()).value("coatings", nlohmann::json::array()).size();
  if (coatings == 0 || !peak.contains("medium")) return "";
  const std::string medium = peak["medium"].get<std::string>();
  std::string words = medium == "substrate" ? "the substrate"
                      : coatings == 1       ? "the coating"
                                            : medium + " (from the top)";
  const std::optional<double> z = number(peak, "z");
  for (const nlohmann::json& interface :
       summary["stress"].value("interfaces", nlohmann::json::array())) {
    const std::optional<double> depth = number(interface, "depth");
    if (z && depth && std::abs(*z - *depth) <= 1e-9 * *depth) words += ", at the interface";
  }
  return " (in " + words + ")";
}

// A coordinate of a cell centre, 0 where rounding left it a hair off the origin (a centre
// cell's x is -lx/2 + nx dx/2).
double coordinate(double value, double cell) {
  return std::abs(value) < 1e-9 * cell ? 0.0 : value;
}

// The stresses' lines: the largest von Mises stress with its place and medium, and the largest
// shear stress on each interface with its distance from the axis.
void add_stress_lines(const nlohmann::json& summary, std::vector<std::string>& lines) {
  const nlohmann::json& s = summary["stress"];
  const double cell = std::min(number(summary, "lx").value_or(0.0) / summary.value("nx", 1.0),
                               number(summary, "ly").value_or(0.0) / summary.value("ny", 1.0));
  const nlohmann::json& mises = s.value("max_von_mises", nlohmann::json());
  const auto value = number(mises, "value"), x = number(mises, "x"), y = number(mises, "y"),
             z = number(mises, "z");
  if (value && x && y && z)
    lines.push_back("largest von Mises stress " + stress(*value) + " at x = " +
                    length(coordinate(*x, cell)) + ", y = " + length(coordinate(*y, cell)) +
                    ", depth " + length(*z) + medium_note(summary, mises));
  for (const nlohmann::json& interface : s.value("interfaces", nlohmann::json::array())) {
    const nlohmann::json& shear = interface.value("max_shear", nlohmann::json());
    const auto tau = number(shear, "value"), xs = number(shear, "x"), ys = number(shear, "y"),
               depth = number(interface, "depth");
    if (tau && xs && ys && depth)
      lines.push_back("largest interface shear stress " + stress(*tau) +
                      " at r = " + length(coordinate(std::hypot(*xs, *ys), cell)) +
                      " (interface at depth " + length(*depth) + ")");
  }
}

}  // namespace

std::vector<std::string> run_highlights(const nlohmann::json& summary) {
  std::vector<std::string> lines;
  if (summary.contains("contact_area")) add_contact_lines(summary, lines);
  if (summary.contains("stress")) add_stress_lines(summary, lines);
  return lines;
}

}  // namespace coatfft::scene
