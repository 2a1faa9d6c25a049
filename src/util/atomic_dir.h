// Output folders appear whole or not at all, like AtomicFile for one file: the content is
// built in a temporary folder next to the final one, which replaces it only once complete.
//
// Replacing a folder deletes the old one, so a folder is replaced only if it is empty or holds
// the marker file an earlier run of the same command left: `--out $HOME` is refused, not wiped.
#pragma once

#include <memory>
#include <string>

#include "util/folder_lock.h"

namespace hexgait {

class AtomicDir {
 public:
  // `marker` names the file that identifies folders this command wrote (e.g.
  // ".hexgait-figures"); `what` names the option in error messages. Throws InputError if the
  // parent folder is missing or not writable, or `path` is a file or a foreign folder.
  AtomicDir(std::string path, std::string marker, std::string what);
  ~AtomicDir();  // removes the temporary folder unless committed
  AtomicDir(const AtomicDir&) = delete;
  AtomicDir& operator=(const AtomicDir&) = delete;

  // The temporary folder to write into, and a file name inside it.
  const std::string& temp_path() const { return temp_path_; }
  std::string File(const std::string& name) const { return temp_path_ + "/" + name; }
  // Writes the marker, then swaps the folder into place; throws InputError on failure.
  void Commit();

 private:
  std::string path_;
  std::string marker_;
  std::string what_;
  std::string temp_path_;
  bool committed_ = false;
  // Held from construction to destruction: two runs cannot build the same folder at once.
  std::unique_ptr<FolderLock> lock_;
  int temp_handle_ = 0;  // in util/temp_registry, so a stop signal removes the folder
};

}  // namespace hexgait
