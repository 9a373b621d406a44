#pragma once
// The one writer of output files (exports, reports, measurements, camera
// files): a reader never sees half of a file. The content goes to a
// temporary file beside the target, is flushed and synced to the card, is
// then renamed over the target, and the folder is synced so that the rename
// itself survives a power cut.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace rockface::storage {

// Calls write(stream) and puts the result at `file`. Throws rockface::Error
// naming the file when it cannot be written.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

// The same for a text already made.
void write_text_atomically(const std::filesystem::path& file, std::string_view text);

}  // namespace rockface::storage
