#pragma once
// What every validation table program shares: its command line (the Markdown file to write and
// --check), the --check bookkeeping (one line per failed row, exit status 1 on any failure) and
// the turning of exceptions into an exit status. A table's --check recomputes a fast subset of
// its rows and compares them with the independent reference at the tolerances the table promises;
// it is registered with ctest (tables/CMakeLists.txt), so a table and its test are one code path.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>
#include <utility>

namespace coatfft::tables {

/// The options every table program takes.
struct TableOptions {
  std::string output;  ///< the Markdown file written (not with --check)
  bool check = false;  ///< recompute a subset and compare; write nothing
};

/// Adds the positional `output` (default `default_output`, relative to the working directory)
/// and `--check` to `app`.
inline void add_table_options(CLI::App& app, TableOptions& options, std::string default_output) {
  options.output = std::move(default_output);
  app.add_option("output", options.output, "Markdown file to write")->capture_default_str();
  app.add_flag("--check", options.check,
               "Recompute a fast subset of the rows and compare them with the reference at the "
               "tests' tolerances (one line per failed row, exit status 1); writes nothing");
}

/// Runs `body` (which returns the exit status); an exception is printed as "program: message"
/// and gives exit status 1.
template <class Body>
int run_table(const char* program, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
}

/// The comparisons of a --check run.
class Checks {
 public:
  explicit Checks(std::string program) : program_(std::move(program)) {}

  /// One comparison on the table row `row`: passes if `ok`; otherwise prints
  /// "<program> --check: FAILED <row>: <what>" on one line of standard output.
  void expect(bool ok, const std::string& row, const std::string& what) {
    ++count_;
    if (ok) return;
    ++failed_;
    std::cout << program_ << " --check: FAILED " << row << ": " << what << "\n" << std::flush;
  }

  /// Prints the tally; returns 0 if every comparison passed, 1 otherwise (also 1 if none ran).
  int finish() const {
    std::cout << program_ << " --check: " << count_ - failed_ << " of " << count_
              << " comparisons passed\n";
    return failed_ == 0 && count_ > 0 ? 0 : 1;
  }

 private:
  std::string program_;
  int count_ = 0;
  int failed_ = 0;
};

}  // namespace coatfft::tables
