#include "base/files.hpp"

#include <unistd.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace uabt {

namespace fs = std::filesystem;

std::optional<std::string> read_text_file(const fs::path& path, std::string& error) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    error = "no such file";
    return std::nullopt;
  }
  if (fs::is_directory(path, ec)) {
    error = "is a directory, not a file";
    return std::nullopt;
  }
  const auto size = fs::file_size(path, ec);
  if (ec) {
    error = "cannot read: " + ec.message();
    return std::nullopt;
  }
  if (size > kMaxInputFileBytes) {
    error = "file is " + std::to_string(size) + " bytes; the limit is " +
            std::to_string(kMaxInputFileBytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open for reading";
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void write_file_atomically(const fs::path& path, const std::string& content) {
  std::error_code ec;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ec);
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      fs::remove(tmp, ec);
      throw std::runtime_error(path.string() + ": write failed");
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error(path.string() + ": cannot rename into place");
  }
}

std::string display_path(const fs::path& path, const fs::path& base) {
  std::error_code ec;
  // The file as found in the directory first (a symlinked alternative is named by its link,
  // not by where the link points), then as the file system resolves it (an included file,
  // reached by its canonical path), else relative with "..": every name stays relative to
  // `base`, so that one prefix opens it from where uabt runs.
  const fs::path lexical = fs::absolute(path, ec).lexically_normal().lexically_relative(
      fs::absolute(base, ec).lexically_normal());
  if (!lexical.empty() && *lexical.begin() != "..") return lexical.generic_string();
  const fs::path resolved =
      fs::weakly_canonical(path, ec).lexically_relative(fs::weakly_canonical(base, ec));
  if (!resolved.empty() && *resolved.begin() != "..") return resolved.generic_string();
  return lexical.empty() ? path.generic_string() : lexical.generic_string();
}

std::string relative_path(const fs::path& path, const fs::path& base) {
  std::error_code ec;
  const fs::path abs_path = fs::weakly_canonical(fs::absolute(path, ec), ec);
  const fs::path rel =
      abs_path.lexically_relative(fs::weakly_canonical(fs::absolute(base, ec), ec));
  return rel.empty() ? abs_path.generic_string() : rel.generic_string();
}

}  // namespace uabt
