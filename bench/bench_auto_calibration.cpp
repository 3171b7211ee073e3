// Calibration data of the cost model of the automatic method choice (model/cost_model.hpp,
// docs/auto.md section 3): for each case, the work counts that the model reads (DC-FFT's padded
// points, the split kernel's work from split_frf_kernel_work) next to the measured setup and
// application times of make_operator (medians), and the least-squares constants. One thread,
// FFTW_ESTIMATE. Writes bench/results/auto_calibration.csv (or OUTPUT).
//   bench_auto_calibration [OUTPUT] [--reps 3]
#include <Eigen/Dense>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "frf/frf.hpp"
#include "loads/hertz_pressure.hpp"

#ifndef COATFFT_SOURCE_DIR
#define COATFFT_SOURCE_DIR "."
#endif

namespace {

using namespace coatfft;

struct Body {
  std::string name;
  LayerStack stack;
};

std::vector<Body> bodies() {
  const Material steel(210e9, 0.3);
  const auto coated = [&](double E, double nu, double h) {
    return LayerStack({Coating{Material(E, nu), h, Interface::bonded}}, steel);
  };
  return {{"steel", LayerStack(steel)},           {"soft_h0.1", coated(21e9, 0.3, 0.1e-3)},
          {"hard_h1", coated(2100e9, 0.3, 1e-3)}, {"tin_20um", coated(400e9, 0.25, 20e-6)},
          {"tin_2um", coated(400e9, 0.25, 2e-6)}, {"polymer_10um", coated(3e9, 0.35, 10e-6)}};
}

struct Row {
  double points_log = 0;  // P log2 P of the padded lattice
  double cells = 0;
  SplitKernelWork work;
  double setup_s = 0;
  double apply_s = 0;
};

Row measure(const Grid& grid, const LayerStack& body, Method method, double tolerance, int reps) {
  OperatorOptions o;
  o.method = method;
  o.split.tolerance = tolerance;
  const Field p = hertz_pressure(grid, 1e9, grid.lx() / 3, Sampling::cell_average);
  std::vector<double> setup, apply;
  Row row;
  Field u;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    BuiltOperator built = make_operator(grid, body, o);
    setup.push_back(detail::seconds_since(start));
    apply.push_back(detail::time_applications(*built.op, p, u, 3));
    const double P = static_cast<double>(built.report.fft_nx * built.report.fft_ny);
    row.points_log = P * std::log2(P);
  }
  row.cells = static_cast<double>(grid.nx() * grid.ny());
  if (method == Method::frf_split) row.work = split_frf_kernel_work(grid, *make_frf(body), o.split);
  row.setup_s = detail::median(setup);
  row.apply_s = detail::median(apply);
  return row;
}

// Least squares of y = X c with relative weights (each row divided by y): the constants fit the
// ratios, not the largest times. A term whose constant comes out negative (collinear with the
// others in this set, or lost in the timing noise) is dropped, its constant 0, and the rest
// refitted: a time is a sum of non-negative costs.
Eigen::VectorXd fit(const std::vector<std::vector<double>>& x, const std::vector<double>& y) {
  const auto rows = static_cast<Eigen::Index>(x.size());
  const auto cols = static_cast<Eigen::Index>(x[0].size());
  std::vector<bool> kept(static_cast<std::size_t>(cols), true);
  for (;;) {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index j = 0; j < cols; ++j)
      if (kept[static_cast<std::size_t>(j)]) idx.push_back(j);
    Eigen::MatrixXd X(rows, static_cast<Eigen::Index>(idx.size()));
    for (Eigen::Index i = 0; i < rows; ++i)
      for (std::size_t k = 0; k < idx.size(); ++k)
        X(i, static_cast<Eigen::Index>(k)) =
            x[static_cast<std::size_t>(i)][static_cast<std::size_t>(idx[k])] /
            y[static_cast<std::size_t>(i)];
    const Eigen::VectorXd c = X.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(rows));
    Eigen::VectorXd full = Eigen::VectorXd::Zero(cols);
    bool negative = false;
    for (std::size_t k = 0; k < idx.size(); ++k) {
      full(idx[k]) = c(static_cast<Eigen::Index>(k));
      if (c(static_cast<Eigen::Index>(k)) < 0) {
        kept[static_cast<std::size_t>(idx[k])] = false;
        negative = true;
        break;
      }
    }
    if (!negative) return full;
  }
}

// FFTW's start: the first plan of the process against a later one (fftw_start_seconds): two
// builds of the same 65 x 65 DC-FFT operator [s].
std::array<double, 2> fftw_start_seconds() {
  std::array<double, 2> seconds{};
  for (double& t : seconds) {
    OperatorOptions o;
    o.method = Method::dcfft;
    const auto start = std::chrono::steady_clock::now();
    make_operator(Grid(65, 65, 3e-3, 3e-3), LayerStack(Material(210e9, 0.3)), o);
    t = detail::seconds_since(start);
  }
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{"Calibration data of the automatic method choice's cost model"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/auto_calibration.csv";
  app.add("output", out_path, "CSV file").show_default();
  int reps = 3;
  app.add("--reps", reps, "Builds per row").show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  try {
    const std::array<double, 2> first_s = fftw_start_seconds();
    std::ostringstream csv;
    csv << "# bench_auto_calibration: setup and application against the cost model's work counts\n";
    bench::write_machine_header(csv);
    csv << "# threads = 1, planning = estimate, reps = " << reps << "\n";
    csv << "# fftw start: first 65x65 dcfft build of the process " << first_s[0] << " s, the next "
        << first_s[1] << " s\n";
    csv << "body,method,n,tolerance,cells,points_log,fold_terms,cell_nodes,hankel_evaluations,"
           "setup_s,apply_s\n";
    std::vector<std::vector<double>> xa, xl, xs;
    std::vector<double> ya, yl, ys;
    for (const Body& b : bodies()) {
      for (const int n : {32, 64, 128, 256, 512, 1024}) {
        const Grid grid(n, n, 3e-3, 3e-3);
        const bool love = b.stack.is_homogeneous();
        for (const double tol :
             love ? std::vector<double>{0.0} : std::vector<double>{1e-3, 1e-6, 1e-11}) {
          if (!love && n > 512) continue;
          const Method m = love ? Method::dcfft : Method::frf_split;
          const Row r = measure(grid, b.stack, m, love ? 1e-11 : tol, reps);
          std::ostringstream line;
          line << b.name << ',' << to_string(m) << ',' << n << ',' << tol << ',' << r.cells << ','
               << r.points_log << ',' << r.work.fold_terms << ',' << r.work.cell_nodes << ','
               << r.work.hankel_evaluations << ',' << r.setup_s << ',' << r.apply_s << '\n';
          std::cout << line.str() << std::flush;
          csv << line.str();
          xa.push_back({1.0, r.points_log});
          ya.push_back(r.apply_s);
          if (love) {
            xl.push_back({1.0, r.cells, r.points_log});
            yl.push_back(r.setup_s);
          } else {
            xs.push_back({1.0, r.cells, r.work.fold_terms, r.work.hankel_evaluations});
            ys.push_back(r.setup_s);
          }
        }
      }
    }
    const Eigen::VectorXd ca = fit(xa, ya), cl = fit(xl, yl), cs = fit(xs, ys);
    csv << "# fit apply = c0 + c1 P log2 P: " << ca.transpose() << "\n";
    csv << "# fit love setup = c0 + c1 cells + c2 P log2 P: " << cl.transpose() << "\n";
    // The cell rule's nodes and the transform's P log2 P are left out: collinear with the cells
    // here, they made the fit's constants negative.
    csv << "# fit split setup = c0 + c1 cells + c2 fold_terms + c3 hankel_evaluations: "
        << cs.transpose() << "\n";
    std::cout << csv.str().substr(csv.str().find("# fit")) << std::flush;
    bench::write_text_file(out_path, csv.str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_auto_calibration: " << e.what() << '\n';
    return 1;
  }
}
