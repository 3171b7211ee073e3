// The automatic method choice measured: for each body, grid and tolerance (1e-2, 1e-3, 1e-4),
// the whole path of `[method] name = "auto"` (reduce_body, choose_method, make_operator, one
// application; scene/automatic_method.cpp) timed and its achieved operator error measured, next
// to the hand-picked settings of the speed-against-error sweep (dcfft, frf-split, frf-spectral
// and frf-dcfft at alpha 2, 4, 8 with g(0) regularized) and the fastest of them that meets the
// tolerance (docs/auto.md, section 5). One Hertz load (p0 = 1 GPa, a = 1 mm, cell-averaged,
// centred) on [-1.5a, 1.5a]^2; one thread, FFTW_ESTIMATE.
//
// Operator error = max |u - u_ref| / max |u_ref|, u_ref the exact convolution of the same
// cell-wise load on the full (unreduced) body: Love's DC-FFT for a homogeneous body, else
// frf-split at split tolerance 1e-13, whose own error is far below the errors measured
// (docs/auto.md, section 5: self-convergence, and the split kernel's all-Hankel route as an
// independent evaluation, --cross-check).
// Prints "# key = value" headers and CSV rows as they come, writes them to
// bench/results/auto_tolerance.csv (or OUTPUT).
//   bench_auto_tolerance [OUTPUT] [--quick] [--reps 3] [--cases soft_h0.1,...]
//                        [--cross-check soft_h0.1,soft_h1,hard_h0.1,hard_h1]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_report.hpp"
#include "bench/command_line.hpp"
#include "convolution/method.hpp"
#include "convolution/operators/make_operator.hpp"
#include "core/detail/timing.hpp"
#include "core/grid.hpp"
#include "layers/layer_stack.hpp"
#include "loads/hertz_pressure.hpp"
#include "materials/material.hpp"
#include "model/auto_method.hpp"
#include "model/body_reduction.hpp"

#ifndef COATFFT_SOURCE_DIR
#define COATFFT_SOURCE_DIR "."
#endif

namespace {

using namespace coatfft;

constexpr double p0 = 1e9;       // Hertz peak pressure [Pa]
constexpr double radius = 1e-3;  // Hertz contact radius a [m]
constexpr double side = 3e-3;    // the domain [-1.5a, 1.5a]^2 [m]
constexpr double reference_split_tolerance = 1e-13;
// The CLI's share of the tolerance offered to the body reduction (scene/automatic_method.hpp).
constexpr double reduction_share = 0.9;
const std::vector<double> tolerances = {1e-2, 1e-3, 1e-4};

struct Case {
  std::string name;
  LayerStack body;
  std::vector<std::ptrdiff_t> sizes;  // N of the N x N grids
};

LayerStack coated(double E, double nu, double h) {
  return LayerStack({Coating{Material(E, nu), h, Interface::bonded}}, Material(210e9, 0.3));
}

// The coated cases of bench_sweep at two sizes, then the example bodies (docs/auto.md,
// section 5, states their values).
std::vector<Case> all_cases() {
  const Material steel(210e9, 0.3);
  const LayerStack three_layer({Coating{Material(400e9, 0.25), 2e-6, Interface::bonded},
                                Coating{Material(279e9, 0.21), 1e-6, Interface::bonded},
                                Coating{Material(170e9, 0.30), 5e-6, Interface::bonded}},
                               steel);
  return {{"soft_h0.1", coated(21e9, 0.3, 0.1e-3), {128, 512}},
          {"soft_h1", coated(21e9, 0.3, 1e-3), {128, 512}},
          {"hard_h0.1", coated(2100e9, 0.3, 0.1e-3), {128, 512}},
          {"hard_h1", coated(2100e9, 0.3, 1e-3), {128, 512}},
          {"steel", LayerStack(steel), {128}},
          {"tin_2um", coated(400e9, 0.25, 2e-6), {128}},
          {"polymer_10um", coated(3e9, 0.35, 10e-6), {128}},
          {"three_layer", three_layer, {128}}};
}

double relative_error(const Field& u, const Field& ref) {
  return (u - ref).abs().maxCoeff() / ref.abs().maxCoeff();
}

Field apply_once(const Grid& grid, const LayerStack& body, const OperatorOptions& o,
                 const Field& p) {
  Field u;
  make_operator(grid, body, o).op->apply(p, u);
  return u;
}

// The exact convolution of the cell-wise load on the full body (see the file's comment).
Field reference(const Grid& grid, const LayerStack& body, const Field& p,
                SplitRoute route = SplitRoute::automatic) {
  OperatorOptions o;
  o.method = exact_method(body);
  o.split.tolerance = reference_split_tolerance;
  o.split.route = route;
  return apply_once(grid, body, o, p);
}

/// Wall and CPU seconds of one run. On a shared machine the wall time also counts the waits for
/// a core; the process's CPU time (one thread here) much less, so both are recorded.
struct Times {
  double wall = 0.0;
  double cpu = 0.0;
};

class Stopwatch {
 public:
  Times elapsed() const {
    return {detail::seconds_since(wall_),
            static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC};
  }

 private:
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  std::clock_t cpu_ = std::clock();
};

Times median(const std::vector<Times>& runs) {
  std::vector<double> wall, cpu;
  for (const Times& t : runs) {
    wall.push_back(t.wall);
    cpu.push_back(t.cpu);
  }
  return {detail::median(wall), detail::median(cpu)};
}

/// One setting as measured: its times (setup + one application, medians) and error.
struct Measured {
  std::string label;
  Times time;
  double error = 0.0;
  double predicted_error = std::numeric_limits<double>::quiet_NaN();  // lattice methods only
};

struct Setting {
  std::string label;
  OperatorOptions options;
};

// The hand-picked settings of bench_sweep (its g(0) regularized at tolerance 1e-13).
std::vector<Setting> hand_picked(const LayerStack& body) {
  std::vector<Setting> settings;
  OperatorOptions o;
  if (body.is_homogeneous()) settings.push_back({"dcfft", o});
  o.method = Method::frf_split;
  settings.push_back({"frf-split", o});
  for (const Method m : {Method::frf_spectral, Method::frf_dcfft})
    for (const double alpha : {2.0, 4.0, 8.0}) {
      o.method = m;
      o.alpha = alpha;
      o.g0 = G0Method::regularized;
      o.g0_tolerance = 1e-13;
      std::ostringstream label;
      label << to_string(m) << " a" << alpha;
      settings.push_back({label.str(), o});
    }
  return settings;
}

Measured measure(const Grid& grid, const LayerStack& body, const Setting& s, const Field& p,
                 const Field& ref, int reps) {
  Measured m;
  m.label = s.label;
  std::vector<Times> runs;
  Field u;
  for (int r = 0; r < reps; ++r) {
    const Stopwatch watch;
    BuiltOperator built = make_operator(grid, body, s.options);
    built.op->apply(p, u);
    runs.push_back(watch.elapsed());
    if (built.report.predicted_error) m.predicted_error = *built.report.predicted_error;
  }
  m.time = median(runs);
  m.error = relative_error(u, ref);
  return m;
}

/// The automatic path of the CLI, as it ran.
struct AutoRun {
  BodyReduction reduction;
  MethodChoice choice;
  Times time;                ///< the whole path
  double reduction_cpu = 0;  ///< of which reduce_body [s CPU]
  double choice_cpu = 0;     ///< of which choose_method [s CPU]
  double error = 0.0;
};

// reduce_body, choose_method, make_operator and one application: what `coatfft run` does for
// `[method] name = "auto"` with a Hertz pressure (scene/automatic_method.cpp).
AutoRun auto_path(const Grid& grid, const LayerStack& body, const Field& p, double tolerance,
                  Field& u) {
  const Stopwatch watch;
  BodyReduction reduction =
      reduce_body(body, {{AxisymmetricLoad::hertz, radius}}, reduction_share * tolerance);
  const double reduced = watch.elapsed().cpu;
  AutoRequest request;
  request.tolerance = tolerance - reduction.estimated_effect;
  request.applications = 1;
  request.max_threads = 1;
  MethodChoice choice = choose_method(grid, reduction.body, request);
  const double chosen = watch.elapsed().cpu;
  make_operator(grid, reduction.body, choice.options).op->apply(p, u);
  return {std::move(reduction), std::move(choice), watch.elapsed(), reduced, chosen - reduced, 0.0};
}

AutoRun run_auto(const Grid& grid, const LayerStack& body, const Field& p, const Field& ref,
                 double tolerance, int reps) {
  Field u;
  AutoRun run = auto_path(grid, body, p, tolerance, u);
  std::vector<Times> runs = {run.time};
  std::vector<double> reduction = {run.reduction_cpu}, choice = {run.choice_cpu};
  for (int r = 1; r < reps; ++r) {
    const AutoRun again = auto_path(grid, body, p, tolerance, u);
    runs.push_back(again.time);
    reduction.push_back(again.reduction_cpu);
    choice.push_back(again.choice_cpu);
  }
  run.time = median(runs);
  run.reduction_cpu = detail::median(reduction);
  run.choice_cpu = detail::median(choice);
  run.error = relative_error(u, ref);
  return run;
}

std::string num(double v) {
  if (std::isnan(v)) return "";
  std::ostringstream os;
  os.precision(4);
  os << v;
  return os.str();
}

std::string hand_row(const std::string& name, std::ptrdiff_t n, const Measured& m) {
  return "hand," + name + ',' + std::to_string(n) + ",," + m.label + ",,,,," +
         num(m.predicted_error) + ',' + num(m.error) + ',' + num(m.time.wall) + ',' +
         num(m.time.cpu) + ",,,,,,,,,\n";
}

// The fastest hand-picked setting, by wall (or CPU) time, whose error is within the tolerance;
// nullptr if none is.
const Measured* fastest_within(const std::vector<Measured>& hand, double tolerance, bool cpu) {
  const Measured* best = nullptr;
  const auto t = [cpu](const Measured& m) { return cpu ? m.time.cpu : m.time.wall; };
  for (const Measured& m : hand)
    if (m.error <= tolerance && (best == nullptr || t(m) < t(*best))) best = &m;
  return best;
}

std::string auto_row(const std::string& name, std::ptrdiff_t n, double tolerance, const AutoRun& a,
                     const std::vector<Measured>& hand) {
  const OperatorOptions& o = a.choice.options;
  const bool split = o.method == Method::frf_split;
  const bool lattice = samples_frf_lattice(o.method);
  const double predicted = a.choice.chosen.predicted_error + a.reduction.estimated_effect;
  std::ostringstream row;
  row << "auto," << name << ',' << n << ',' << num(tolerance) << ',' << to_string(o.method) << ','
      << a.reduction.kind << ',' << (split ? num(o.split.tolerance) : "") << ','
      << (lattice ? num(o.alpha) : "") << ',' << num(a.reduction.estimated_effect) << ','
      << num(predicted) << ',' << num(a.error) << ',' << num(a.time.wall) << ',' << num(a.time.cpu)
      << ',' << num(a.reduction_cpu) << ',' << num(a.choice_cpu) << ',';
  const Measured* best = fastest_within(hand, tolerance, false);
  const Measured* best_cpu = fastest_within(hand, tolerance, true);
  if (best != nullptr)
    row << best->label << ',' << num(best->time.wall) << ',' << num(best->error) << ','
        << num(a.time.wall / best->time.wall) << ',' << best_cpu->label << ','
        << num(a.time.cpu / best_cpu->time.cpu);
  else
    row << "none,,,,,";
  row << ',' << (a.error <= tolerance ? "yes" : "no") << '\n';
  return row.str();
}

std::string loadavg() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  in >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// The reference against the split kernel's all-Hankel route (no lattice, no window) on the
// first grid of `c`: an independent evaluation of the same convolution.
std::string cross_check(const Case& c) {
  const Grid grid(c.sizes.front(), c.sizes.front(), side, side);
  const Field p = hertz_pressure(grid, p0, radius, Sampling::cell_average);
  const auto start = std::chrono::steady_clock::now();
  const Field hankel = reference(grid, c.body, p, SplitRoute::hankel);
  const double hankel_s = detail::seconds_since(start);
  std::ostringstream line;
  line << "# cross_check " << c.name << " N = " << c.sizes.front()
       << ": max |u_ref - u_hankel_route| / max |u_ref| = "
       << num(relative_error(hankel, reference(grid, c.body, p)))
       << " (hankel route, split tolerance 1e-13, " << num(hankel_s) << " s)\n";
  return line.str();
}

std::string header(int reps, bool quick, const std::string& checks) {
  std::ostringstream csv;
  csv << "# bench_auto_tolerance: the automatic method choice (reduction + choice + make_operator "
         "+ one application) against hand-picked settings, per tolerance\n";
  bench::write_machine_header(csv);
  csv << "# loadavg_start = " << loadavg() << "\n";
  csv << "# mode = " << (quick ? "quick" : "full") << ", reps = " << reps
      << " (times are medians), threads = 1, planning = estimate\n";
  csv << "# load = Hertz p0 = 1 GPa, a = 1 mm, cell-averaged, centred on [-1.5a, 1.5a]^2\n";
  csv << "# bodies = bonded on steel (210 GPa, 0.3): soft_h0.1/soft_h1 21 GPa, 0.3, h 0.1 mm/1 mm; "
         "hard_h0.1/hard_h1 2100 GPa, 0.3, h 0.1 mm/1 mm; steel homogeneous; tin_2um TiN (400 GPa, "
         "0.25) 2 um; polymer_10um (3 GPa, 0.35) 10 um; three_layer TiN (400 GPa, 0.25) 2 um / Cr "
         "(279 GPa, 0.21) 1 um / Ni-P (170 GPa, 0.30) 5 um\n";
  csv << "# error = max |u - u_ref| / max |u_ref|; u_ref = dcfft (homogeneous) or frf-split at "
         "split tolerance 1e-13 on the full body\n";
  csv << "# hand = setup + one application; g0 regularized (tolerance 1e-13) for frf-spectral "
         "and frf-dcfft\n";
  csv << "# auto: predicted_error = choice + reduction effect; fastest = the hand row of least "
         "time_s with error <= tolerance, ratio = time_s / its time_s; fastest_cpu and ratio_cpu "
         "the same by cpu_s\n";
  csv << "# time_s = wall time, cpu_s = CPU time of the process (one thread), medians; auto: "
         "reduction_cpu_s and choice_cpu_s = the CPU time of reduce_body and choose_method in "
         "cpu_s\n";
  csv << checks;
  csv << "kind,case,n,tolerance,method,reduction,split_tolerance,alpha,reduction_effect,"
         "predicted_error,error,time_s,cpu_s,reduction_cpu_s,choice_cpu_s,fastest,fastest_s,"
         "fastest_error,ratio,fastest_cpu,"
         "ratio_cpu,meets_tolerance\n";
  return csv.str();
}

// The rows of one case on one grid: its hand-picked settings, then auto per tolerance.
std::string case_rows(const Case& c, std::ptrdiff_t n, int reps) {
  const Grid grid(n, n, side, side);
  const Field p = hertz_pressure(grid, p0, radius, Sampling::cell_average);
  const Field ref = reference(grid, c.body, p);
  std::string rows;
  std::vector<Measured> hand;
  for (const Setting& s : hand_picked(c.body)) {
    hand.push_back(measure(grid, c.body, s, p, ref, reps));
    const std::string row = hand_row(c.name, n, hand.back());
    std::cout << row << std::flush;
    rows += row;
  }
  for (const double tolerance : tolerances) {
    std::string row;
    try {
      row = auto_row(c.name, n, tolerance, run_auto(grid, c.body, p, ref, tolerance, reps), hand);
    } catch (const std::exception& e) {
      row = "# failed: auto " + c.name + " N = " + std::to_string(n) + " tolerance " +
            num(tolerance) + ": " + e.what() + "\n";
    }
    std::cout << row << std::flush;
    rows += row;
  }
  return rows;
}

bool selected(const std::vector<std::string>& names, const std::string& name) {
  return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

int main(int argc, char** argv) {
  coatfft::bench::CommandLine app{
      "The automatic method choice: tolerance against achieved error and time"};
  std::string out_path = std::string(COATFFT_SOURCE_DIR) + "/bench/results/auto_tolerance.csv";
  app.add("output", out_path, "CSV file").show_default();
  bool quick = false;
  app.flag("--quick", quick, "N = 128 only, one repetition (for trying)");
  int reps = 3;
  app.add("--reps", reps, "Repetitions per timing (1 with --quick)").show_default().positive();
  std::vector<std::string> names;
  app.add("--cases", names, "Cases (default: all)").comma_separated();
  std::vector<std::string> checks = {"soft_h0.1", "soft_h1", "hard_h0.1", "hard_h1"};
  app.add("--cross-check", checks, "Cases whose reference is checked by the Hankel route")
      .comma_separated()
      .show_default();
  if (const auto status = app.parse(argc, argv)) return *status;
  if (quick) reps = 1;
  try {
    std::vector<Case> cases = all_cases();
    std::string check_lines;
    for (const Case& c : cases)
      if (std::find(checks.begin(), checks.end(), c.name) != checks.end() &&
          !c.body.is_homogeneous())
        check_lines += cross_check(c);
    const std::string head = header(reps, quick, check_lines);
    std::cout << head << std::flush;
    std::string rows;
    for (Case& c : cases) {
      if (!selected(names, c.name)) continue;
      if (quick) c.sizes = {128};
      for (const std::ptrdiff_t n : c.sizes) rows += case_rows(c, n, reps);
    }
    const std::string tail = "# loadavg_end = " + loadavg() + "\n";
    std::cout << tail;
    bench::write_text_file(out_path, head + rows + tail);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench_auto_tolerance: " << e.what() << '\n';
    return 1;
  }
}
