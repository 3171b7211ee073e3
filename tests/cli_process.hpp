#pragma once
// Running the `coatfft` program from the CLI tests: its exit status and stderr, scratch files,
// scenes made from one edit of a good scene, and the check of a refusal (exit 2, one line, no
// output).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace coatfft_test {

namespace fs = std::filesystem;

struct ProcessResult {
  int status;
  std::string stderr_text;
};

/// The program with `args`; `environment` ("NAME=value ...") set for it alone.
inline ProcessResult run_coatfft(const std::string& args, const std::string& environment = "") {
  // ctest runs test cases in parallel: one stderr file per command line.
  const fs::path err =
      fs::temp_directory_path() /
      ("coatfft_test_stderr_" + std::to_string(std::hash<std::string>{}(environment + args)));
  const std::string command = environment + " " + std::string(COATFFT_EXE) + " " + args + " 2>" +
                              err.string() + " >/dev/null";
  const int raw = std::system(command.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text};
}

inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "coatfft_cli_tests";
  fs::create_directories(dir);
  return dir / name;
}

inline const char* kGoodScene = R"([grid]
nx = 33
ny = 33
lx = 3.0e-3
ly = 3.0e-3
[substrate]
material = "steel"
[pressure]
kind = "hertz"
p0 = 1.0e9
a = 1.0e-3
[method]
name = "dcfft"
)";

// A small sphere contact on steel (10 N, 32 x 32 cells).
inline const char* kSmallContactScene = R"([grid]
nx = 32
ny = 32
lx = 3.0e-3
ly = 3.0e-3
[substrate]
material = "steel"
[contact]
indenter = "sphere"
radius = 0.01
load = 10.0
)";

// TiN 2 um on steel by frf-spectral on 64^2 square cells: Spinu's (2021) pipeline at alpha = 2 is
// about 2.5 % off (docs/validation/frf_pipelines.md), so the run warns.
inline const char* kPipelineWarningScene = R"([grid]
nx = 64
ny = 64
lx = 4e-3
ly = 4e-3
[substrate]
material = "steel"
[[coating]]
material = "titanium_nitride"
thickness = 2e-6
[pressure]
kind = "hertz"
p0 = 1e9
a = 1e-3
[method]
name = "frf-spectral"
)";

// Writes `base` with `from` replaced by `to` (the one change under test) to NAME.toml.
inline fs::path write_scene(const std::string& base, const std::string& name,
                            const std::string& from, const std::string& to) {
  std::string text = base;
  if (!from.empty()) {
    const auto pos = text.find(from);
    REQUIRE(pos != std::string::npos);
    text.replace(pos, from.size(), to);
  }
  const fs::path path = scratch(name + ".toml");
  std::ofstream(path) << text;
  return path;
}

// `base` with `from` replaced by `to` run by `coatfft run` into a fresh NAME_out, which is
// returned; the run must succeed.
inline fs::path run_scene_ok(const std::string& base, const std::string& name,
                             const std::string& from = "", const std::string& to = "") {
  const fs::path out = scratch(name + "_out");
  fs::remove_all(out);
  const auto result =
      run_coatfft("run " + write_scene(base, name, from, to).string() + " -o " + out.string());
  INFO(result.stderr_text);
  REQUIRE(result.status == 0);
  return out;
}

// The summary.json of an output folder.
// The raw shape tuple of a .npy header, e.g. "(2, 6, 33, 33)".
inline std::string npy_shape(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string header(256, '\0');
  in.read(header.data(), 256);
  const auto b = header.find("'shape': (");
  const auto e = header.find(')', b);
  return header.substr(b + 9, e - b - 8);
}

// The values of a float64 .npy file, in file order.
inline std::vector<double> npy_values(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t start = all.find('\n') + 1;
  std::vector<double> v((all.size() - start) / 8);
  std::memcpy(v.data(), all.data() + start, v.size() * 8);
  return v;
}

// The lines of a text file.
inline std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline nlohmann::json read_summary(const fs::path& out) {
  nlohmann::json summary;
  std::ifstream(out / "summary.json") >> summary;
  return summary;
}

inline fs::path scene_with(const std::string& name, const std::string& from,
                           const std::string& to) {
  return write_scene(kGoodScene, name, from, to);
}

// A scene edit that must be refused: exit 2, one line on stderr mentioning `must_mention`, and
// no output folder. Returns the run, for what else its message must say.
struct BadCase {
  const char* name;
  std::string from, to;
  const char* must_mention;
};

inline ProcessResult check_refused(const std::string& base, const BadCase& c) {
  INFO(c.name);
  const fs::path scene = write_scene(base, c.name, c.from, c.to);
  const fs::path out = scratch(std::string(c.name) + "_out");
  fs::remove_all(out);
  const auto result = run_coatfft("run " + scene.string() + " -o " + out.string());
  INFO(result.stderr_text);
  CHECK(result.status == 2);
  CHECK(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n') == 1);
  CHECK(result.stderr_text.find(c.must_mention) != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  return result;
}

// The peak resident set of one `coatfft ARGS` run [MiB], from wait4 on the process itself (the
// shell execs it, so the child is coatfft), and its exit status.
struct MeasuredRun {
  int status = -1;
  double peak_rss_mib = 0.0;
};

inline MeasuredRun run_coatfft_measured(const std::string& args) {
  const std::string command =
      "exec " + std::string(COATFFT_EXE) + " " + args + " 2>/dev/null >/dev/null";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int raw = 0;
  struct rusage usage {};
  wait4(pid, &raw, 0, &usage);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, static_cast<double>(usage.ru_maxrss) / 1024.0};
}

// Every file under `dir` (names and contents, hidden ones included), for "byte-identical" checks.
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    std::string content = entry.is_directory() ? "<folder>" : "";
    if (entry.is_regular_file()) {
      std::ifstream in(entry.path(), std::ios::binary);
      content.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    files[fs::relative(entry.path(), dir).string()] = content;
  }
  return files;
}

}  // namespace coatfft_test
