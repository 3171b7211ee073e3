#pragma once
// A benchmark's command line: CLI11 behind a small interface compiled once (command_line.cpp).
// CLI11 is header-only, and each source that declares and parses options with it spends seconds
// compiling its parser; sixteen benchmarks did so each.
#include <cstddef>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace coatfft::bench {

class CommandLine {
 public:
  /// The settings of one option beyond its name, variable and description (CLI11's meaning).
  class Option {
   public:
    explicit Option(CLI::Option* option) : option_(option) {}
    Option& required();
    Option& show_default();     ///< --help shows the variable's value before parsing
    Option& comma_separated();  ///< a list given as 1,2,3
    Option& positive();         ///< every value > 0
    Option& hidden();           ///< left out of --help (options for the program's own use)
    Option& excludes(const Option& other);
    /// Every value in [lo, hi].
    template <class T>
    Option& range(T lo, T hi) {
      if constexpr (std::is_integral_v<T>)
        return integer_range(static_cast<long long>(lo), static_cast<long long>(hi));
      else
        return real_range(static_cast<double>(lo), static_cast<double>(hi));
    }

   private:
    Option& integer_range(long long lo, long long hi);
    Option& real_range(double lo, double hi);
    CLI::Option* option_;
  };

  explicit CommandLine(const std::string& description);
  ~CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  /// An option ("--reps") or a positional argument ("output") stored in `value`.
  Option& add(const std::string& name, std::string& value, const std::string& description);
  Option& add(const std::string& name, int& value, const std::string& description);
  Option& add(const std::string& name, long& value, const std::string& description);
  Option& add(const std::string& name, double& value, const std::string& description);
  Option& add(const std::string& name, std::vector<int>& value, const std::string& description);
  Option& add(const std::string& name, std::vector<long>& value, const std::string& description);
  Option& add(const std::string& name, std::vector<double>& value, const std::string& description);
  Option& add(const std::string& name, std::vector<std::string>& value,
              const std::string& description);
  /// A flag: `value` becomes true when given.
  Option& flag(const std::string& name, bool& value, const std::string& description);

  /// The first argument that is not an option, and everything after it, are left to rest().
  void leave_the_rest();
  std::vector<std::string> rest() const;
  std::string help() const;

  /// Parses the command line. Empty: go on; otherwise the exit status to return from main, after
  /// --help was printed or a parse error was reported as CLI11 reports it.
  std::optional<int> parse(int argc, char** argv);

 private:
  Option& keep(CLI::Option* option);
  std::unique_ptr<CLI::App> app_;
  std::deque<Option> options_;  // stable addresses for the references handed out
};

}  // namespace coatfft::bench
