#pragma once
// Opening the CLI's input files (scenes, pressure and height maps, FFTW wisdom) with care: only
// regular files are opened, so that a path naming /dev/zero, a FIFO, a directory or a socket,
// directly or through a symbolic link, ends with a one-line message instead of blocking or
// streaming forever; and a file's size is checked against a limit before anything is read or
// allocated. Every refusal is a coatfft::InvalidArgument whose message starts with the path:
//
//   "PATH: cannot open: No such file or directory"           (any error of the file system)
//   "PATH: not a regular file (a directory)"                  (or a character device, a FIFO, ...)
//   "PATH: 5000000 bytes, more than the limit of 1048576 bytes for a scene file"
//
// `what` names the kind of file in the last message, with its article ("a scene file").
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace coatfft::io {

/// Text from a file as echoed in a message: in double quotes, with '"', '\\' and non-printable
/// bytes escaped ("\\x01"), and at most 80 characters inside the quotes ("..." ends a longer
/// text; an escape is never cut in two).
std::string quoted_excerpt(std::string_view text);

/// Default limit on the size of a .npy or CSV file: 4 GiB (a 16384 x 16384 .npy takes 2 GiB).
inline constexpr std::uintmax_t kMaxArrayFileBytes = std::uintmax_t{4} << 30;

/// "a directory", "a character device", "a FIFO", ...: what a path names instead of a regular
/// file, for messages.
const char* describe_file_type(std::filesystem::file_type type);

/// Checks, without opening anything, that `path` names a regular file (symbolic links are
/// followed) of at most `max_bytes` bytes, and returns its size. For a reader that hands the
/// path to another library (FFTW's wisdom import) or reads the file piece by piece (InputFile).
std::uintmax_t require_regular_input(const std::filesystem::path& path, std::string_view what,
                                     std::uintmax_t max_bytes);

/// The whole content of the regular file `path`, of at most `max_bytes` bytes: refused as
/// require_regular_input() does before the file is opened, then read in one piece. A file that
/// changes size while it is read is refused too ("PATH: the file changed while being read").
std::string read_input_file(const std::filesystem::path& path, std::string_view what,
                            std::uintmax_t max_bytes);

/// A regular file open for reading piece by piece, for readers that must not hold the whole file
/// twice (.npy): the constructor refuses as require_regular_input() does, before opening, and
/// checks again on the opened file (which is opened without blocking).
class InputFile {
 public:
  InputFile(const std::filesystem::path& path, std::string_view what, std::uintmax_t max_bytes);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// The size of the file in bytes, as found when it was opened.
  std::uintmax_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

  /// Reads exactly `count` bytes at the current position into `out`; throws InvalidArgument
  /// ("PATH: the file changed while being read") if the file ends first.
  void read_exact(void* out, std::size_t count);

  /// Reads exactly `count` bytes at `offset` into `out`, the current position unchanged (for a
  /// reader that seeks: libzip's); throws as read_exact() does.
  void read_at(std::uintmax_t offset, void* out, std::size_t count);

  /// True when no byte follows the current position (reads one byte to find out).
  bool at_end();

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
};

}  // namespace coatfft::io
