// Outputs are complete or absent (common/io/output_file.h): a failed write keeps the previous file
// and leaves no temporary, and symbolic links, folders and devices are refused, not replaced.
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/output_file.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

namespace fs = std::filesystem;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The folder holds exactly these names (no temporary left behind).
void expectOnly(const std::string& dir, std::set<std::string> names) {
  std::set<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) found.insert(e.path().filename().string());
  EXPECT_EQ(found, names);
}

std::string errorOf(const std::function<void()>& write) {
  try {
    write();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputFile, ReplacesTheTargetWhole) {
  const std::string dir = testTempDir(), path = dir + "out.txt";
  writeFileAtomically(path, "first");
  writeFileAtomically(path, "second, longer");
  EXPECT_EQ(contents(path), "second, longer");
  expectOnly(dir, {"out.txt"});
}

// RLIMIT_FSIZE stands in for a full disk: the write fails part way (EFBIG, like ENOSPC).
TEST(OutputFile, AFailedWriteKeepsThePreviousFile) {
  const std::string dir = testTempDir(), path = dir + "out.txt";
  writeFileAtomically(path, "previous");
  signal(SIGXFSZ, SIG_IGN);
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  rlimit small = old;
  small.rlim_cur = 1000;
  setrlimit(RLIMIT_FSIZE, &small);
  const std::string error = errorOf([&] { writeFileAtomically(path, std::string(4000, 'x')); });
  setrlimit(RLIMIT_FSIZE, &old);
  EXPECT_NE(error.find(path + ": cannot write: File too large"), std::string::npos) << error;
  EXPECT_EQ(contents(path), "previous");
  expectOnly(dir, {"out.txt"});
}

TEST(OutputFile, RefusesLinksFoldersDevicesAndMissingFolders) {
  const std::string dir = testTempDir();
  writeFileAtomically(dir + "real.txt", "kept");
  fs::create_symlink(dir + "real.txt", dir + "link.txt");
  EXPECT_NE(errorOf([&] { writeFileAtomically(dir + "link.txt", "x"); }).find("symbolic link"),
            std::string::npos);
  EXPECT_EQ(contents(dir + "real.txt"), "kept");
  EXPECT_TRUE(fs::is_symlink(dir + "link.txt"));
  fs::create_directory(dir + "folder");
  EXPECT_NE(errorOf([&] { checkOutputPath(dir + "folder"); }).find("not a regular file"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { checkOutputPath("/dev/null"); }).find("not a regular file"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              writeFileAtomically(dir + "missing/out.txt", "x");
            }).find("missing/out.txt: cannot write: folder"),
            std::string::npos);
  expectOnly(dir, {"real.txt", "link.txt", "folder"});
}

// Every writer goes through it: an image into a missing folder fails and creates nothing.
TEST(OutputFile, ImageWritersUseIt) {
  const std::string dir = testTempDir();
  const Image image(4, 2);
  writeExr(dir + "a.exr", image);
  writePng(dir + "a.png", image);
  EXPECT_THROW(writeExr(dir + "no/a.exr", image), InputError);
  EXPECT_THROW(writePng(dir + "no/a.png", image), InputError);
  expectOnly(dir, {"a.exr", "a.png"});
  EXPECT_EQ(readExr(dir + "a.exr").width, 4);
}

}  // namespace
}  // namespace voxgi::test
