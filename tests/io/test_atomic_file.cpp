// Atomic writes: the target appears complete or not at all, and no temporary is left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <iterator>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

TEST(AtomicFile, CommitRenamesIntoPlace) {
  test::ScratchDir dir;
  const std::string path = dir.file("out.txt");
  test::write_text(path, "old contents");
  {
    AtomicFile file(path, /*sync=*/true);
    EXPECT_EQ(file.temp_path().rfind(path + ".tmp-", 0), 0u);
    file.write("new ");
    EXPECT_EQ(test::read_text(path), "old contents");  // untouched until commit
    file.write("contents");
    file.commit();
  }
  EXPECT_EQ(test::read_text(path), "new contents");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
  struct stat st {};
  ASSERT_EQ(stat(path.c_str(), &st), 0);
  EXPECT_NE(st.st_mode & 0044, 0u) << "the umask, not 0600, decides the mode";
}

// Several outputs all or nothing: written under temporary names that keep the extension, put
// in place together; a failing one leaves every target as it was, and no temporary.
TEST(OutputBatch, CommitsAllOrNone) {
  test::ScratchDir dir;
  const std::string a = dir.file("a.mesh"), b = dir.file("b.sol");
  test::write_text(a, "old a");
  std::string seen;
  try {
    OutputBatch batch;
    batch.write(a, [&](const std::string& path) {
      seen = path;
      write_file_atomically(path, "new a");
    });
    batch.write(b, [&](const std::string& path) {
      write_file_atomically(path, "partial b");
      throw InputError(path + ": write failed: No space left on device");
    });
    batch.commit();
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), b + ": write failed: No space left on device");
  }
  EXPECT_TRUE(seen.ends_with(".mesh") && seen.rfind(dir.file("a.tmp-"), 0) == 0) << seen;
  EXPECT_EQ(test::read_text(a), "old a");
  EXPECT_FALSE(std::filesystem::exists(b));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);

  OutputBatch batch;
  batch.write(a, [](const std::string& path) { write_file_atomically(path, "new a"); });
  batch.write(b, [](const std::string& path) { write_file_atomically(path, "new b"); });
  EXPECT_EQ(test::read_text(a), "old a");  // untouched until commit
  batch.commit();
  EXPECT_EQ(test::read_text(a), "new a");
  EXPECT_EQ(test::read_text(b), "new b");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2);
}

TEST(AtomicFile, AbandonedWriteLeavesNothing) {
  test::ScratchDir dir;
  const std::string path = dir.file("out.txt");
  try {
    AtomicFile file(path);
    file.write("partial");
    throw std::runtime_error("writer failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// An output that cannot be written is the user's to fix (a missing folder, a folder of that name):
// InputError, which the CLI reports with exit 2, not an internal error.
TEST(AtomicFile, ErrorsNameThePath) {
  try {
    write_file_atomically("/nonexistent-dir/x.mesh", "x");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent-dir/x.mesh: cannot create", 0), 0u)
        << e.what();
  }
  EXPECT_THROW(read_file_bytes("/nonexistent-dir/x.mesh"), InputError);
}

TEST(AtomicFile, FolderInTheWayIsAnInputErrorAndLeavesNothing) {
  test::ScratchDir dir;
  const std::string path = dir.file("out.mesh");
  std::filesystem::create_directory(path);
  try {
    write_file_atomically(path, "x");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
  // Only the folder itself: no temporary beside it.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(AtomicFile, RequireWritable) {
  test::ScratchDir dir;
  EXPECT_NO_THROW(require_writable(dir.file("out.mesh")));
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));  // the probe left nothing
  EXPECT_THROW(require_writable(dir.path()), InputError);
  EXPECT_THROW(require_writable("/nonexistent-dir/x.mesh"), InputError);
}

TEST(AtomicFile, ReadFileBytes) {
  test::ScratchDir dir;
  const std::string bytes("a\0b\nc", 5);
  write_file_atomically(dir.file("b"), bytes);
  EXPECT_EQ(read_file_bytes(dir.file("b")), bytes);
}

}  // namespace
}  // namespace riemesh
