// End-to-end tests of the speed-against-error programs: bench_sweep on its --tiny sweep must run,
// write a complete CSV with the machine headers, and its errors must agree with independent facts
// (direct summation, the 1.5% bound of Spinu (2021) for DC-FFT at 32^2, convergence in N and in
// alpha); bench_figures and bench_peak_rss must write what the scripts read. No timing is asserted
// (house rule); only that the timing and memory columns are filled in.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Runs `program` (one of the COATFFT_BENCH_*_EXE paths) with `args`, output to `log`.
int run(const char* program, const std::string& args, const fs::path& log) {
  const std::string command = std::string(program) + " " + args + " >" + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("coatfft_test_bench_sweep_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Runs scripts/SCRIPT_AND_ARGS with Debian's /usr/bin/python3 (numpy, matplotlib; installed by
// scripts/setup.sh), appending its output to log; returns its exit status.
int python(const std::string& script_and_args, const fs::path& log) {
  const std::string command = "/usr/bin/python3 " + std::string(COATFFT_SOURCE_DIR) + "/scripts/" +
                              script_and_args + " >>" + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

struct Row {
  std::string method;
  long n;
  double alpha;
  std::string g0;
  double g0_tol, setup_s, apply_s, rss_mb, max_err, rms_err, coeff_s;
};

}  // namespace

TEST_CASE("bench_sweep --tiny writes a complete, consistent CSV", "[bench_sweep]") {
  const fs::path dir = scratch_dir("tiny");
  const fs::path csv = dir / "sweep.csv";
  REQUIRE(run(COATFFT_BENCH_SWEEP_EXE, "--tiny --output " + csv.string(), dir / "log.txt") == 0);
  REQUIRE(fs::exists(csv));

  std::ifstream in(csv);
  std::string line;
  std::map<std::string, std::string> headers;
  std::vector<Row> rows;
  bool seen_columns = false;
  while (std::getline(in, line)) {
    if (line.rfind("# ", 0) == 0) {
      const auto eq = line.find(" = ");
      if (eq != std::string::npos) headers[line.substr(2, eq - 2)] = line.substr(eq + 3);
      continue;
    }
    if (!seen_columns) {
      CHECK(line ==
            "case,method,N,alpha,g0,g0_tol,sampling,setup_s,apply_s_median,peak_rss_mb,max_err,"
            "rms_err,coeff_s");
      seen_columns = true;
      continue;
    }
    const auto f = split(line);
    REQUIRE(f.size() == 13);
    CHECK(f[0] == "hertz_homogeneous");
    CHECK(f[6] == "centre");
    rows.push_back({f[1], std::stol(f[2]), std::stod(f[3]), f[4], std::stod(f[5]), std::stod(f[7]),
                    std::stod(f[8]), std::stod(f[9]), std::stod(f[10]), std::stod(f[11]),
                    std::stod(f[12])});
  }
  for (const char* key : {"cpu", "compiler", "flags", "fftw", "threads", "date", "planning"}) {
    INFO("header key " << key);
    CHECK(headers.count(key) == 1);
  }
  CHECK(headers["fftw"].find("fftw-3") == 0);
  CHECK(headers.count("total_wall_s") == 1);  // the footer: the sweep ran to its end

  // --tiny: N in {32, 64}; direct, dcfft and each FRF pipeline at alpha 2 and 4 with two g(0).
  auto find = [&](const std::string& method, long n, double alpha, const std::string& g0) {
    for (const Row& r : rows)
      if (r.method == method && r.n == n && r.alpha == alpha && r.g0 == g0) return r;
    FAIL("no row " << method << " N = " << n << " alpha = " << alpha << " g0 = " << g0);
    return Row{};
  };
  for (const Row& r : rows) {
    INFO(r.method << " N = " << r.n << " alpha = " << r.alpha << " g0 = " << r.g0);
    CHECK(std::isfinite(r.max_err));
    CHECK(r.rms_err <= r.max_err);
    CHECK(r.setup_s >= 0.0);
    CHECK(r.coeff_s >= 0.0);
    CHECK(r.coeff_s <= r.setup_s);
    CHECK(r.apply_s > 0.0);
    // A child that built an operator holds at least its own code and data: > 1 MB.
    CHECK(r.rss_mb > 1.0);
  }
  for (long n : {32L, 64L}) {
    const Row direct = find("direct", n, 0.0, "none");
    const Row dcfft = find("dcfft", n, 0.0, "none");
    // DC-FFT is the direct sum to rounding (~1e-15 of u); the CSV keeps 6 digits.
    CHECK(dcfft.max_err == Approx(direct.max_err).epsilon(1e-5));
    CHECK(dcfft.rms_err == Approx(direct.rms_err).epsilon(1e-5));
  }
  // Spinu (2021), section 5: "even with a coarse mesh of 32 x 32, the error is kept under 1.5%";
  // our centre-sampled Hertz load gives 3.5e-3 against the closed form (docs/
  // validation/hertz_dcfft.md), and the discretisation error must shrink from 32 to 64.
  CHECK(find("dcfft", 32, 0.0, "none").max_err < 1.5e-2);
  CHECK(find("dcfft", 64, 0.0, "none").max_err < 0.5 * find("dcfft", 32, 0.0, "none").max_err);
  // FRF pipelines: periodicity error ~ 1/alpha (docs/theory.md 4.3: 2.5% of u(0) at alpha = 2,
  // 1.3% at alpha = 4 for L = 3a), nearly independent of N.
  for (const char* method : {"frf-spectral", "frf-dcfft"})
    for (long n : {32L, 64L}) {
      INFO(method << " N = " << n);
      const double e2 = find(method, n, 2.0, "regularized").max_err;
      const double e4 = find(method, n, 4.0, "regularized").max_err;
      CHECK(e2 > 1.5e-2);
      CHECK(e2 < 4e-2);
      CHECK(e4 < 0.75 * e2);
      // g(0) by quadrature to 1e-4 shifts u by a constant of at most ~1e-4 of g(0)'s share of
      // u(0) (less than u(0) itself), so the max error moves by less than 1e-4.
      CHECK(std::abs(find(method, n, 2.0, "quadrature").max_err - e2) < 1e-4);
    }
}

TEST_CASE("bench_figures --tiny writes the data of the figures of Spinu (2021)", "[bench_sweep]") {
  const fs::path dir = scratch_dir("figures");
  REQUIRE(run(COATFFT_BENCH_FIGURES_EXE, dir.string() + " --tiny", dir / "log.txt") == 0);
  for (const char* name : {"fig2a_dcfft_error_field.csv", "fig2b_dcfft_error_vs_n.csv",
                           "fig3a_frf_alpha.csv", "fig3b_frf_g0.csv"}) {
    INFO(name);
    CHECK(fs::exists(dir / name));
  }
  // Figure 2(a) holds the 64 x 64 error field: 64^2 data lines.
  std::ifstream in(dir / "fig2a_dcfft_error_field.csv");
  std::string line;
  int data = 0;
  double max_abs = 0.0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    ++data;
    max_abs = std::max(max_abs, std::abs(std::stod(split(line)[2])));
  }
  CHECK(data == 64 * 64);
  // Same bound as the sweep's dcfft row at N = 64 (8.6e-4, docs/validation/hertz_dcfft.md).
  CHECK(max_abs < 1e-3);
  CHECK(max_abs > 1e-4);
}

TEST_CASE(
    "bench_peak_rss reports a child's exit code and memory, and bench_sweep refuses bad input",
    "[bench_sweep]") {
  const fs::path dir = scratch_dir("rss");
  CHECK(run(COATFFT_BENCH_PEAK_RSS_EXE, "/bin/sh -c 'exit 3'", dir / "log1.txt") == 3);
  REQUIRE(run(COATFFT_BENCH_PEAK_RSS_EXE, "/bin/true", dir / "log2.txt") == 0);
  const std::string text = slurp(dir / "log2.txt");
  CHECK(text.find("peak_rss_mb = ") != std::string::npos);
  // An unknown option, a list item that is not a number and an unknown method are refused before
  // any work, with a message naming them.
  CHECK(run(COATFFT_BENCH_SWEEP_EXE, "--no-such-option", dir / "log3.txt") != 0);
  CHECK(slurp(dir / "log3.txt").find("--no-such-option") != std::string::npos);
  CHECK(run(COATFFT_BENCH_SWEEP_EXE, "--tiny --grids 32,1k", dir / "log4.txt") != 0);
  CHECK(slurp(dir / "log4.txt").find("1k") != std::string::npos);
  CHECK(run(COATFFT_BENCH_SWEEP_EXE, "--tiny --methods frf-splitt", dir / "log5.txt") != 0);
  CHECK(slurp(dir / "log5.txt").find("\"frf-splitt\" is not one of") != std::string::npos);
}

// scripts/plot_pareto.py and scripts/markdown_blocks.py (Debian's /usr/bin/python3 with
// matplotlib, installed by scripts/setup.sh) turn the CSVs into the PNGs and the generated blocks
// of docs/benchmarks.md: on the tiny sweep they must write one plot per case, the "fastest method
// for a target error" table, keep the text around the markers, and refuse a doc without markers.
TEST_CASE("plot_pareto.py and markdown_blocks.py fill the docs' generated blocks",
          "[bench_sweep]") {
  const fs::path dir = scratch_dir("scripts");
  const fs::path csv = dir / "sweep.csv";
  REQUIRE(run(COATFFT_BENCH_SWEEP_EXE, "--tiny --output " + csv.string(), dir / "log.txt") == 0);
  const fs::path doc = dir / "doc.md";
  {
    std::ofstream out(doc);
    out << "before\n<!-- BEGIN GENERATED by scripts/plot_pareto.py: do not edit by hand -->\nold\n"
           "<!-- END GENERATED -->\nmiddle\n<!-- BEGIN GENERATED t -->\n<!-- END GENERATED t -->\n"
           "after\n";
  }
  const auto python = [&](const std::string& args) { return ::python(args, dir / "python.txt"); };
  REQUIRE(python("plot_pareto.py " + csv.string() + " --outdir " + dir.string() + " --markdown " +
                 doc.string()) == 0);
  CHECK(fs::file_size(dir / "pareto_hertz_homogeneous.png") > 1000);
  REQUIRE(python("markdown_blocks.py " + doc.string() + " t " + csv.string() +
                 " --columns case,method,N,max_err") == 0);
  const std::string text = slurp(doc);
  INFO(text);
  CHECK(text.rfind("before\n", 0) == 0);
  CHECK(text.find("\nmiddle\n") != std::string::npos);
  CHECK(text.size() > 7);
  CHECK(text.substr(text.size() - 7) == "\nafter\n");
  CHECK(text.find("\nold\n") == std::string::npos);
  CHECK(text.find("#### Fastest method for a target max error") != std::string::npos);
  CHECK(text.find("| hertz_homogeneous | 1e-02 |") != std::string::npos);
  CHECK(text.find("| case | method | N | max_err |") != std::string::npos);
  CHECK(text.find("| hertz_homogeneous | dcfft | 32 |") != std::string::npos);
  // A doc without the block's markers is refused (non-zero exit), not appended to.
  const fs::path bare = dir / "bare.md";
  std::ofstream(bare) << "no markers\n";
  CHECK(python("markdown_blocks.py " + bare.string() + " t " + csv.string()) != 0);
  CHECK(slurp(bare) == "no markers\n");
  CHECK(python("markdown_blocks.py " + doc.string() + " t " + csv.string() + " --columns nope") !=
        0);
}

// The views of markdown_blocks.py that compute their tables (docs/validation.md's coated
// convergence table; docs/benchmarks.md's direct-vs-DC-FFT table): on a tiny sweep of two
// coated cases and on a small bench_dcfft CSV they must write the tables with the measured
// numbers, and refuse a CSV without the rows they need.
TEST_CASE("markdown_blocks.py renders the coated convergence and direct speed-up tables",
          "[bench_sweep]") {
  const fs::path dir = scratch_dir("views");
  const fs::path log = dir / "python.txt";
  const fs::path csv = dir / "sweep.csv";
  REQUIRE(run(COATFFT_BENCH_SWEEP_EXE,
              "--tiny --cases coated_soft_h1,coated_hard_h0.1 --output " + csv.string(),
              dir / "log.txt") == 0);
  const fs::path doc = dir / "doc.md";
  std::ofstream(doc) << "before\n<!-- BEGIN GENERATED coated -->\nold\n<!-- END GENERATED coated "
                        "-->\nmiddle\n<!-- BEGIN GENERATED direct -->\n<!-- END GENERATED direct "
                        "-->\nafter\n";
  REQUIRE(python("markdown_blocks.py " + doc.string() + " coated " + csv.string() +
                     " --view coated-convergence",
                 log) == 0);

  // The sweep's own max_err of the coated_soft_h1 frf-split row at N = 32, as the table shows it.
  std::ifstream in(csv);
  std::string line;
  std::string split_32;
  while (std::getline(in, line))
    if (line.rfind("coated_soft_h1,frf-split,32,", 0) == 0) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.2e", std::stod(split(line)[10]));
      split_32 = buf;
    }
  REQUIRE_FALSE(split_32.empty());
  std::string text = slurp(doc);
  INFO(text);
  CHECK(text.rfind("before\n<!-- BEGIN GENERATED coated -->\n", 0) == 0);
  CHECK(text.find("\nold\n") == std::string::npos);
  CHECK(text.find("| case | method | alpha | N = 32 | N = 64 | order (last two N) | alpha x error "
                  "at largest N |") != std::string::npos);
  CHECK(text.find("| coated_soft_h1 | frf-split |  | " + split_32 + " | ") != std::string::npos);
  for (const std::string row :
       {"| coated_soft_h1 | frf-spectral | 2 | ", "| coated_soft_h1 | frf-dcfft | 4 | ",
        "| coated_hard_h0.1 | frf-split |  | ", "| coated_hard_h0.1 | frf-dcfft | 2 | "})
    CHECK(text.find(row) != std::string::npos);
  CHECK(text.find("- coated_hard_h0.1: bonded coating E_c/E_s = 10.0") != std::string::npos);
  CHECK(text.find("g(0) by quadrature") != std::string::npos);

  const fs::path dcfft = dir / "dcfft.csv";
  std::ofstream(dcfft) << "# date = today\n# cpu = cpu\n# compiler = cc\n"
                          "method,N,threads,plan_ms,apply_ms_min,apply_ms_median,ratio,rel_err_l2,"
                          "rel_err_inf\n"
                          "dcfft,256,1,5,1,1.2,0.6,1e-16,6e-16\n"
                          "direct,32,1,0,0.9,1.0,80,0,0\n"
                          "dcfft_small,32,1,1,0.012,0.0125,0,1e-15,3.4e-15\n";
  REQUIRE(python("markdown_blocks.py " + doc.string() + " direct " + dcfft.string() +
                     " --view direct-speedup",
                 log) == 0);
  text = slurp(doc);
  CHECK(text.find("| 32^2 | 1 | 0.0125 | **80x** | 3.4e-15 |") != std::string::npos);
  CHECK(text.find("| 256^2") == std::string::npos);
  CHECK(text.substr(text.size() - 7) == "\nafter\n");

  // Refused, doc untouched: a sweep without coated cases, a dcfft CSV without direct rows, and
  // --columns with a computed view.
  const std::string before = slurp(doc);
  const fs::path homogeneous = dir / "homogeneous.csv";
  std::ofstream(homogeneous) << "case,method,N,alpha,g0,max_err\nhertz_homogeneous,dcfft,32,0,none,"
                                "0.0035\n";
  CHECK(python("markdown_blocks.py " + doc.string() + " coated " + homogeneous.string() +
                   " --view coated-convergence",
               log) != 0);
  CHECK(python("markdown_blocks.py " + doc.string() + " direct " + csv.string() +
                   " --view direct-speedup",
               log) != 0);
  CHECK(python("markdown_blocks.py " + doc.string() + " coated " + csv.string() +
                   " --view coated-convergence --columns case",
               log) != 0);
  CHECK(slurp(doc) == before);
}
