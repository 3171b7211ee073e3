#include "io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "core/error.hpp"

namespace coatfft::io {

namespace fs = std::filesystem;

namespace {

void check_size(const fs::path& path, std::uintmax_t size, std::string_view what,
                std::uintmax_t max_bytes) {
  COATFFT_REQUIRE(size <= max_bytes, path.string(), ": ", size, " bytes, more than the limit of ",
                  max_bytes, " bytes for ", what);
}

// "PATH: cannot open: Permission denied", from errno as the failed call left it.
[[noreturn]] void throw_system(const fs::path& path, const char* doing) {
  const std::string reason = std::generic_category().message(errno);
  throw InvalidArgument(path.string() + ": " + doing + ": " + reason);
}

constexpr std::size_t max_echoed = 80;

// One byte of text from a file as written in a message: '"', '\' and non-printable bytes escaped.
std::string escaped(char c) {
  constexpr char kHex[] = "0123456789abcdef";
  const auto byte = static_cast<unsigned char>(c);
  if (c == '"' || c == '\\') return {'\\', c};
  if (c == '\n') return "\\n";
  if (c == '\t') return "\\t";
  if (c == '\r') return "\\r";
  if (byte < 0x20 || byte >= 0x7f) return {'\\', 'x', kHex[byte >> 4], kHex[byte & 15]};
  return {c};
}

[[noreturn]] void throw_changed(const fs::path& path) {
  throw InvalidArgument(path.string() + ": the file changed while being read");
}

}  // namespace

// Text from a file as echoed in a message: in double quotes, escaped, and shortened as
// detail::shorten does (at most 80 characters, "..." at the end of a longer text), without
// cutting an escape in two.
std::string quoted_excerpt(std::string_view text) {
  std::string out(1, '"');
  std::size_t fits = out.size();  // the end of the last escape within 80 - 3 characters
  for (const char c : text) {
    out += escaped(c);
    if (out.size() <= 1 + max_echoed - 3) fits = out.size();
    if (out.size() > 1 + max_echoed) break;
  }
  if (out.size() > 1 + max_echoed) {
    out.resize(fits);
    out += "...";
  }
  out += '"';
  return out;
}

const char* describe_file_type(fs::file_type type) {
  switch (type) {
    case fs::file_type::regular:
      return "a regular file";
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::symlink:
      return "a symbolic link";
    default:
      return "of an unknown type";
  }
}

std::uintmax_t require_regular_input(const fs::path& path, std::string_view what,
                                     std::uintmax_t max_bytes) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);  // follows symbolic links
  COATFFT_REQUIRE(!error, path.string(), ": cannot open: ", error.message());
  COATFFT_REQUIRE(status.type() == fs::file_type::regular, path.string(), ": not a regular file (",
                  describe_file_type(status.type()), ")");
  const std::uintmax_t size = fs::file_size(path, error);
  COATFFT_REQUIRE(!error, path.string(), ": cannot open: ", error.message());
  check_size(path, size, what, max_bytes);
  return size;
}

InputFile::InputFile(const fs::path& path, std::string_view what, std::uintmax_t max_bytes)
    : path_(path) {
  require_regular_input(path, what, max_bytes);
  // Opened without blocking and checked again, in case the path changed since the check above:
  // opening a FIFO with O_NONBLOCK returns at once.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw_system(path, "cannot open");
  struct stat info {};
  if (::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd_);
    throw InvalidArgument(path.string() + ": not a regular file (it changed while being opened)");
  }
  size_ = static_cast<std::uintmax_t>(info.st_size);
  try {
    check_size(path, size_, what, max_bytes);
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

InputFile::~InputFile() {
  ::close(fd_);
}

void InputFile::read_exact(void* out, std::size_t count) {
  auto* bytes = static_cast<char*>(out);
  while (count > 0) {
    const ssize_t got = ::read(fd_, bytes, count);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw_system(path_, "cannot read");
    if (got == 0) throw_changed(path_);
    bytes += got;
    count -= static_cast<std::size_t>(got);
  }
}

void InputFile::read_at(std::uintmax_t offset, void* out, std::size_t count) {
  auto* bytes = static_cast<char*>(out);
  while (count > 0) {
    const ssize_t got = ::pread(fd_, bytes, count, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw_system(path_, "cannot read");
    if (got == 0) throw_changed(path_);
    bytes += got;
    offset += static_cast<std::uintmax_t>(got);
    count -= static_cast<std::size_t>(got);
  }
}

bool InputFile::at_end() {
  char byte = 0;
  ssize_t got = 0;
  do {
    got = ::read(fd_, &byte, 1);
  } while (got < 0 && errno == EINTR);
  if (got < 0) throw_system(path_, "cannot read");
  return got == 0;
}

std::string read_input_file(const fs::path& path, std::string_view what, std::uintmax_t max_bytes) {
  InputFile file(path, what, max_bytes);
  std::string content(static_cast<std::size_t>(file.size()), '\0');
  file.read_exact(content.data(), content.size());
  if (!file.at_end()) throw_changed(path);
  return content;
}

}  // namespace coatfft::io
