// The temporary files and folders of writes in progress, so a command stopped by a signal
// between its safe points can remove them before it exits (see StartStopWatchdog).
#pragma once

#include <functional>
#include <string>

namespace hexgait {

// Runs `create`, which makes a temporary file or folder and returns its path (or throws), and
// registers that path, both under the registry's lock: a stop that removes every temporary
// cannot fall between the two and leave one behind. Returns a handle for UnregisterTemp.
int CreateRegisteredTemp(const std::function<std::string()>& create);
// Registers a path that exists already or that other code creates later (a lock file, a staged
// movie the encoder renames into place); returns a handle for UnregisterTemp.
int RegisterTemp(const std::string& path);
// After the temporary was renamed into place or removed.
void UnregisterTemp(int handle);
// Runs `commit`, the renames that put a finished temporary in place, under the registry's lock:
// once a stop has removed every temporary, no thread can put a file in place after it (it waits
// for the exit instead), and a stop never falls between moving an old folder aside and moving
// the new one in. `commit` must not create or register temporaries.
void CommitTemp(const std::function<void()>& commit);
// Removes every registered temporary (folders with their content) and blocks further
// registration, so nothing new appears while the process exits.
void RemoveAllTempsForExit();

}  // namespace hexgait
