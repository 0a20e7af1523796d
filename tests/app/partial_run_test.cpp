// Who may take over a dependency's unfinished run (cli/partial_run.hpp): a run whose
// process still lives is left alone; one whose process is gone is taken over when it holds
// a database, removed when it does not; and its lock file goes with it.
#include "app/partial_run.hpp"

#include <csignal>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace esc::app {
namespace {

namespace fs = std::filesystem;

fs::path fresh_cache(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("esc-partial-test-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A child process that starts a run of `entry` (with a database when `with_db`), tells
// the parent its directory, then waits to be killed (at the latest when this goes, so a
// failed assertion never leaves it behind).
struct Owner {
  Owner(const fs::path& entry, bool with_db);
  Owner(const Owner&) = delete;
  Owner& operator=(const Owner&) = delete;
  pid_t pid = -1;
  fs::path dir;
  void kill() {
    if (pid <= 0) return;
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    pid = -1;
  }
  ~Owner() { kill(); }
};

Owner::Owner(const fs::path& entry, bool with_db) {
  int ready[2];
  if (::pipe(ready) != 0) return;
  const pid_t child = ::fork();
  if (child == 0) {
    PartialRun run = PartialRun::create(entry);
    fs::create_directories(run.dir());
    if (with_db) std::ofstream(run.dir() / "esc.db") << "db";
    const std::string name = run.dir().string();
    (void)!::write(ready[1], name.data(), name.size());
    ::close(ready[1]);
    for (;;) ::pause();
  }
  ::close(ready[1]);
  pid = child;
  std::string name(4096, '\0');
  const ssize_t n = ::read(ready[0], name.data(), name.size());
  ::close(ready[0]);
  name.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  dir = name;
}

TEST(PartialRun, ALiveRunIsLeftAloneAGoneOneIsTakenOver) {
  const fs::path entry = fresh_cache("take-over") / "basic-0123";
  Owner owner(entry, true);
  ASSERT_TRUE(fs::is_directory(owner.dir)) << owner.dir;
  {
    const PartialRun mine = PartialRun::create(entry);
    EXPECT_NE(mine.dir(), owner.dir);
    EXPECT_FALSE(take_over_abandoned(entry, mine).has_value());
    EXPECT_TRUE(fs::exists(owner.dir / "esc.db"));
  }
  owner.kill();
  const PartialRun mine = PartialRun::create(entry);
  const auto taken = take_over_abandoned(entry, mine);
  ASSERT_TRUE(taken.has_value());
  EXPECT_EQ(*taken, owner.dir);
  EXPECT_TRUE(fs::exists(mine.dir() / "esc.db"));
  EXPECT_FALSE(fs::exists(owner.dir));
  EXPECT_FALSE(fs::exists(owner.dir.string() + ".lock"));
}

TEST(PartialRun, AGoneRunWithoutADatabaseIsRemovedAndLocksGoWithTheirOwners) {
  const fs::path cache = fresh_cache("remove");
  const fs::path entry = cache / "stop-4567";
  Owner owner(entry, false);
  ASSERT_TRUE(fs::is_directory(owner.dir)) << owner.dir;
  owner.kill();
  {
    const PartialRun mine = PartialRun::create(entry);
    EXPECT_FALSE(take_over_abandoned(entry, mine).has_value());
    EXPECT_FALSE(fs::exists(owner.dir));
    EXPECT_TRUE(fs::exists(mine.dir().string() + ".lock"));
  }
  // Nothing is left: the dead run, its lock, and this process's lock once released.
  EXPECT_TRUE(fs::is_empty(cache));
}

}  // namespace
}  // namespace esc::app
