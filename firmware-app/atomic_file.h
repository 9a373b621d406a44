#pragma once
// Output files of the verbs, written whole or not at all: to PATH.part,
// then renamed, so a full disk or a killed process never leaves half a
// report or half a measurement file under the real name.
#include <string>

namespace rockface::app {

// Throws Error naming the path when it cannot be written.
void write_atomically(const std::string& path, const std::string& text);

}  // namespace rockface::app
