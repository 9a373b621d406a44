#pragma once
// Kept only for the files that have not moved yet (firmware-app/analysis):
// the one atomic file writer lives in core/common/atomic_file.h. New code
// includes that header and calls rockface::write_file_atomically.
#include "core/common/atomic_file.h"

namespace rockface::storage {

using rockface::write_file_atomically;
using rockface::write_text_atomically;

}  // namespace rockface::storage
