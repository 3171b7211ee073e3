#pragma once
// What every validation table program shares: its command line (the Markdown file to write and
// --check), the --check bookkeeping (one line per failed row, exit status 1 on any failure), the
// writing of its files and the turning of exceptions into an exit status. A table's --check
// recomputes a fast subset of its rows and compares them with the independent reference at the
// tolerances the table promises; it is registered with ctest (tables/CMakeLists.txt), so a table
// and its test are one code path.
#include <chrono>
#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "core/detail/write_text_file.hpp"
#include "core/error.hpp"

namespace coatfft::tables {

/// A further option of a table's write mode: a value (`--csv PATH`, into `text`) or a flag
/// (`--quick`, into `flag`); exactly one of the two is set.
struct TableOption {
  const char* name;         ///< "--csv"
  const char* description;  ///< one line for --help
  std::string* text = nullptr;
  bool* flag = nullptr;
};

/// A table program: what main() hands to table_main.
struct TableProgram {
  const char* name;            ///< "hard_cases_table": the prefix of its messages
  const char* description;     ///< one line for --help
  const char* default_output;  ///< the Markdown file written, relative to the working directory
  std::function<int()> check;  ///< --check: recompute a subset, compare; the exit status
  std::function<int(const std::string& output)> write;  ///< write the table; the exit status
  std::vector<TableOption> options = {};                ///< further options of the write mode
};

/// The main() of a table program: `program.name [OUTPUT] [--check] [further options]`. Parse
/// errors exit as CLI11 says; an exception from check or write is printed as "name: message" and
/// gives exit status 1. Compiled once (table_program.cpp) for every table: CLI11's parser costs
/// several seconds of compilation in each source that uses it.
int table_main(int argc, char** argv, const TableProgram& program);

/// Writes `text` to `path` (creating its folder); throws coatfft::Error naming the path.
using detail::write_text_file;

/// The end of a table's write mode: `markdown`, with a last line "Run time N s." measured from
/// `start`, written to `output`, and "wrote OUTPUT" on standard output. Returns 0, the exit status.
int write_table_file(const std::string& output, const std::string& markdown,
                     std::chrono::steady_clock::time_point start);

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
