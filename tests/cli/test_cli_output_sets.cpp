// A command's output files appear together or not at all (README.md, *Reliability*): a target that
// cannot be written half-way through leaves the previous results untouched, and SIGKILL at any
// instant of a long `whirl export` leaves the folder with the complete previous set or the complete
// new one, never a mixture; the next run removes what the killed ones left behind.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <random>
#include <regex>
#include <thread>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kFst = "cases/nrel5mw/Main_Onshore.fst";

// The time stamp of a .lin header ("Predictions were generated on 25-Nov-2026 at 12:16:42"): the one
// thing two runs of the same command write differently.
const std::regex kStamp("on [0-9]{2}-[A-Za-z]{3}-[0-9]{4} at [0-9]{2}:[0-9]{2}:[0-9]{2}");

/// Every file under `dir` (relative path → content, time stamps masked), folders as "name/".
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string rel = fs::relative(e.path(), dir).string();
    if (e.is_directory()) s[rel + "/"] = "";
    else s[rel] = std::regex_replace(test::slurp(e.path()), kStamp, "on DATE at TIME");
  }
  return s;
}

/// Copies the files of `set` into `dir`, emptied first.
void restore(const fs::path& dir, const std::map<std::string, std::string>& set) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& [rel, text] : set) {
    if (rel.back() == '/') fs::create_directories(dir / rel);
    else std::ofstream(dir / rel, std::ios::binary) << text;
  }
}

/// Entries of `dir` with whirl's temporary naming (staging folders, `.tmp<pid>` files).
std::vector<std::string> whirlTemporaries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.find(".whirl-") != std::string::npos || n.find(".tmp") != std::string::npos) found.push_back(n);
  }
  return found;
}

std::string describe(const std::map<std::string, std::string>& s) {
  std::string d = std::to_string(s.size()) + " entries:";
  int n = 0;
  for (const auto& kv : s)
    if (++n <= 8) d += " " + kv.first;
  return d;
}

// ---- a destination that cannot be written half-way through ----------------------------------------

TEST(CliOutputSets, LinearizeFailingAtOneFileKeepsThePreviousSet) {
  const auto dir = test::freshDir("sets_linearize");
  const std::string yaml = "cases/landbased_2dof/landbased_2dof.yaml";
  ASSERT_EQ(test::whirl("linearize " + yaml + " --out " + dir.string()).code, 0);
  // The user replaced A.csv by a folder of their own: no file may take its place, not even for root.
  fs::remove(dir / "A.csv");
  fs::create_directories(dir / "A.csv");
  std::ofstream(dir / "A.csv" / "keep.txt") << "mine";
  const auto before = snapshot(dir);
  const auto r = test::whirl("linearize " + yaml + " --set gravity=5 --out " + dir.string());
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("A.csv: is a folder"));
  EXPECT_THAT(r.err, HasSubstr("previous results are unchanged"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(snapshot(dir), before) << "M, C, K, Q must not be replaced while A fails";
  EXPECT_THAT(whirlTemporaries(dir.parent_path()), ::testing::IsEmpty());
}

TEST(CliOutputSets, ExportFailingHalfWayKeepsThePreviousSet) {
  const auto dir = test::freshDir("sets_export");
  ASSERT_EQ(test::whirl("export " + kFst + " --rpm 9 --azimuths 4 --format lin --out " + dir.string()).code, 0);
  std::ofstream(dir / "notes.txt") << "another command's file";
  fs::create_directories(dir / "statespace.6.lin" / "sub");  // a folder where file 6 of 8 goes
  const auto before = snapshot(dir);
  const auto r = test::whirl("export " + kFst + " --rpm 9 --azimuths 8 --format lin --out " + dir.string());
  EXPECT_NE(r.code, 0);
  EXPECT_THAT(r.err, HasSubstr("statespace.6.lin: is a folder"));
  EXPECT_EQ(snapshot(dir), before) << "files 1-5 must not replace the previous ones";
  EXPECT_THAT(whirlTemporaries(dir), ::testing::IsEmpty());
  EXPECT_THAT(whirlTemporaries(dir.parent_path()), ::testing::IsEmpty());
  // Once the folder is out of the way the same command writes all 8, keeping the other file.
  fs::remove_all(dir / "statespace.6.lin");
  ASSERT_EQ(test::whirl("export " + kFst + " --rpm 9 --azimuths 8 --format lin --out " + dir.string()).code, 0);
  for (int k = 1; k <= 8; ++k) EXPECT_TRUE(fs::is_regular_file(dir / ("statespace." + std::to_string(k) + ".lin")));
  EXPECT_EQ(test::slurp(dir / "notes.txt"), "another command's file");
}

/// A staging folder as a killed whirl (process `pid`) leaves it: mkdtemp's name, mode 0700, the marker.
fs::path killedRunsStaging(const fs::path& folder, const std::string& prefix, const std::string& pid) {
  const fs::path staging = folder / (prefix + pid + "-a1B2c3");
  fs::create_directories(staging);
  fs::permissions(staging, fs::perms::owner_all);
  std::ofstream(staging / ".whirl-staging") << staging.filename().string();
  return staging;
}

TEST(CliOutputSets, StaleStagingFoldersOfDeadRunsAreRemovedAndNothingElse) {
  const auto dir = test::freshDir("sets_stale");
  // pid 2^22 + 1 is above the default pid_max (4194304): no running process has it.
  const std::string dead = "4194305";
  killedRunsStaging(dir, ".whirl-", dead);
  killedRunsStaging(dir.parent_path(), "." + dir.filename().string() + ".whirl-", dead);
  // Files are never removed by their name: these are the user's (issue 48, item 2).
  std::ofstream(dir / ("campbell_modes.json.tmp" + dead)) << "half";
  std::ofstream(dir / ("data.tmp" + dead)) << "mine";
  std::ofstream(dir / "data.tmp") << "not whirl's naming";
  const auto r = test::whirl("linearize cases/landbased_2dof/landbased_2dof.yaml --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(whirlTemporaries(dir),
              ::testing::UnorderedElementsAre("campbell_modes.json.tmp" + dead, "data.tmp" + dead, "data.tmp"));
  EXPECT_THAT(whirlTemporaries(dir.parent_path()), ::testing::IsEmpty());
}

TEST(CliOutputSets, InterruptedRollForwardIsCompletedByTheNextRun) {
  // The journal of a run killed while moving its files into place (what commit() leaves when the
  // folder cannot be swapped): the next run in that folder finishes the move first.
  const auto dir = test::freshDir("sets_journal");
  std::ofstream(dir / "a.csv") << "old a";
  std::ofstream(dir / "b.csv") << "old b";
  const fs::path staging = killedRunsStaging(dir, ".whirl-", "4194305");
  std::ofstream(staging / ".whirl-commit") << "a.csv\nb.csv\n";
  std::ofstream(staging / "b.csv") << "new b";  // a.csv was moved before the kill
  fs::remove(dir / "a.csv");
  std::ofstream(dir / "a.csv") << "new a";
  const auto r = test::whirl("linearize cases/landbased_2dof/landbased_2dof.yaml --out " + dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("completed the output of an interrupted run"));
  EXPECT_EQ(test::slurp(dir / "a.csv"), "new a");
  EXPECT_EQ(test::slurp(dir / "b.csv"), "new b");
  EXPECT_FALSE(fs::exists(staging));
}

// ---- SIGKILL at random instants -------------------------------------------------------------------

/// The binary under test; WHIRL_OUTPUT_SET_BINARY points it at another build (an older whirl shows
/// the mixtures this test exists to catch).
std::string binary() {
  const char* other = std::getenv("WHIRL_OUTPUT_SET_BINARY");
  return other && *other ? other : WHIRL_BINARY;
}

pid_t spawn(const std::vector<std::string>& args) {
  const std::string exe = binary();
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(WHIRL_SOURCE_DIR) != 0) ::_exit(126);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    std::vector<char*> argv{const_cast<char*>(exe.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(exe.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

/// True when process `pid` has started writing: its staging folder or a temporary file of its naming
/// is in `dir` or beside it (those of earlier, killed runs do not count).
bool writing(const fs::path& dir, pid_t pid) {
  const std::string p = std::to_string(pid);
  std::error_code ec;
  for (const fs::path& d : {dir, dir.parent_path()})
    for (const auto& e : fs::directory_iterator(d, ec)) {
      const std::string n = e.path().filename().string();
      if (n.find(".whirl-" + p + "-") != std::string::npos) return true;
    }
  return false;
}

/// Runs the command to its end, or kills it `delay` after its first temporary file appears (a
/// negative delay: −delay after the start); returns the exit status (−9 when killed).
int runKilled(const std::vector<std::string>& args, const fs::path& dir, double delay, double* write_time = nullptr) {
  const pid_t pid = spawn(args);
  const auto start = Clock::now();
  auto since = start;
  bool seen = false;
  int status = 0;
  for (;;) {
    if (::waitpid(pid, &status, WNOHANG) == pid) break;
    const auto now = Clock::now();
    if (!seen && writing(dir, pid)) {
      seen = true;
      since = now;
    }
    const bool fire = delay < 0 ? std::chrono::duration<double>(now - start).count() >= -delay
                                : seen && std::chrono::duration<double>(now - since).count() >= delay;
    if (fire) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  if (write_time) *write_time = seen ? std::chrono::duration<double>(Clock::now() - since).count() : 0;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

TEST(CliOutputSetsSlow, KilledExportLeavesTheOldSetOrTheNewOne) {
  // The case scaled down to keep the test under a minute: 26 operating points x 12 azimuths =
  // 312 .lin files (the issue: 36 azimuths, 936 files), into a folder holding a previous complete
  // export (8 azimuths: 208 files of other names and contents) and the files of other commands (a
  // file and a subfolder, which every run must keep).
  const auto base = test::freshDir("sets_kill");
  const fs::path dir = base / "out";
  auto args = [&](int azimuths) {
    return std::vector<std::string>{"export",     kFst,
                                    "--schedule", "cases/nrel5mw/NREL5MW_Oper.csv",
                                    "--azimuths", std::to_string(azimuths),
                                    "--format",   "lin",
                                    "--out",      dir.string()};
  };
  fs::create_directories(dir / "other" / "deep");
  std::ofstream(dir / "steady.csv") << "wind,rpm\n";
  std::ofstream(dir / "other" / "deep" / "x.txt") << "kept";
  ASSERT_EQ(runKilled(args(8), dir, 1e9), 0);
  const auto old_set = snapshot(dir);
  double write_time = 0;
  ASSERT_EQ(runKilled(args(12), dir, 1e9, &write_time), 0);
  const auto new_set = snapshot(dir);
  ASSERT_EQ(new_set.size(), 312u + 4u);  // + steady.csv, other/, other/deep/, other/deep/x.txt
  ASSERT_EQ(old_set.size(), 208u + 4u);
  ASSERT_GT(write_time, 0) << "whirl wrote no temporary file: the kills would all fall before the writing";

  constexpr int kKills = 12;
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> u(0, 1);
  int old_seen = 0, new_seen = 0;
  for (int i = 0; i < kKills; ++i) {
    restore(dir, old_set);
    // Computation; writing and committing; then more around the swap and the removal of the old tree.
    const double delay = i < 2 ? -0.05 - 0.2 * u(rng) : (i < 7 ? 1.2 * u(rng) : 0.7 + 0.6 * u(rng)) * write_time;
    const int rc = runKilled(args(12), dir, delay);
    const auto now = snapshot(dir);
    const bool is_old = now == old_set, is_new = now == new_set;
    old_seen += is_old;
    new_seen += is_new;
    EXPECT_TRUE(is_old || is_new) << "kill " << i << " after " << delay << " s (exit " << rc << "): the folder holds "
                                  << describe(now) << ", neither the old set nor the new one";
  }
  std::printf("%d kills: %d left the old set, %d the new one (writing and committing took %.3f s)\n", kKills, old_seen,
              new_seen, write_time);
  // The next complete run removes every temporary the killed runs left.
  ASSERT_EQ(runKilled(args(12), dir, 1e9), 0);
  EXPECT_EQ(snapshot(dir), new_set);
  EXPECT_THAT(whirlTemporaries(base), ::testing::IsEmpty());
}

}  // namespace
}  // namespace whirl
