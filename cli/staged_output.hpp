#pragma once
// Output that cannot destroy (docs/scene_format.md, "Output folder"). A run's files are written
// into a hidden staging folder (inside an existing OUTDIR, beside a new one) and appear in OUTDIR
// together, once all of them are complete; a failure or an interruption at any point leaves OUTDIR
// as it was. coatfft replaces only regular files that an earlier run wrote (listed in
// OUTDIR/.coatfft-outputs) and this run produces again, never an input of the run or a file of
// the user's, and removes only files that an earlier run wrote and this run does not produce.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/signal_cleanup.hpp"

namespace coatfft::cli {

/// Refuses (InvalidArgument, naming `what`) a `target` to be replaced by a new file: it must be
/// absent or a regular file (not a folder, device, FIFO or symbolic link), and none of `inputs`.
void check_output_target(const std::filesystem::path& target, std::string_view what,
                         const std::vector<std::filesystem::path>& inputs);

/// The files of one run into the folder OUTDIR.
class StagedOutput {
 public:
  /// Checks OUTDIR (absent or a folder) and every name in it (check_output_target) before any
  /// work is done; `inputs` are the run's input files (scene, pressure, height map, wisdom).
  StagedOutput(std::filesystem::path outdir, std::vector<std::string> names,
               std::vector<std::filesystem::path> inputs);
  ~StagedOutput();  ///< removes the staging folder (and any folder it created) unless committed
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Where to write the output `name` (one of the names given to the constructor).
  std::filesystem::path path(const std::string& name);
  /// OUTDIR and the paths of its outputs (for checks that no other file of the run is one).
  std::vector<std::filesystem::path> targets() const;
  /// Moves every output into OUTDIR at once (a new OUTDIR: one rename of the staging folder; an
  /// existing one: file by file, undone on any failure), then removes stale outputs.
  void commit();

  /// Name of the list of outputs kept in OUTDIR.
  static constexpr const char* manifest_name = ".coatfft-outputs";

 private:
  /// Every output name in OUTDIR: absent, or a regular file an earlier run wrote (listed in the
  /// manifest) and none of the inputs; refused (InvalidArgument) otherwise.
  void check_targets() const;
  void stage();
  void commit_into_existing();
  void remove_stale(const std::vector<std::string>& previous,
                    const std::vector<std::string>& produced);

  std::filesystem::path outdir_;
  std::vector<std::string> names_;
  std::vector<std::filesystem::path> inputs_;
  std::filesystem::path staging_;
  std::vector<std::filesystem::path> created_parents_;  ///< deepest first
  std::unique_ptr<RemoveOnSignal> on_signal_;
  bool committed_ = false;
};

/// One output file (`coatfft frf -o FILE`, the FFTW wisdom file): written to a hidden file beside
/// it and renamed over it when complete.
class StagedFile {
 public:
  StagedFile(std::filesystem::path target, std::string_view what,
             std::vector<std::filesystem::path> inputs);
  ~StagedFile();  ///< removes the temporary file unless committed
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::filesystem::path& path() const { return temporary_; }
  void commit();

 private:
  std::filesystem::path target_;
  std::string what_;
  std::vector<std::filesystem::path> inputs_;
  std::filesystem::path temporary_;
  RemoveOnSignal on_signal_;
  bool committed_ = false;
};

/// Writes `text` to `target` through a StagedFile.
void write_file_atomically(const std::filesystem::path& target, std::string_view what,
                           const std::string& text,
                           const std::vector<std::filesystem::path>& inputs);

}  // namespace coatfft::cli
