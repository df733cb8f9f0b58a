#include "stickslip/io/atomic_file.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

namespace stickslip {

void WriteFileAtomically(const std::filesystem::path& path, std::string_view content) {
  namespace fs = std::filesystem;
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(directory)) {
    throw std::runtime_error(
        fmt::format("cannot write '{}': directory '{}' does not exist", path.string(),
                    directory.string()));
  }
  // The process id keeps concurrent writers of the same target apart.
  const fs::path temporary = directory / fmt::format(".{}.tmp.{}", path.filename().string(),
                                                     static_cast<long>(::getpid()));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error(fmt::format("cannot write '{}'", temporary.string()));
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(
        fmt::format("cannot rename '{}' to '{}': {}", temporary.string(), path.string(),
                    error.message()));
  }
}

}  // namespace stickslip
