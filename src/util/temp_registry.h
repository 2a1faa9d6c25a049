// The temporary files and folders of writes in progress, so a command stopped by a signal
// between its safe points can remove them before it exits (see StartStopWatchdog).
#pragma once

#include <string>

namespace hexgait {

// Registers a temporary file or folder; returns a handle for UnregisterTemp.
int RegisterTemp(const std::string& path);
// After the temporary was renamed into place or removed.
void UnregisterTemp(int handle);
// Removes every registered temporary (folders with their content) and blocks further
// registration, so nothing new appears while the process exits.
void RemoveAllTempsForExit();

}  // namespace hexgait
