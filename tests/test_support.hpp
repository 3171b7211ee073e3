#pragma once
// Small helpers several test files share, defined once so that the test files of one program can
// also be compiled together (unity builds).
#include <array>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

namespace {

/// |a - ref| / |ref|.
[[maybe_unused]] double rel_err(double a, double ref) {
  return std::abs(a - ref) / std::abs(ref);
}

/// The maximum of f on [lo, hi] (f unimodal there) by Brent's method (Boost.Math), to about
/// 1e-8 relative in the abscissa: {where, value}.
[[maybe_unused]] std::array<double, 2> maximise(const std::function<double(double)>& f, double lo,
                                                double hi) {
  const auto [x, minus_f] =
      boost::math::tools::brent_find_minima([&](double t) { return -f(t); }, lo, hi, 30);
  return {x, -minus_f};
}

/// The whole content of a file ("" when it cannot be read).
[[maybe_unused]] std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace
