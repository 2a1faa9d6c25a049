// Every file and folder hexgait writes is owned by one of these until it is complete, so an
// output appears whole or not at all, and an error, a Ctrl-C or a SIGTERM (util/temp_registry)
// never leaves half of one behind:
//   AtomicFile       one file, written under a temporary name and renamed into place;
//   StagedFiles      several files of one folder, renamed into place together;
//   AtomicDir        a folder built aside and swapped in whole (figures, a report, adapt);
//   ResumableFolder  a folder a long run fills as it goes and may resume (evolve, repertoire,
//                    sweep), marked "running" until its last result is written;
//   OutputFolder     a folder several commands add files to (the benchmarks' out/bench),
//                    removed again if it was made for a command that wrote nothing;
//   ScratchFiles     files a command needs only while it runs.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "util/folder_lock.h"

namespace hexgait {

// Checks before any work starts that `path` can be created: its folder exists and is writable,
// and it is a new name or a regular file (never a folder, a link or a device).
void CheckOutputPath(const std::string& path, const std::string& what);

// A temporary file next to `path`; Commit() renames it into place. Destroyed without Commit()
// (an error, an exception), it removes the temporary file.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);  // throws InputError if the folder is not writable
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* handle() { return file_.get(); }
  const std::string& temp_path() const { return temp_path_; }
  void Write(std::string_view text);
  void Commit();  // throws StorageError on a failed write or flush, FileError on a failed rename

 private:
  struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::string path_;
  std::string temp_path_;
  std::unique_ptr<std::FILE, FileCloser> file_;
  bool failed_ = false;
  int temp_handle_ = 0;  // in util/temp_registry, so a stop signal removes the file
};

// Writes `text` to `path` atomically.
void WriteFileAtomically(const std::string& path, std::string_view text);

// Files of one folder written under staging names (NAME.staged.PID.EXT, the extension kept so
// an encoder still knows the format) and renamed into place together by CommitAll(): a movie
// set's three movies and pages replace an earlier set only once the last is complete.
class StagedFiles {
 public:
  explicit StagedFiles(std::string dir);  // `dir` with a trailing slash
  ~StagedFiles();                         // removes whatever is still staged
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;

  // Where to write `name`; it counts as staged from now on.
  std::string Stage(const std::string& name);
  void CommitAll();  // throws FileError when a rename fails

 private:
  std::string Staged(const std::string& name) const;
  std::string dir_;
  std::vector<std::string> names_;
  std::vector<int> handles_;  // in util/temp_registry
};

// A folder built in a temporary folder next to the final one, which replaces it only once
// complete. Replacing a folder deletes the old one, so a folder is replaced only if it is empty
// or holds the marker file an earlier run of the same command left: `--out $HOME` is refused,
// not wiped.
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

// The folder of a resumable run of `command`: refused if another command wrote it, created,
// locked for the run, and marked running (FOLDER/.hexgait-COMMAND) until Complete(); readers
// refuse it meanwhile (RefuseUnfinishedRun), since an older run's results may still lie beside
// this run's state. Every file is written atomically.
class ResumableFolder {
 public:
  // Opens `path` (given by `flag`: "--out" or "--resume"). A folder is accepted when new, empty,
  // or written by `command` (its marker, or one of `legacy_files` for runs from before markers);
  // `files` are checked as outputs before anything is written.
  ResumableFolder(const std::string& path, const std::string& flag, const std::string& command,
                  const std::vector<std::string>& files,
                  const std::vector<std::string>& legacy_files = {});
  ResumableFolder(const ResumableFolder&) = delete;
  ResumableFolder& operator=(const ResumableFolder&) = delete;

  const std::string& path() const { return path_; }
  std::string File(const std::string& name) const { return path_ + "/" + name; }
  void Write(const std::string& name, const std::string& text) const;
  // Marks the folder complete: every result of this run is written.
  void Complete() const;

 private:
  std::string path_, command_;
  std::unique_ptr<FolderLock> lock_;
};

// The marks a ResumableFolder keeps, written atomically into FOLDER/.hexgait-COMMAND.
void MarkRunStarted(const std::string& folder, const std::string& command);
void MarkRunComplete(const std::string& folder, const std::string& command);

// Throws InputError naming `flag` when the folder's marker says its last run of `command` did
// not finish (interrupted, failed or still going). A folder without a marker, or with one from
// before the marker had a state, passes: there is nothing to tell.
void RefuseUnfinishedRun(const std::string& folder, const std::string& flag,
                         const std::string& command);

// A folder that collects several commands' files, made if missing and checked (`first_file`
// can be written there) before any work. A folder it had to create is removed again unless
// Keep() is called once the results are written; a folder that existed is never removed.
class OutputFolder {
 public:
  OutputFolder(const std::string& folder, const char* first_file);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& path() const { return path_; }  // with a trailing slash
  void Keep();

 private:
  std::string folder_, path_;
  int temp_handle_ = 0;  // registered while a folder this made may still be removed
};

// Files removed when this goes, and registered in util/temp_registry meanwhile, so a stop
// removes them too. Each is removed before it is unregistered, so a stop arriving while an
// error unwinds cannot leave one behind.
class ScratchFiles {
 public:
  explicit ScratchFiles(const std::vector<std::string>& paths);
  ~ScratchFiles();
  ScratchFiles(const ScratchFiles&) = delete;
  ScratchFiles& operator=(const ScratchFiles&) = delete;

 private:
  std::vector<std::string> paths_;
  std::vector<int> handles_;
};

}  // namespace hexgait
