#pragma once
// The one atomic file writer: a reader never sees half of a file, and a
// power cut leaves either the old file or the new one. The content goes to a
// temporary file in the target's folder, is synced to the card, is renamed
// over the target, and the folder is synced so that the rename itself
// survives. On failure the temporary file is removed, the old file is left
// as it was, and rockface::Error names the file and the reason (the system's
// error text where there is one).
//
// Standard library and POSIX only: every layer uses it, from the camera's
// spool to the exports and the tablet's settings.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace rockface {

// Calls write(stream) and puts what it wrote at `file`. An exception thrown
// by `write` removes the temporary file and propagates unchanged.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

// The same for a text (or any bytes) already made.
void write_text_atomically(const std::filesystem::path& file, std::string_view text);

// The same for raw bytes (pictures, camera files).
void write_bytes_atomically(const std::filesystem::path& file, const void* data, std::size_t size);

}  // namespace rockface
