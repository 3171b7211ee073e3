#include "tables/table_program.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "core/detail/timing.hpp"

namespace coatfft::tables {

int table_main(int argc, char** argv, const TableProgram& program) {
  CLI::App app{program.description};
  std::string output = program.default_output;
  bool check = false;
  app.add_option("output", output, "Markdown file to write")->capture_default_str();
  app.add_flag("--check", check,
               "Recompute a fast subset of the rows and compare them with the reference at the "
               "tests' tolerances (one line per failed row, exit status 1); writes nothing");
  for (const TableOption& option : program.options) {
    if (option.text) app.add_option(option.name, *option.text, option.description);
    if (option.flag) app.add_flag(option.name, *option.flag, option.description);
  }
  CLI11_PARSE(app, argc, argv);
  try {
    return check ? program.check() : program.write(output);
  } catch (const std::exception& e) {
    std::cerr << program.name << ": " << e.what() << "\n";
    return 1;
  }
}

int write_table_file(const std::string& output, const std::string& markdown,
                     std::chrono::steady_clock::time_point start) {
  char run_time[64];
  std::snprintf(run_time, sizeof run_time, "\nRun time %.0f s.\n", detail::seconds_since(start));
  write_text_file(output, markdown + run_time);
  std::cout << "wrote " << output << "\n";
  return 0;
}

}  // namespace coatfft::tables
