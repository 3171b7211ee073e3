#include "cli/output_file.hpp"

#include "core/error.hpp"
#include "io/input_file.hpp"

namespace coatfft::cli {

void refuse_existing_output(const std::filesystem::path& target, bool overwrite,
                            std::string_view flag) {
  std::error_code ec;
  // symlink_status: a dangling link is an existing name too.
  const bool exists = std::filesystem::exists(std::filesystem::symlink_status(target, ec));
  COATFFT_REQUIRE(overwrite || !exists, "output file ", io::quoted_excerpt(target.string()),
                  " exists: it is left as it is (choose another name, or give ", flag,
                  " to replace it)");
}

}  // namespace coatfft::cli
