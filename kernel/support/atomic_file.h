// atomic_file.h -- write a whole output file or nothing.
//
// Writes `content` to a temporary file beside `path` and renames it into place, so a
// failure (disk full, bad directory, an exception before the call) never leaves a
// partial output file. Throws std::runtime_error naming the path on failure.
#pragma once

#include <string>

namespace grassfire {

void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace grassfire
