// The output folder of a run: the lock, the manifest (only the previous run's files removed) and
// atomic writes under unique temporary names.
#include <gtest/gtest.h>
#include <sys/file.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "dymesh/io/atomic_file.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/core/scenario.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;

class Folder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("dymesh_folder_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void Put(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  fs::path dir_;
};

TEST_F(Folder, ReplaceRemovesOnlyThePreviousRunsFiles) {
  {
    OutputFolder first(dir_.string(), {"a.obj", "report.html", "summary.json"});
    first.ReplacePreviousRun();
    for (const char* name : {"a.obj", "report.html", "summary.json"}) Put(name, "old");
  }
  Put("notes.txt", "mine");
  // a hostile manifest line must not reach outside the folder
  std::ofstream(dir_ / kManifestFileName, std::ios::app) << "../outside.txt\n/etc/hostname\n";
  std::ofstream(dir_.parent_path() / "outside.txt") << "keep";
  // an interrupted second run: it wrote b.obj only
  OutputFolder second(dir_.string(), {"b.obj", "report.html", "summary.json"});
  second.ReplacePreviousRun();
  Put("b.obj", "new");
  EXPECT_FALSE(fs::exists(dir_ / "a.obj"));
  EXPECT_FALSE(fs::exists(dir_ / "report.html"));  // the old complete report does not stay beside new files
  EXPECT_FALSE(fs::exists(dir_ / "summary.json"));
  EXPECT_TRUE(fs::exists(dir_ / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir_.parent_path() / "outside.txt"));
  fs::remove(dir_.parent_path() / "outside.txt");
}

TEST_F(Folder, SecondHolderIsRefusedUntilTheFirstReleases) {
  auto first = std::make_unique<OutputFolder>(dir_.string(), std::vector<std::string>{"x"});
  EXPECT_THROW(OutputFolder(dir_.string(), {"x"}), OutputFolderBusy);
  first.reset();
  EXPECT_NO_THROW(OutputFolder(dir_.string(), {"x"}));
}

TEST_F(Folder, NameTooLongForTheFolderIsRefused) {
  try {
    OutputFolder folder(dir_.string(), {std::string(250, 'n')});
    FAIL() << "accepted a 250-byte name";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--out");
    EXPECT_NE(std::string(e.what()).find("is 250 bytes"), std::string::npos) << e.what();
  }
}

TEST_F(Folder, ConcurrentAtomicWritesNeverShareATemporary) {
  // two writers of the same file: each write lands whole, no temporary is left behind
  fs::create_directories(dir_);
  const std::string path = (dir_ / "same.txt").string();
  const std::string a(100000, 'a'), b(100000, 'b');
  auto writer = [&](const std::string& text) {
    for (int i = 0; i < 50; ++i) WriteFileAtomically(path, text);
  };
  std::thread ta(writer, a), tb(writer, b);
  ta.join();
  tb.join();
  std::ifstream in(path);
  const std::string got((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(got == a || got == b);
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) {
    ++files;
    EXPECT_EQ(e.path().filename(), "same.txt");
  }
  EXPECT_EQ(files, 1);
}

}  // namespace
}  // namespace dymesh
