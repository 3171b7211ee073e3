// Convergence of DC-FFT on the Hertz pressure (seed paper Fig. 2(b)): for N x N grids on
// [-1.5a, 1.5a]^2 it prints and writes a markdown table of the seed's error measure
// (u_num - u_exact)/u_exact(0). Usage: hertz_dcfft_table [output.md] [--csv output.csv]
// (default docs/validation_hertz_dcfft.md relative to the working directory); --csv also writes the
// errors as a CSV with "# key = value" headers, which scripts/make_validation_docs.sh renders into
// docs/validation.md's generated block hertz_dcfft (scripts/markdown_blocks.py).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "convolution/dcfft_operator.hpp"
#include "convolution/influence_kernel.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "materials/catalog.hpp"
#include "validation/hertz.hpp"

namespace {

struct Row {
  std::ptrdiff_t n;
  double h;             // cell size [m]
  double max_error;     // max |seed error| over the grid
  double rms_error;     // root mean square of the seed error over the grid
  double centre_error;  // seed error at the four cells nearest the origin (r = h / sqrt 2)
  double seconds;       // kernel + plan + one apply
};

Row run(std::ptrdiff_t n, double p0, double a, double e_star) {
  const auto start = std::chrono::steady_clock::now();
  const coatfft::Grid grid(n, n, 3.0 * a, 3.0 * a);
  coatfft::DcfftOperator op(coatfft::love_kernel(grid, e_star));
  coatfft::Field p(n, n);
  for (std::ptrdiff_t j = 0; j < n; ++j)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const double r = std::hypot(grid.x(i), grid.y(j));
      p(i, j) = r < a ? p0 * std::sqrt(1.0 - r * r / (a * a)) : 0.0;
    }
  const coatfft::Field u = op.apply(p);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double u0 = coatfft::hertz_displacement(0.0, p0, a, e_star);
  Row row{n, grid.dx(), 0.0, 0.0, 0.0, seconds};
  for (std::ptrdiff_t j = 0; j < n; ++j)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const double r = std::hypot(grid.x(i), grid.y(j));
      const double e =
          coatfft::seed_error(u(i, j), coatfft::hertz_displacement(r, p0, a, e_star), u0);
      row.max_error = std::max(row.max_error, std::abs(e));
      row.rms_error += e * e;
      // Even N has no node at the origin; cell (n/2, n/2) is one of the four nearest to it.
      if (i == n / 2 && j == n / 2) row.centre_error = e;
    }
  row.rms_error = std::sqrt(row.rms_error / static_cast<double>(n * n));
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string path = "docs/validation_hertz_dcfft.md";
    std::string csv_path;
    for (int k = 1; k < argc; ++k) {
      const std::string arg = argv[k];
      if (arg == "--csv") {
        COATFFT_REQUIRE(k + 1 < argc, "hertz_dcfft_table: --csv needs a file name");
        csv_path = argv[++k];
      } else {
        path = arg;
      }
    }
    const double p0 = 1e9;  // Pa
    const double a = 1e-3;  // m
    const coatfft::Material steel = coatfft::material_by_name("steel");
    const double e_star = steel.plane_strain_modulus();
    std::vector<Row> rows;
    for (std::ptrdiff_t n : {32, 64, 128, 256, 512}) rows.push_back(run(n, p0, a, e_star));

    std::string md;
    std::string csv =
        "# program = hertz_dcfft_table\n"
        "# load = Hertz p0 = 1 GPa, a = 1 mm, steel (E = 210 GPa, nu = 0.3), sampled at the cell "
        "centres of an N x N grid on [-1.5a, 1.5a]^2\n"
        "# method = DC-FFT with Love's coefficients; reference: closed form (theory.md 1.6-1.7)\n"
        "# error = (u_num - u_exact) / u_exact(0) (seed paper Fig. 2); max_abs_error = max over "
        "all "
        "cells, rms_error = root mean square over all cells\n"
        "# error_nearest_origin = error at the four cells nearest the origin, r = h / sqrt 2 (even "
        "N: no cell centre at the origin)\n"
        "# orders = log2 of the ratio of successive errors\n"
        "N,h_over_a,max_abs_error,order_max,rms_error,order_rms,error_nearest_origin\n";
    char line[256];
    md +=
        "| N | h / a | max \\|error\\| | order (max) | rms error | order (rms) | "
        "error at central cells | time [s] |\n";
    md += "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Row& r = rows[k];
      std::string order_max;
      std::string order_rms;
      if (k > 0) {
        std::snprintf(line, sizeof line, "%.2f", std::log2(rows[k - 1].max_error / r.max_error));
        order_max = line;
        std::snprintf(line, sizeof line, "%.2f", std::log2(rows[k - 1].rms_error / r.rms_error));
        order_rms = line;
      }
      std::snprintf(line, sizeof line, "| %td | %.5f | %.3e | %s | %.3e | %s | %.3e | %.3f |\n",
                    r.n, r.h / a, r.max_error, order_max.c_str(), r.rms_error, order_rms.c_str(),
                    r.centre_error, r.seconds);
      md += line;
      std::snprintf(line, sizeof line, "%td,%.5f,%.3e,%s,%.3e,%s,%.3e\n", r.n, r.h / a, r.max_error,
                    order_max.c_str(), r.rms_error, order_rms.c_str(), r.centre_error);
      csv += line;
    }
    std::string header =
        "Hertz pressure (p0 = 1 GPa, a = 1 mm, steel E = 210 GPa, nu = 0.3) sampled at the cell\n"
        "centres of an N x N grid on [-1.5a, 1.5a]^2, displacement by DC-FFT (Love coefficients),\n"
        "compared with the closed form (theory.md 1.6-1.7). Error = (u_num - u_exact) / "
        "u_exact(0)\n"
        "(seed paper Fig. 2). Central cells: the four cells nearest the origin (r = h / sqrt 2).\n"
        "Orders: log2 of the ratio of successive errors. Time: kernel, plans and one application.\n"
        "Generated by `scripts/make_validation_docs.sh hertz_dcfft` (program `hertz_dcfft_table`,\n"
        "built with COATFFT_BUILD_BENCH=ON).\n\n";
    std::cout << header << md;
    std::ofstream out(path);
    COATFFT_REQUIRE(out.good(), "hertz_dcfft_table: cannot write '", path, "'");
    out << header << md;
    if (!csv_path.empty()) {
      std::ofstream csv_out(csv_path);
      COATFFT_REQUIRE(csv_out.good(), "hertz_dcfft_table: cannot write '", csv_path, "'");
      csv_out << csv;
    }
    bool decreasing = true;
    for (std::size_t k = 1; k < rows.size(); ++k)
      decreasing = decreasing && rows[k].max_error < rows[k - 1].max_error;
    std::cout << (decreasing ? "max error decreases with N\n" : "max error does NOT decrease\n");
    return decreasing ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "hertz_dcfft_table: " << e.what() << "\n";
    return 2;
  }
}
