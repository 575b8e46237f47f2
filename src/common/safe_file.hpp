#pragma once
/// @file safe_file.hpp
/// How gapfem opens the files it writes (docs/results.md, "Files gapfem writes and what it never
/// touches"). Every file is created new (O_CREAT | O_EXCL | O_NOFOLLOW) — a regular file of an
/// earlier run under the same name is unlinked first, which changes no other file whatever links
/// it has — or, to continue a file of ours (restart, the JSON shadows), opened without following a
/// link or blocking on a pipe and checked to be a regular file of this user with one name. A
/// symbolic link, named pipe, device, socket or directory in the place of a file gapfem writes is
/// an error naming it: never followed, never opened for writing.
#include <cstdint>
#include <filesystem>
#include <string>

namespace gapfem::files {

/// What occupies a name, seen without following a symbolic link (lstat).
enum class Kind { Missing, Regular, Directory, Symlink, Fifo, Other };

Kind kind_of(const std::filesystem::path& path);
/// "a symbolic link", "a named pipe (FIFO)", "a directory", "a device or socket", "a regular file".
const char* kind_text(Kind kind);

/// The sentence for a name gapfem will not write through: "'out/job.dat' is a symbolic link;
/// gapfem writes ... : remove it or choose another output directory with -o".
std::string refusal(const std::filesystem::path& path, Kind kind);
/// The same without the name: "it is a symbolic link; gapfem writes ...".
std::string refusal_reason(Kind kind);

/// Creates `path` as a new empty regular file open for writing (O_RDWR) and returns its
/// descriptor. A regular file there is unlinked first; anything else there raises AnalysisError
/// (refusal()). Returns -1 with errno set when the system refuses (no space, permissions, ...).
int create_new(const std::filesystem::path& path);

/// Opens an existing file of ours to continue writing it (O_RDWR): not through a symbolic link,
/// without blocking on a pipe, and only a regular file of this user with one name (AnalysisError
/// otherwise). Returns -1 with errno set when it cannot be opened (ENOENT when missing).
int open_own(const std::filesystem::path& path);

/// Opens a file to read (O_RDONLY, symbolic links followed): only a regular file — a pipe or
/// device would block or never end (AnalysisError). Returns -1 with errno set when it cannot be
/// opened.
int open_read(const std::filesystem::path& path);

/// Raises AnalysisError unless `path` is missing or a regular file, i.e. unless a rename onto it
/// replaces an earlier result rather than a link, pipe, device or directory.
void check_replaceable(const std::filesystem::path& path);

/// Renames `from` over `to` after check_replaceable(to); false with errno set when the system
/// refuses.
bool replace(const std::filesystem::path& from, const std::filesystem::path& to);

/// Unlinks `path` when it is a regular file (a leftover of an earlier run); anything else stays.
void remove_regular(const std::filesystem::path& path);

/// Writes `bytes` to a new file `path` (create_new, fsync) and closes it; false with errno set
/// when the system refuses.
bool write_new(const std::filesystem::path& path, std::string_view bytes);

/// Writes `bytes` to `path` atomically: into a new `path`.tmp, fsync'ed and renamed over `path`
/// (check_replaceable). false with errno set when the system refuses.
bool write_replace(const std::filesystem::path& path, std::string_view bytes);

/// Reads a whole regular file (open_read); false with errno set when it cannot.
bool read_all(const std::filesystem::path& path, std::string& out);

/// Makes `dir` an empty directory of this user, readable only by it: an earlier directory of ours
/// there is emptied (its symbolic links are removed, never followed); anything else there raises
/// AnalysisError. false with errno set when the system refuses.
bool fresh_private_directory(const std::filesystem::path& dir);

} // namespace gapfem::files
