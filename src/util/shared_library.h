// C libraries that only some commands need (Mesa's OSMesa and EGL, FreeType, libpng, FFmpeg,
// Open MPI), opened with dlopen the first time something uses them, so a process pays only for
// what its command uses: `hexgait simulate` never maps Mesa's LLVM or FFmpeg's codecs.
// A library, once opened, stays for the life of the process: Mesa and FFmpeg keep thread-local
// state and exit handlers, and unloading them early buys nothing.
#pragma once

#include <string>

namespace hexgait {

// Where a library comes from: the name the dynamic loader looks for (its SONAME, found when
// hexgait was configured) and the Debian package that installs it, for the error message.
struct LibraryName {
  const char* soname;
  const char* package;  // "" when the configure step could not tell
};

class SharedLibrary {
 public:
  // Opens `name` (once per process; later calls return the same library). On failure returns
  // nullptr and sets `error` to DescribeLoadFailure's line.
  static const SharedLibrary* Open(const LibraryName& name, std::string* error);
  // Opens a module of hexgait's own (libhexgait_mpi.so) from the folder of the binary that holds
  // this code, then from the build and install folders it was configured with.
  static const SharedLibrary* OpenModule(const std::string& file, std::string* error);

  // The address of `symbol`, or nullptr with `error` naming the symbol and the library.
  void* Find(const char* symbol, std::string* error) const;
  // Sets `fn` to `symbol` typed as the header declares it; false with `error` if missing.
  template <class Fn>
  bool Bind(const char* symbol, Fn*& fn, std::string* error) const {
    fn = reinterpret_cast<Fn*>(Find(symbol, error));
    return fn != nullptr;
  }
  const std::string& name() const { return name_; }

  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

 private:
  friend class SharedLibraryOpener;
  SharedLibrary(void* handle, std::string name) : handle_(handle), name_(std::move(name)) {}
  void* handle_;
  std::string name_;
};

// "libavcodec.so.59 (Debian package libavcodec59)": how error messages name a library.
std::string DescribeLibrary(const LibraryName& name);
// Why `name` did not load, from dlopen's `dl_error`, as a clause for "cannot X: ...": the
// library "is not installed", or it "is installed but cannot be loaded" and the file that
// failed (a dependency it needs, or its own damaged file) with the loader's reason. A broken
// dependency is not reported as the library missing.
std::string DescribeLoadFailure(const LibraryName& name, const std::string& dl_error);

}  // namespace hexgait
