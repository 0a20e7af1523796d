// A main script not found as given is looked up as an import is: $ESC_PATH's directories in
// order, then the standard library; one that exists as given, or an absolute path, is
// taken as it is, and one found nowhere is left for the compiler to report.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "app/import_path.hpp"

namespace esc::app {
namespace {

namespace fs = std::filesystem;

class MainScript : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("esc-main-script-" + std::to_string(getpid()));
    fs::remove_all(root_);
    for (const char* dir : {"first/paper", "second/paper", "library/paper", "cwd"}) fs::create_directories(root_ / dir);
    for (const char* file : {"second/paper/a.esc", "library/paper/a.esc", "library/paper/b.esc", "cwd/here.esc"})
      std::ofstream(root_ / file) << "// a script\n";
    previous_ = fs::current_path();
    fs::current_path(root_ / "cwd");
    ASSERT_EQ(setenv("ESC_PATH", ((root_ / "first").string() + ":" + (root_ / "second").string()).c_str(), 1), 0);
  }
  void TearDown() override {
    unsetenv("ESC_PATH");
    fs::current_path(previous_);
    fs::remove_all(root_);
  }
  fs::path root_;
  fs::path previous_;
};

TEST_F(MainScript, IsLookedUpInEscPathThenTheLibrary) {
  const fs::path library = root_ / "library";
  EXPECT_EQ(find_main_script("paper/a.esc", library), root_ / "second/paper/a.esc");   // the first that holds it
  EXPECT_EQ(find_main_script("paper/b.esc", library), root_ / "library/paper/b.esc");
  unsetenv("ESC_PATH");
  EXPECT_EQ(find_main_script("paper/a.esc", library), root_ / "library/paper/a.esc");
}

TEST_F(MainScript, AsGivenWhenItExistsIsAbsoluteOrIsNowhere) {
  const fs::path library = root_ / "library";
  EXPECT_EQ(find_main_script("here.esc", library), fs::path("here.esc"));
  std::ofstream("a.esc") << "// beside\n";
  EXPECT_EQ(find_main_script("a.esc", library), fs::path("a.esc"));
  EXPECT_EQ(find_main_script(root_ / "cwd/absent.esc", library), root_ / "cwd/absent.esc");
  EXPECT_EQ(find_main_script("paper/absent.esc", library), fs::path("paper/absent.esc"));
  EXPECT_EQ(find_main_script("paper", library), fs::path("paper"));   // directories are no scripts
  EXPECT_EQ(find_main_script("", library), fs::path());
}

}  // namespace
}  // namespace esc::app
