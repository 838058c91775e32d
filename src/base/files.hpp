#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace uabt {

// Largest mission file uabt reads; beyond it a file is refused with a finding, not parsed.
inline constexpr std::uintmax_t kMaxInputFileBytes = 16u * 1024u * 1024u;

// Reads a whole file. Returns nullopt and sets `error` when it cannot be read or is too large.
std::optional<std::string> read_text_file(const std::filesystem::path& path, std::string& error);

// Whether `path` lies inside `folder` once every symbolic link in both is resolved
// (weakly_canonical): the one rule for the files of a mission folder (mission.xml,
// alternatives, domain.fret, requirements, nodes.xml, world.json, <include>d files) and of an
// uplink package. A symlink that leads out of the folder is refused as an <include> outside it
// is, unread, so that nothing of the outside file is ever shown.
bool lies_inside(const std::filesystem::path& path, const std::filesystem::path& folder);

// Why a file of `what` ("the mission folder") that does not lie inside it is not read.
std::string outside_folder_error(const std::string& what);

// A path uabt cannot write its output to (a directory where a file goes, a fifo, a folder
// that is a file, a device that refuses the bytes): a command-line error, exit 2. The message
// names the path and what is wrong with it.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `content` to `path`. A regular file (or a missing one) is written to a temporary
// file in its folder and renamed over it, so that a reader never sees half a file; a symlink
// is followed and its target written that way; a character device (/dev/null, a terminal) is
// written directly. Anything else (a directory, a fifo, a socket) is refused: uabt never
// replaces what is not a regular file. Creates missing parent directories. Throws OutputError.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// Throws OutputError unless `dir` can take output files: a directory (or a symlink to one)
// that uabt may write in, or a missing one whose nearest existing ancestor is such a directory.
// `role` names the option in the message ("--out"). Creates nothing.
void check_output_directory(const std::filesystem::path& dir, const std::string& role);

// check_output_directory, then creates `dir` and its missing parents. Throws OutputError.
void make_output_directory(const std::filesystem::path& dir, const std::string& role);

// Removes an output file an earlier run left (a regular file, or a symlink: the link, not its
// target); leaves anything else where it is. Throws OutputError when it cannot.
void remove_output_file(const std::filesystem::path& path);

// `path` relative to `base` (generic form, '/' separators): as found in `base` (a symlink by
// its own name), else as resolved, else with ".." ("../pkg/requirements.fret") when it lies
// outside.
std::string display_path(const std::filesystem::path& path, const std::filesystem::path& base);

// `path` relative to `base` wherever it lies ("../out/compiled.xml"; generic form), the form
// of every finding's file: relative to the mission directory, so that one prefix makes them
// all openable from where uabt runs.
std::string relative_path(const std::filesystem::path& path, const std::filesystem::path& base);

}  // namespace uabt
