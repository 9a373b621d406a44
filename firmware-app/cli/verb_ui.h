#pragma once
// The tablet UI (`rockface ui`, and `rockface` without a verb).
namespace rockface::app {

// Starts the UI in a window with default options; returns the exit code.
int start_tablet_ui();

}  // namespace rockface::app
