#include "base/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
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

bool lies_inside(const fs::path& path, const fs::path& folder) {
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return false;
  const fs::path base = fs::weakly_canonical(fs::absolute(folder, ec), ec);
  if (ec) return false;
  const fs::path inside = target.lexically_relative(base);
  return !inside.empty() && *inside.begin() != "..";
}

std::string outside_folder_error(const std::string& what) {
  return "leads outside " + what + " through a symbolic link; uabt reads only files inside it";
}

namespace {

[[noreturn]] void refuse(const fs::path& path, const std::string& what) {
  throw OutputError(path.generic_string() + ": " + what);
}

// What a file that is not a regular file is, for a message: "a directory", "a fifo"…
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a fifo";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISREG(mode)) return "a regular file";
  return "not a regular file";
}

std::string error_text(int error) {
  return std::error_code(error, std::generic_category()).message();
}

// The nearest part of `dir` that exists (`dir` itself when it does), with its status; empty
// when no part of a relative path exists (the current directory then). Symlinks are followed.
fs::path existing_part(const fs::path& dir, struct stat& st) {
  for (fs::path at = dir; !at.empty();) {
    if (::stat(at.c_str(), &st) == 0) return at;
    const int error = errno;
    struct stat link;
    if (error == ENOENT && ::lstat(at.c_str(), &link) == 0)
      refuse(at, "is a symbolic link to nothing, not a directory");
    if (error != ENOENT && error != ENOTDIR) refuse(at, error_text(error));
    fs::path up = at.parent_path();
    if (up == at) break;
    at = std::move(up);
  }
  if (::stat(".", &st) != 0) refuse(dir, "the current directory cannot be read");
  return {};
}

// Checks that `dir` is, or can become, a directory uabt writes in.
void check_directory(const fs::path& dir, const std::string& role) {
  struct stat st;
  const fs::path existing = existing_part(dir, st);
  const fs::path shown = existing.empty() ? fs::path(".") : existing;
  const std::string prefix = role.empty() ? "" : role + " ";
  if (!S_ISDIR(st.st_mode))
    refuse(dir, (existing == dir ? prefix + "names " + kind_of(st.st_mode)
                                 : shown.generic_string() + " is " + kind_of(st.st_mode)) +
                    ", not a directory");
  if (::access(shown.c_str(), W_OK | X_OK) != 0)
    refuse(dir, (existing == dir ? std::string("the directory") : shown.generic_string()) +
                    " is not writable: " + error_text(errno));
}

void make_directories(const fs::path& dir, const std::string& role = "") {
  if (dir.empty()) return;
  check_directory(dir, role);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) refuse(dir, "cannot create the directory: " + ec.message());
}

void write_all(int fd, const fs::path& path, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      ::close(fd);
      refuse(path, "cannot write: " + error_text(error));
    }
    done += static_cast<std::size_t>(n);
  }
}

// A device is written where it is: nothing to rename, nothing to truncate.
void write_device(const fs::path& path, const std::string& content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) refuse(path, "cannot open for writing: " + error_text(errno));
  write_all(fd, path, content);
  if (::close(fd) != 0) refuse(path, "cannot write: " + error_text(errno));
}

// `target` (a regular file or none) replaced by a complete new file; `shown` names it.
void replace_regular(const fs::path& target, const fs::path& shown, const std::string& content,
                     const struct stat* existing) {
  fs::path tmp = target;
  tmp += ".tmp." + std::to_string(::getpid());
  const mode_t mode = existing ? (existing->st_mode & 07777) : 0666;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, mode);
  if (fd < 0) refuse(shown, "cannot create a file beside it: " + error_text(errno));
  std::error_code ec;
  try {
    if (existing) ::fchmod(fd, mode);  // the old file's permissions, whatever the umask
    write_all(fd, shown, content);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  if (::close(fd) != 0) {
    const int error = errno;
    fs::remove(tmp, ec);
    refuse(shown, "cannot write: " + error_text(error));
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    const std::string message = ec.message();
    fs::remove(tmp, ec);
    refuse(shown, "cannot replace it: " + message);
  }
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::string& content) {
  if (path.empty() || !path.has_filename()) refuse(path, "names a directory, not a file");
  struct stat st;
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISCHR(st.st_mode)) return write_device(path, content);
    if (!S_ISREG(st.st_mode))
      refuse(path, "is " + kind_of(st.st_mode) +
                       "; uabt writes a regular file or a character device, and replaces "
                       "nothing else");
    // A regular file, perhaps through symlinks: the file they lead to is the one replaced.
    struct stat link;
    fs::path target = path;
    if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
      std::error_code ec;
      target = fs::canonical(path, ec);
      if (ec) refuse(path, "cannot follow the symbolic link: " + ec.message());
    }
    return replace_regular(target, path, content, &st);
  }
  const int error = errno;
  if (error != ENOENT && error != ENOTDIR) refuse(path, error_text(error));
  // Nothing there yet, or a symlink to a file not written yet: follow the links by hand.
  fs::path target = path;
  for (int hops = 0;; ++hops) {
    struct stat link;
    if (::lstat(target.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) break;
    if (hops == 40) refuse(path, "too many levels of symbolic links");
    std::error_code ec;
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) refuse(path, "cannot follow the symbolic link: " + ec.message());
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  if (!target.has_filename()) refuse(path, "leads to a directory name, not a file");
  make_directories(target.parent_path());
  replace_regular(target, path, content, nullptr);
}

void check_output_directory(const fs::path& dir, const std::string& role) {
  check_directory(dir, role);
}

void make_output_directory(const fs::path& dir, const std::string& role) {
  make_directories(dir, role);
}

void remove_output_file(const fs::path& path) {
  struct stat link;
  if (::lstat(path.c_str(), &link) != 0) return;
  if (!S_ISREG(link.st_mode) && !S_ISLNK(link.st_mode)) return;
  if (::unlink(path.c_str()) != 0) refuse(path, "cannot remove it: " + error_text(errno));
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
