#pragma once
// One row of the speed-against-error sweep: its settings, the command line that bench_sweep gives
// the child program bench_sweep_row for it, and the files the child leaves for bench_sweep (the
// displacement, then its timings). Shared by bench/bench_sweep.cpp and bench/bench_sweep_row.cpp.
#include <cstddef>
#include <fstream>
#include <iomanip>
#include <optional>
#include <string>
#include <vector>

#include "bench/sweep_cases.hpp"
#include "convolution/fft/planning.hpp"
#include "convolution/kernels/g0.hpp"
#include "convolution/method.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/error.hpp"
#include "core/types.hpp"

namespace coatfft::sweep {

/// The settings of one row.
struct RowSpec {
  std::string case_name;
  Method method = Method::dcfft;
  std::ptrdiff_t n = 0;
  double alpha = 0.0;          ///< frf-spectral, frf-dcfft; 0 otherwise
  std::optional<G0Method> g0;  ///< frf-spectral, frf-dcfft
  double g0_tol = 0.0;
};

/// How the child runs: planner effort, threads, and seconds of repeated applications.
struct RowRun {
  Planning planning = Planning::estimate;
  int threads = 1;
  double budget_s = 0.5;
};

/// The CSV's g0 column: "none", "regularized" or "quadrature".
inline std::string g0_label(const RowSpec& row) {
  return row.g0 ? std::string(to_string(*row.g0)) : "none";
}

/// The operator options of a row.
inline OperatorOptions operator_options(const RowSpec& row, const RowRun& run) {
  OperatorOptions o;
  o.method = row.method;
  o.planning = run.planning;
  o.threads = run.threads;
  if (row.g0) {
    o.alpha = row.alpha;
    o.g0 = *row.g0;
    o.g0_tolerance = row.g0_tol;
  }
  return o;
}

/// The arguments of bench_sweep_row for `row` (after the program's path); the child writes its
/// displacement to `field_file` and its timings to `field_file`.txt.
inline std::vector<std::string> row_arguments(const RowSpec& row, const RowRun& run,
                                              const std::string& field_file) {
  std::vector<std::string> args = {"--case",     row.case_name,
                                   "--method",   std::string(to_string(row.method)),
                                   "--n",        std::to_string(row.n),
                                   "--planning", std::string(to_string(run.planning)),
                                   "--threads",  std::to_string(run.threads),
                                   "--budget",   fmt(run.budget_s),
                                   "--output",   field_file};
  if (row.g0) {
    for (const std::string& s : {std::string("--alpha"), fmt(row.alpha), std::string("--g0"),
                                 g0_label(row), std::string("--g0-tol"), fmt(row.g0_tol)})
      args.push_back(s);
  }
  return args;
}

/// What the child measured.
struct RowTiming {
  double setup_s = 0.0;         ///< wall time of building the operator [s]
  double apply_s_median = 0.0;  ///< median of the repeated applications [s]
  int reps = 0;                 ///< how many were timed
  double coeff_s = 0.0;         ///< part of setup_s spent on the influence coefficients [s]
};

/// Writes u (nx ny doubles, x fastest) to `path` and the timings to `path`.txt.
inline void write_row_result(const std::string& path, const Field& u, const RowTiming& t) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(u.data()),
            static_cast<std::streamsize>(u.size() * static_cast<std::ptrdiff_t>(sizeof(double))));
  COATFFT_REQUIRE(out.good(), "cannot write ", path);
  std::ofstream txt(path + ".txt");
  txt << std::setprecision(17) << t.setup_s << ' ' << t.apply_s_median << ' ' << t.reps << ' '
      << t.coeff_s << '\n';
  COATFFT_REQUIRE(txt.good(), "cannot write ", path, ".txt");
}

/// Reads what write_row_result wrote for an n x n grid.
inline Field read_row_result(const std::string& path, std::ptrdiff_t n, RowTiming& t) {
  Field u(n, n);
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(u.data()),
          static_cast<std::streamsize>(u.size() * static_cast<std::ptrdiff_t>(sizeof(double))));
  COATFFT_REQUIRE(in.good(), "cannot read the child's field from ", path);
  std::ifstream txt(path + ".txt");
  txt >> t.setup_s >> t.apply_s_median >> t.reps >> t.coeff_s;
  COATFFT_REQUIRE(!txt.fail(), "cannot read the child's timings from ", path, ".txt");
  return u;
}

}  // namespace coatfft::sweep
