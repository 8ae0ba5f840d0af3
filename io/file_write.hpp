// The one way the program writes a whole file (score.json, pictures, exports, reports, bench
// results, the scenario a run used): to a temporary name in the file's own folder, written,
// flushed to the disk (fsync), closed and checked, then renamed over the file, and the folder
// synced. A reader sees the old file or the new one, never a part of one; a full or read-only
// disk is an error naming the file, never a "wrote" over an empty file.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace needle::io {

// "FILE: cannot write: reason" (the system's words: "No space left on device", ...).
struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes `bytes` as `file`, whose folder must exist. A symbolic link is written through to its
// target. A file that exists and is not a regular file (/dev/null, /dev/full, a FIFO) cannot be
// replaced by a rename, so it is written in place, and checked the same way. Throws WriteError;
// the temporary file is removed on failure and the old file, if any, is left as it was.
void write_file(const std::filesystem::path& file, std::string_view bytes);

// Makes `folder` and the folders above it that are missing, for files to be written there; one that
// exists is left as it is. Throws WriteError "FOLDER: cannot create the folder: reason".
void make_folder(const std::filesystem::path& folder);

}  // namespace needle::io
