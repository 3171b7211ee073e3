#include "cli/run_outputs.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "core/detail/close_written.hpp"
#include "core/error.hpp"
#include "scene/run_highlights.hpp"
#include "scene/scene_netcdf.hpp"

namespace coatfft::cli {

void write_displacement_rows(std::ostream& out, const Grid& grid, std::ptrdiff_t y0, const Field& p,
                             const Field& uz, bool header) {
  if (header) out << "x,y,pressure,uz\n";
  out << std::setprecision(17);
  for (Eigen::Index j = 0; j < p.cols(); ++j)
    for (Eigen::Index i = 0; i < grid.nx(); ++i)
      out << grid.x(i) << ',' << grid.y(y0 + j) << ',' << p(i, j) << ',' << uz(i, j) << '\n';
}

std::vector<std::string> output_names(const scene::OutputSpec& spec) {
  std::vector<std::string> names;
  if (spec.uz) names.push_back("uz.npy");
  if (spec.pressure) names.push_back("pressure.npy");
  if (spec.displacement_csv) names.push_back("displacement.csv");
  names.push_back("summary.json");
  if (spec.gap) names.push_back("gap.npy");
  if (spec.sweep) names.push_back("sweep.csv");
  if (spec.plastic) names.push_back("plastic.npy");
  if (spec.residual_gap) names.push_back("residual_gap.npy");
  if (spec.in_plane && spec.ux) names.push_back("ux.npy");
  if (spec.in_plane && spec.uy) names.push_back("uy.npy");
  if (spec.shear) names.insert(names.end(), {"shear_x.npy", "shear_y.npy"});
  if (spec.stick) names.push_back("stick.npy");
  if (spec.slip) names.insert(names.end(), {"slip_x.npy", "slip_y.npy"});
  if (spec.fretting) names.push_back("fretting.csv");
  if (spec.stress) names.push_back("stress.npy");
  if (spec.von_mises) names.push_back("von_mises.npy");
  if (spec.stress_section) names.push_back("stress_section.npy");
  if (spec.von_mises_section) names.push_back("von_mises_section.npy");
  if (spec.stress_interfaces) names.push_back("stress_interfaces.npy");
  if (spec.von_mises_interfaces) names.push_back("von_mises_interfaces.npy");
  if (!spec.netcdf) return names;
  const auto is_npy = [](const std::string& name) { return name.ends_with(".npy"); };
  const auto first = std::find_if(names.begin(), names.end(), is_npy);
  if (first == names.end()) return names;
  *first = scene::netcdf_output_name;
  names.erase(std::remove_if(first + 1, names.end(), is_npy), names.end());
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

void write_summary(const std::filesystem::path& path, const nlohmann::json& summary) {
  std::ofstream json(path);
  json << std::setw(2) << summary << '\n';
  detail::close_written(json, "summary.json");
}

void print_warnings(const nlohmann::json& summary) {
  for (const auto& warning : summary["warnings"]) {
    std::cerr << "coatfft: warning: " << warning.get<std::string>() << '\n';
  }
}

void print_highlights(const nlohmann::json& summary) {
  for (const std::string& line : scene::run_highlights(summary)) std::cout << line << '\n';
  std::cout.flush();
}

}  // namespace coatfft::cli
