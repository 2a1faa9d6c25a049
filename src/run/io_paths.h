// An output never destroys an input. Each command lists the files it reads and the files or
// folders it writes; Check() compares every output with every input before any work starts, so
// `simulate --genome g.genome --csv g.genome` is refused instead of overwriting the genome.
#pragma once

#include <string>
#include <vector>

namespace hexgait {

class IoPaths {
 public:
  // A file or folder the command reads. Empty paths (a default) are skipped.
  IoPaths& Input(const std::string& flag, const std::string& path);
  // A file the command replaces.
  IoPaths& Output(const std::string& flag, const std::string& path);
  // A folder the command replaces whole: every input inside it would be destroyed.
  IoPaths& OutputFolder(const std::string& flag, const std::string& path);
  // Throws InputError naming the output and the input it would destroy.
  void Check() const;

 private:
  struct Entry {
    std::string flag;
    std::string path;
  };
  std::vector<Entry> inputs_;
  std::vector<Entry> outputs_;
  std::vector<Entry> output_folders_;
};

// Refuses an output whose extension does not match what is written ("render --out m.png"):
// `extension` is ".mp4", ".png", ...; throws InputError naming `flag`.
void CheckExtension(const std::string& path, const std::string& extension, const std::string& flag);

}  // namespace hexgait
