#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <random>

#include "core/error.hpp"

namespace riemesh {

namespace {

std::string errno_text() { return std::strerror(errno); }

// Six random characters, different per call and per process.
std::string random_suffix() {
  static std::atomic<unsigned> counter{0};
  static const char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device device;
  std::mt19937 gen(device() ^ (static_cast<unsigned>(::getpid()) << 8) ^ counter++);
  std::string s(6, 'a');
  for (char& c : s) c = kAlphabet[gen() % (sizeof(kAlphabet) - 1)];
  return s;
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw InputError(path + ": cannot open for reading: " + errno_text());
  std::string bytes;
  struct stat st {};
  const bool stated = ::fstat(::fileno(f), &st) == 0;
  if (stated && S_ISDIR(st.st_mode)) {
    std::fclose(f);
    throw InputError(path + ": is a folder, not a file");  // (was "read error")
  }
  if (stated && S_ISREG(st.st_mode) && st.st_size > 0) {
    bytes.resize(static_cast<std::size_t>(st.st_size));
    bytes.resize(std::fread(bytes.data(), 1, bytes.size(), f));
  }
  char buffer[1 << 16];  // the rest, or all of a pipe or special file
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) bytes.append(buffer, n);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) throw InputError(path + ": read error");
  return bytes;
}

AtomicFile::AtomicFile(std::string path, bool sync) : path_(std::move(path)), sync_(sync) {
  // O_EXCL with a random name instead of mkstemp: mkstemp creates mode 0600, whereas open()
  // with 0666 lets the umask decide, as for any ordinary output file.
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp_path_ = path_ + ".tmp-" + random_suffix();
    const int fd = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
      if (errno == EEXIST) continue;
      throw InputError(path_ + ": cannot create temporary file " + temp_path_ + ": " +
                       errno_text());
    }
    file_ = ::fdopen(fd, "wb");
    if (!file_) {
      ::close(fd);
      ::unlink(temp_path_.c_str());
      throw InputError(path_ + ": cannot open temporary file: " + errno_text());
    }
    return;
  }
  throw InputError(path_ + ": cannot find a free temporary file name");
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
    ::unlink(temp_path_.c_str());
  }
}

void AtomicFile::fail(const char* what) {
  const std::string message = path_ + ": " + what + ": " + errno_text();
  discard();
  throw InputError(message);
}

void AtomicFile::write(const void* data, std::size_t size) {
  if (!file_) throw Error(path_ + ": write after commit");
  if (size > 0 && std::fwrite(data, 1, size, file_) != size) fail("write failed");
}

void AtomicFile::commit() {
  if (!file_) throw Error(path_ + ": commit without an open file");
  if (std::fflush(file_) != 0) fail("write failed");
  if (sync_ && ::fsync(::fileno(file_)) != 0) fail("fsync failed");
  std::FILE* f = file_;
  file_ = nullptr;
  if (std::fclose(f) != 0) {
    ::unlink(temp_path_.c_str());
    throw InputError(path_ + ": close failed: " + errno_text());
  }
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const std::string message =
        path_ + ": cannot rename temporary file into place: " + errno_text();
    ::unlink(temp_path_.c_str());
    throw InputError(message);
  }
}

void require_writable(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw InputError(path + ": is a folder, not a file name for the output");
  try {
    AtomicFile probe(path);  // creates a temporary beside the target; removed, uncommitted
  } catch (const InputError& e) {
    // Said of the output, not of the temporary the probe made ("cannot create temporary file
    // x.mesh.tmp-wnq771: No such file or directory"): the system's reason, after the last ": ".
    const std::string what = e.what();
    const std::size_t at = what.rfind(": ");
    throw InputError(path + ": cannot write the output there" +
                     (at == std::string::npos ? std::string() : " (" + what.substr(at + 2) + ")"));
  }
}

OutputBatch::~OutputBatch() {
  for (const auto& [temp, target] : staged_) (void)std::remove(temp.c_str());
}

std::string OutputBatch::stage(const std::string& target) {
  // "dir/name.ext" -> "dir/name.tmp-XXXXXX.ext": the extension kept for the writers.
  const std::size_t slash = target.find_last_of('/');
  const std::size_t dot = target.find_last_of('.');
  const std::size_t cut = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1)
                              ? dot
                              : target.size();
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string temp = target.substr(0, cut) + ".tmp-" + random_suffix() + target.substr(cut);
    struct stat st {};
    if (::stat(temp.c_str(), &st) == 0) continue;
    staged_.emplace_back(temp, target);
    return temp;
  }
  throw InputError(target + ": cannot find a free temporary file name");
}

std::string OutputBatch::renamed(std::string message, const std::string& temp,
                                 const std::string& target) {
  for (std::size_t at = message.find(temp); at != std::string::npos;
       at = message.find(temp, at + target.size()))
    message.replace(at, temp.size(), target);
  return message;
}

void OutputBatch::commit() {
  for (std::size_t k = 0; k < staged_.size(); ++k) {
    const auto& [temp, target] = staged_[k];
    if (std::rename(temp.c_str(), target.c_str()) != 0) {
      const std::string message = target + ": cannot rename temporary file into place: " + errno_text();
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(k));
      throw InputError(message);
    }
  }
  staged_.clear();
}

void write_file_atomically(const std::string& path, std::string_view contents, bool sync) {
  AtomicFile file(path, sync);
  file.write(contents);
  file.commit();
}

}  // namespace riemesh
