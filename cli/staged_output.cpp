#include "cli/staged_output.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <string>

#include "core/detail/close_written.hpp"
#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::cli {

namespace fs = std::filesystem;

namespace {

// Paths in messages are quoted as file text is (io/input_file.hpp): escaped and shortened.
std::string quoted(const fs::path& path) {
  return io::quoted_excerpt(path.string());
}

// A hidden name beside `path`, unique to this process: ".NAME.partial-PID".
fs::path hidden_beside(const fs::path& path) {
  return path.parent_path() /
         detail::concat(".", path.filename().string(), ".partial-", ::getpid());
}

// `path` made absolute with "." and ".." resolved and no trailing separator, so that its parent
// and file name are the folder it lives in and its own name.
fs::path normalised(const fs::path& path) {
  fs::path p = fs::absolute(path).lexically_normal();
  if (p.has_parent_path() && p.filename().empty()) p = p.parent_path();
  return p;
}

void rename_or_throw(const fs::path& from, const fs::path& to, std::string_view what) {
  std::error_code ec;
  fs::rename(from, to, ec);
  COATFFT_REQUIRE(!ec, "cannot move ", what, " to ", quoted(to), ": ", ec.message());
}

// Where an existing output waits in the staging folder until the new set is in place.
std::string backup_name(const std::string& name) {
  std::string backup = ".old.";  // appended, not operator+: GCC 12 warns falsely on the latter
  backup += name;
  return backup;
}

std::vector<std::string> read_manifest(const fs::path& file) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(file, ec))) return names;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line) && names.size() < 64;) {
    // Only plain names of this folder: a list edited by hand cannot point elsewhere.
    if (!line.empty() && line.find('/') == std::string::npos && line[0] != '.')
      names.push_back(line);
  }
  return names;
}

// Whether `name` is `prefix` followed by the number of a process that no longer exists: a staging
// folder left by a coatfft that was killed (SIGKILL, or an MPI job's rank 0 ended by its launcher).
bool left_by_dead_process(const std::string& name, const std::string& prefix) {
  if (!name.starts_with(prefix)) return false;
  const std::string number = name.substr(prefix.size());
  if (number.empty() || number.size() > 9 ||
      !std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  const auto pid = static_cast<pid_t>(std::stol(number));
  return pid > 0 && ::kill(pid, 0) == -1 && errno == ESRCH;
}

// Removes the folders in `folder` named `prefix`PID whose process is gone (never a link, never
// another name).
void remove_dead_staging(const fs::path& folder, const std::string& prefix) {
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator();
       it.increment(ec)) {
    const fs::path& found = it->path();
    if (left_by_dead_process(found.filename().string(), prefix) &&
        fs::is_directory(fs::symlink_status(found, ec)))
      fs::remove_all(found, ec);
  }
}

}  // namespace

void check_output_target(const fs::path& target, std::string_view what,
                         const std::vector<fs::path>& inputs) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(target, ec);
  if (!fs::exists(status)) return;
  COATFFT_REQUIRE(fs::is_regular_file(status), what, " ", quoted(target), " exists and is ",
                  io::describe_file_type(status.type()), ": coatfft replaces only regular files");
  for (const fs::path& input : inputs) {
    COATFFT_REQUIRE(!fs::equivalent(target, input, ec), what, " ", quoted(target),
                    " is an input of this run (", quoted(input), "): choose another output");
  }
}

StagedOutput::StagedOutput(fs::path outdir, std::vector<std::string> names,
                           std::vector<fs::path> inputs)
    : names_(std::move(names)), inputs_(std::move(inputs)) {
  COATFFT_REQUIRE(!outdir.empty(), "output folder: empty path");
  outdir_ = normalised(outdir);
  names_.push_back(manifest_name);
  std::error_code ec;
  const fs::file_status status = fs::status(outdir_, ec);
  if (!fs::exists(status)) return;
  COATFFT_REQUIRE(fs::is_directory(status), "output folder ", quoted(outdir), " exists and is ",
                  io::describe_file_type(status.type()),
                  ": -o names the folder the run writes into");
  check_targets();
}

void StagedOutput::check_targets() const {
  const std::vector<std::string> previous = read_manifest(outdir_ / manifest_name);
  for (const std::string& name : names_) {
    const fs::path target = outdir_ / name;
    check_output_target(target, "output", inputs_);
    // A file that no coatfft run wrote (the manifest does not list it) is the user's, even when
    // it bears an output's name: it is never replaced.
    std::error_code ec;
    COATFFT_REQUIRE(name == manifest_name || !fs::exists(fs::symlink_status(target, ec)) ||
                        std::find(previous.begin(), previous.end(), name) != previous.end(),
                    "output ", quoted(target), " exists and no coatfft run wrote it (",
                    manifest_name,
                    " does not list it): it is left as it is; choose another "
                    "output folder, or move the file away");
  }
}

StagedOutput::~StagedOutput() {
  if (staging_.empty()) return;
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
  on_signal_.reset();
  if (committed_) return;
  for (const fs::path& parent : created_parents_) fs::remove(parent, ec);  // only if empty
}

void StagedOutput::stage() {
  // Missing parents of OUTDIR are created now (and removed again if the run fails), so that the
  // staging folder sits beside OUTDIR, on its file system: every final move is a rename.
  for (fs::path p = outdir_.parent_path(); !fs::exists(p) && p.has_relative_path();
       p = p.parent_path())
    created_parents_.push_back(p);
  // In an existing OUTDIR the staging folder goes inside it, on its file system even when OUTDIR
  // is a mount point, and needing no write access to its parent; otherwise it sits beside it and
  // becomes OUTDIR by one rename.
  std::error_code ec;
  // Staging folders of killed runs, inside OUTDIR or beside it, go first.
  if (fs::is_directory(outdir_, ec)) remove_dead_staging(outdir_, ".coatfft.partial-");
  remove_dead_staging(outdir_.parent_path(),
                      detail::concat(".", outdir_.filename().string(), ".partial-"));
  staging_ = fs::is_directory(outdir_, ec)
                 ? outdir_ / detail::concat(".coatfft.partial-", ::getpid())
                 : hidden_beside(outdir_);
  std::vector<fs::path> files;
  for (const std::string& name : names_) {
    files.push_back(staging_ / name);
    files.push_back(staging_ / backup_name(name));
  }
  std::vector<fs::path> folders{staging_};
  folders.insert(folders.end(), created_parents_.begin(), created_parents_.end());
  on_signal_ = std::make_unique<RemoveOnSignal>(files, folders);
  fs::create_directories(staging_, ec);
  COATFFT_REQUIRE(!ec, "cannot create ", quoted(staging_), ": ", ec.message());
}

std::vector<fs::path> StagedOutput::targets() const {
  std::vector<fs::path> paths{outdir_};
  for (const std::string& name : names_) paths.push_back(outdir_ / name);
  return paths;
}

fs::path StagedOutput::path(const std::string& name) {
  COATFFT_REQUIRE(std::find(names_.begin(), names_.end(), name) != names_.end(),
                  "StagedOutput: ", name, " is not one of the announced outputs");
  if (staging_.empty()) stage();
  return staging_ / name;
}

void StagedOutput::commit() {
  HoldSignals hold;  // a signal now would stop between two renames
  {
    std::ofstream manifest(path(manifest_name));
    for (const std::string& name : names_)
      if (name != manifest_name && fs::exists(staging_ / name)) manifest << name << '\n';
    detail::close_written(manifest, staging_ / manifest_name, "the list of outputs");
  }
  std::error_code ec;
  if (!fs::exists(fs::status(outdir_, ec))) {
    rename_or_throw(staging_, outdir_, "the outputs");
  } else {
    commit_into_existing();
    fs::remove_all(staging_, ec);
  }
  committed_ = true;
}

void StagedOutput::commit_into_existing() {
  check_targets();
  const std::vector<std::string> previous = read_manifest(outdir_ / manifest_name);
  std::vector<std::pair<std::string, bool>> done;  // name, whether an old file was set aside
  try {
    for (const std::string& name : names_) {
      if (!fs::exists(staging_ / name)) continue;
      const bool had_old = fs::exists(fs::symlink_status(outdir_ / name));
      if (had_old) rename_or_throw(outdir_ / name, staging_ / backup_name(name), name);
      done.emplace_back(name, had_old);
      rename_or_throw(staging_ / name, outdir_ / name, name);
    }
  } catch (const Error&) {
    // Undo in reverse order: the new file back to staging, the old one back in place.
    std::error_code ec;
    for (auto it = done.rbegin(); it != done.rend(); ++it) {
      if (!fs::exists(staging_ / it->first))
        fs::rename(outdir_ / it->first, staging_ / it->first, ec);
      if (it->second) fs::rename(staging_ / backup_name(it->first), outdir_ / it->first, ec);
    }
    throw;
  }
  std::vector<std::string> produced;
  for (const auto& entry : done) produced.push_back(entry.first);
  remove_stale(previous, produced);
}

void StagedOutput::remove_stale(const std::vector<std::string>& previous,
                                const std::vector<std::string>& produced) {
  for (const std::string& name : previous) {
    if (std::find(produced.begin(), produced.end(), name) != produced.end()) continue;
    std::error_code ec;
    if (fs::is_regular_file(fs::symlink_status(outdir_ / name, ec))) fs::remove(outdir_ / name, ec);
  }
}

StagedFile::StagedFile(fs::path target, std::string_view what, std::vector<fs::path> inputs)
    : target_(normalised(target)),
      what_(what),
      inputs_(std::move(inputs)),
      temporary_(hidden_beside(target_)),
      on_signal_({temporary_}, {}) {
  // The file is written beside its target: a missing folder is named as the user wrote it, not
  // as the hidden file that could not be opened.
  std::error_code ec;
  const fs::file_status folder = fs::status(target_.parent_path(), ec);
  COATFFT_REQUIRE(fs::exists(folder), what_, " ", quoted(target), ": the directory ",
                  quoted(target.parent_path()), " does not exist");
  COATFFT_REQUIRE(fs::is_directory(folder), what_, " ", quoted(target), ": ",
                  quoted(target.parent_path()), " is ", io::describe_file_type(folder.type()),
                  ", not a directory");
  check_output_target(target_, what_, inputs_);
}

StagedFile::~StagedFile() {
  std::error_code ec;
  if (!committed_) fs::remove(temporary_, ec);
}

void StagedFile::commit() {
  HoldSignals hold;
  check_output_target(target_, what_, inputs_);
  rename_or_throw(temporary_, target_, what_);
  committed_ = true;
}

void write_file_atomically(const fs::path& target, std::string_view what, const std::string& text,
                           const std::vector<fs::path>& inputs) {
  StagedFile file(target, what, inputs);
  {
    std::ofstream out(file.path(), std::ios::binary);
    COATFFT_REQUIRE(out.good(), "cannot write ", what, " ", quoted(file.path()));
    out << text;
    detail::close_written(out, file.path(), what);
  }
  file.commit();
}

}  // namespace coatfft::cli
