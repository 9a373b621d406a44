#pragma once
// Writing an export file so that a reader never sees half of it: the content
// goes to a temporary file beside the target, is flushed to the card, and is
// then renamed over the target.
#include <filesystem>
#include <functional>
#include <ostream>

namespace rockface::storage {

// Calls write(stream) and puts the result at `file`. Throws rockface::Error
// naming the file when it cannot be written.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

}  // namespace rockface::storage
