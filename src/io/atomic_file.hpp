#pragma once
// Whole-file reads and all-or-nothing writes. A write goes to "<path>.tmp-XXXXXX" in the target
// folder and is renamed into place only when complete, so a failed or interrupted write never
// leaves a half-written file under the target name (DESIGN.md "Conventions").
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace riemesh {

/// The bytes of a file. Throws InputError (naming the file) if it cannot be opened or read.
std::string read_file_bytes(const std::string& path);

/// A file being written atomically: write(), then commit() to rename it into place. Destroying
/// it without commit() removes the temporary file. I/O failures (a missing or read-only folder, a
/// folder of the target's name, a full disk) throw InputError naming the path: they are the
/// user's to fix, not bugs; misuse (write after commit) throws riemesh::Error.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path, bool sync = false);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(const void* data, std::size_t size);
  void write(std::string_view text) { write(text.data(), text.size()); }
  /// Flushes, optionally fsyncs, closes and renames the temporary file to the target path.
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }

 private:
  void discard() noexcept;
  [[noreturn]] void fail(const char* what);

  std::string path_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  bool sync_ = false;
};

/// Throws InputError naming the path unless a file can be written there: its folder exists and
/// takes new files, and no folder has its name. Commands with several outputs call it for each
/// before any work, so that the last output cannot fail after the first is written.
void require_writable(const std::string& path);

/// Several outputs of one command, all or nothing: write(target, fn) has fn write the output to
/// a temporary name beside the target (same folder, same extension, so the writers pick the
/// format from it), and commit() renames them all into place once every one is written. A
/// failed write (a full disk) or a batch destroyed without commit() removes the temporaries
/// and leaves every target as it was. Errors name the target, not the temporary.
class OutputBatch {
 public:
  OutputBatch() = default;
  ~OutputBatch();
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  template <class Write>
  void write(const std::string& target, Write&& fn) {
    const std::string temp = stage(target);
    try {
      fn(temp);
    } catch (const InputError& e) {
      throw InputError(renamed(e.what(), temp, target));
    }
  }
  /// Renames every staged output into place. A rename that fails (rare: the temporaries sit in
  /// the targets' folders) throws InputError naming its target; the outputs renamed before it
  /// stay in place, the others are removed.
  void commit();

 private:
  std::string stage(const std::string& target);
  static std::string renamed(std::string message, const std::string& temp, const std::string& target);

  std::vector<std::pair<std::string, std::string>> staged_;  // (temporary, target)
};

/// Writes `contents` to `path` atomically.
void write_file_atomically(const std::string& path, std::string_view contents, bool sync = false);

}  // namespace riemesh
