#include "bench/command_line.hpp"

#include <CLI/CLI.hpp>

namespace coatfft::bench {

using Option = CommandLine::Option;

Option& Option::required() {
  option_->required();
  return *this;
}

Option& Option::show_default() {
  option_->capture_default_str();
  return *this;
}

Option& Option::comma_separated() {
  option_->delimiter(',');
  return *this;
}

Option& Option::positive() {
  option_->check(CLI::PositiveNumber);
  return *this;
}

Option& Option::hidden() {
  option_->group("");
  return *this;
}

Option& Option::excludes(const Option& other) {
  option_->excludes(other.option_);
  return *this;
}

Option& Option::integer_range(long long lo, long long hi) {
  option_->check(CLI::Range(lo, hi));
  return *this;
}

Option& Option::real_range(double lo, double hi) {
  option_->check(CLI::Range(lo, hi));
  return *this;
}

CommandLine::CommandLine(const std::string& description)
    : app_(std::make_unique<CLI::App>(description)) {}

CommandLine::~CommandLine() = default;

Option& CommandLine::keep(CLI::Option* option) {
  return options_.emplace_back(option);
}

Option& CommandLine::add(const std::string& name, std::string& value, const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, int& value, const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, long& value, const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, double& value, const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, std::vector<int>& value, const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, std::vector<long>& value, const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, std::vector<double>& value,
                         const std::string& d) {
  return keep(app_->add_option(name, value, d));
}
Option& CommandLine::add(const std::string& name, std::vector<std::string>& value,
                         const std::string& d) {
  return keep(app_->add_option(name, value, d));
}

Option& CommandLine::flag(const std::string& name, bool& value, const std::string& d) {
  return keep(app_->add_flag(name, value, d));
}

void CommandLine::leave_the_rest() {
  app_->prefix_command();
}

std::vector<std::string> CommandLine::rest() const {
  return app_->remaining();
}

std::string CommandLine::help() const {
  return app_->help();
}

std::optional<int> CommandLine::parse(int argc, char** argv) {
  try {
    app_->parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app_->exit(e);
  }
  return std::nullopt;
}

}  // namespace coatfft::bench
