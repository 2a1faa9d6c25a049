#include "util/shared_library.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

namespace hexgait {
namespace {

// Every library opened so far, by the name it was opened under. Never closed (see the header).
std::mutex& LibrariesMutex() {
  static std::mutex mutex;
  return mutex;
}
std::map<std::string, std::unique_ptr<SharedLibrary>>& Libraries() {
  static auto* libraries = new std::map<std::string, std::unique_ptr<SharedLibrary>>;
  return *libraries;
}

std::string LastDlError() {
  const char* text = dlerror();
  return text ? text : "unknown dlopen error";
}

// The folder of the executable or shared object that holds this code (hexgait, or the Python
// module), so a module built or installed beside it is found wherever the tree was moved.
std::filesystem::path OwnFolder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&OwnFolder), &info) == 0 || !info.dli_fname) return {};
  std::error_code ec;
  const auto path = std::filesystem::canonical(info.dli_fname, ec);
  return ec ? std::filesystem::path() : path.parent_path();
}

}  // namespace

std::string DescribeLibrary(const LibraryName& name) {
  const std::string package = name.package && *name.package
                                  ? std::string("Debian package ") + name.package
                                  : std::string("the package that provides it");
  return std::string(name.soname) + " (" + package + ")";
}

class SharedLibraryOpener {
 public:
  // Opens `path` with `flags` under `key`, or returns the library opened under `key` before.
  static const SharedLibrary* Open(const std::string& key, const std::string& path, int flags,
                                   std::string* error) {
    std::lock_guard<std::mutex> lock(LibrariesMutex());
    auto& libraries = Libraries();
    if (const auto it = libraries.find(key); it != libraries.end()) return it->second.get();
    void* handle = dlopen(path.c_str(), flags);
    if (!handle) {
      *error = LastDlError();
      return nullptr;
    }
    auto library = std::unique_ptr<SharedLibrary>(new SharedLibrary(handle, path));
    return libraries.emplace(key, std::move(library)).first->second.get();
  }
};

std::string DescribeLoadFailure(const LibraryName& name, const std::string& dl_error) {
  // dlerror() starts with the file that could not be opened: the library itself when it is
  // absent, else a dependency of it (or the library's own path when the file is damaged).
  const std::string missing = ": cannot open shared object file";
  const size_t colon = dl_error.find(missing);
  if (colon != std::string::npos && dl_error.compare(0, colon, name.soname) == 0) {
    return DescribeLibrary(name) + " is not installed";
  }
  if (colon != std::string::npos) {
    return DescribeLibrary(name) + " is installed but cannot be loaded: it needs " +
           dl_error.substr(0, colon) + ", which is missing";
  }
  return DescribeLibrary(name) + " is installed but cannot be loaded: " + dl_error;
}

const SharedLibrary* SharedLibrary::Open(const LibraryName& name, std::string* error) {
  std::string why;
  const SharedLibrary* library =
      SharedLibraryOpener::Open(name.soname, name.soname, RTLD_NOW | RTLD_LOCAL, &why);
  if (!library) *error = DescribeLoadFailure(name, why);
  return library;
}

const SharedLibrary* SharedLibrary::OpenModule(const std::string& file, std::string* error) {
  std::vector<std::filesystem::path> folders;
  if (const auto own = OwnFolder(); !own.empty()) folders = {own, own.parent_path()};
#ifdef HEXGAIT_MODULE_DIRS
  // Configured: the build folder, then the install folder (CMakeLists.txt).
  for (const char* dir : {HEXGAIT_MODULE_DIRS}) folders.emplace_back(dir);
#endif
  for (const auto& folder : folders) {
    const auto path = folder / file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) continue;
    // RTLD_GLOBAL: Open MPI's own plug-ins resolve their symbols against libmpi.
    std::string why;
    const SharedLibrary* library =
        SharedLibraryOpener::Open(file, path.string(), RTLD_NOW | RTLD_GLOBAL, &why);
    if (!library) *error = "cannot load " + path.string() + ": " + why;
    return library;
  }
  *error = file + " is not installed beside hexgait";
  return nullptr;
}

void* SharedLibrary::Find(const char* symbol, std::string* error) const {
  dlerror();
  void* address = dlsym(handle_, symbol);
  if (!address) *error = name_ + " has no " + symbol + ": " + LastDlError();
  return address;
}

}  // namespace hexgait
