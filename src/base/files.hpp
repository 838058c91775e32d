#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace uabt {

// Largest mission file uabt reads; beyond it a file is refused with a finding, not parsed.
inline constexpr std::uintmax_t kMaxInputFileBytes = 16u * 1024u * 1024u;

// Reads a whole file. Returns nullopt and sets `error` when it cannot be read or is too large.
std::optional<std::string> read_text_file(const std::filesystem::path& path, std::string& error);

// Writes `content` to a temporary file beside `path`, then renames it over `path`, so a reader
// never sees half a file. Creates missing parent directories. Throws std::runtime_error.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

// `path` relative to `base` (generic form, '/' separators): as found in `base` (a symlink by
// its own name), else as resolved, else with ".." ("../pkg/requirements.fret") when it lies
// outside.
std::string display_path(const std::filesystem::path& path, const std::filesystem::path& base);

// `path` relative to `base` wherever it lies ("../out/compiled.xml"; generic form), the form
// of every finding's file: relative to the mission directory, so that one prefix makes them
// all openable from where uabt runs.
std::string relative_path(const std::filesystem::path& path, const std::filesystem::path& base);

}  // namespace uabt
