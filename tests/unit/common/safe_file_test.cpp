// common/safe_file: files are created new and never written through a symbolic link, into a pipe
// or over another user's file; a hard link to an earlier result is replaced, not written.
#include "common/error.hpp"
#include "common/safe_file.hpp"
#include "test_util.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace gapfem;
namespace fs = std::filesystem;

namespace {

/// The test's directory, emptied (a rerun finds no pipe or link of the run before).
fs::path fresh_dir() {
  const fs::path dir = gapfem::test::test_dir();
  for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
  return dir;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

/// A file outside the folder the functions are given, whose content must never change.
struct Sentinel {
  fs::path path;
  explicit Sentinel(const fs::path& dir) : path(dir / "outside.txt") { write_text(path, "keep\n"); }
  bool intact() const { return gapfem::test::slurp(path) == "keep\n"; }
};

} // namespace

TEST(SafeFile, CreateNewReplacesAnEarlierRegularFileAndItsHardLinkedTwinIsUntouched) {
  const fs::path dir = fresh_dir();
  const Sentinel outside(dir);
  const fs::path out = dir / "out";
  fs::create_directories(out);
  const fs::path p = out / "job.dat";
  ASSERT_EQ(::link(outside.path.c_str(), p.c_str()), 0); // job.dat is another name of outside
  const int fd = files::create_new(p);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::write(fd, "new\n", 4), 4);
  ::close(fd);
  EXPECT_EQ(gapfem::test::slurp(p), "new\n");
  EXPECT_TRUE(outside.intact());
}

TEST(SafeFile, LinksPipesAndDirectoriesAreRefusedNamingWhatTheyAre) {
  const fs::path dir = fresh_dir();
  const Sentinel outside(dir);
  const fs::path out = dir / "out";
  fs::create_directories(out);
  const fs::path link = out / "a.dat", fifo = out / "b.dat", sub = out / "c.dat";
  fs::create_symlink(outside.path, link);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  fs::create_directory(sub);
  struct Case {
    fs::path path;
    const char* kind;
  };
  for (const Case& c : {Case{link, "a symbolic link"}, Case{fifo, "a named pipe (FIFO)"},
                        Case{sub, "a directory"}}) {
    for (int op = 0; op < 4; ++op) {
      try {
        switch (op) {
        case 0:
          files::create_new(c.path);
          break;
        case 1:
          files::open_own(c.path);
          break;
        case 2:
          files::check_replaceable(c.path);
          break;
        default:
          files::write_replace(c.path, "x");
        }
        ADD_FAILURE() << c.path << " op " << op << " was not refused";
      } catch (const AnalysisError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(c.path.string()), std::string::npos) << m;
        EXPECT_NE(m.find(c.kind), std::string::npos) << m;
        EXPECT_NE(m.find("remove it"), std::string::npos) << m;
      }
    }
  }
  EXPECT_TRUE(outside.intact());
  EXPECT_EQ(files::kind_of(link), files::Kind::Symlink);
  EXPECT_EQ(files::kind_of(fifo), files::Kind::Fifo);
}

TEST(SafeFile, AFileIsContinuedOnlyWhenItIsOursWithOneName) {
  const fs::path dir = fresh_dir();
  const fs::path p = dir / "job.sta", twin = dir / "twin.sta";
  write_text(p, "line\n");
  const int fd = files::open_own(p);
  ASSERT_GE(fd, 0);
  ::close(fd);
  ASSERT_EQ(::link(p.c_str(), twin.c_str()), 0);
  try {
    files::open_own(p);
    ADD_FAILURE() << "a file with two names was continued";
  } catch (const AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("2 names (hard links)"), std::string::npos) << e.what();
  }
  fs::remove(twin);
  EXPECT_LT(files::open_own(dir / "missing.sta"), 0);
  EXPECT_EQ(errno, ENOENT);
}

TEST(SafeFile, ReadingAPipeIsRefusedInsteadOfBlocking) {
  const fs::path dir = fresh_dir();
  const fs::path fifo = dir / "old.res";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::string text;
  EXPECT_THROW(files::read_all(fifo, text), AnalysisError); // returns at once (O_NONBLOCK)
  write_text(dir / "data", "abc");
  ASSERT_TRUE(files::read_all(dir / "data", text));
  EXPECT_EQ(text, "abc");
}

TEST(SafeFile, WriteReplaceLeavesOneCompleteFileAndNoStagingCopy) {
  const fs::path dir = fresh_dir();
  const fs::path p = dir / "lib.sub";
  ASSERT_TRUE(files::write_replace(p, "first"));
  ASSERT_TRUE(files::write_replace(p, "second"));
  EXPECT_EQ(gapfem::test::slurp(p), "second");
  EXPECT_FALSE(fs::exists(dir / "lib.sub.tmp"));
  // a link planted at the staging name is refused, never followed
  const Sentinel outside(dir);
  fs::create_symlink(outside.path, dir / "lib.sub.tmp");
  EXPECT_THROW(files::write_replace(p, "third"), AnalysisError);
  EXPECT_TRUE(outside.intact());
  EXPECT_EQ(gapfem::test::slurp(p), "second");
}

TEST(SafeFile, FreshPrivateDirectoryEmptiesOursAndRefusesALink) {
  const fs::path dir = fresh_dir();
  const Sentinel outside(dir);
  const fs::path scratch = dir / "job.scratch";
  ASSERT_TRUE(files::fresh_private_directory(scratch));
  write_text(scratch / "old.o", "x");
  fs::create_symlink(outside.path, scratch / "link");
  ASSERT_TRUE(files::fresh_private_directory(scratch));
  EXPECT_TRUE(fs::is_empty(scratch));
  EXPECT_TRUE(outside.intact());
  struct stat st {};
  ASSERT_EQ(::stat(scratch.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0700u);
  fs::remove(scratch);
  fs::create_directory_symlink(dir, scratch);
  EXPECT_THROW(files::fresh_private_directory(scratch), AnalysisError);
}
