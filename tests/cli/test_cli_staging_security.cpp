// The staging folders of output sets (src/writers/output_set.hpp) in a folder others can write:
// whirl merges only a staging folder this user's whirl created (mkdtemp name, owner, mode 0700, its
// marker) and removes no file by its name alone. The two reproducers of issue 48, item 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "tests/cli/cli_support.hpp"

namespace whirl::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

const std::string kLinearize = "linearize cases/nrel5mw/Main_Onshore.fst --out ";
const std::string kHostile = "system('touch pwned')\n";

/// A staging folder planted beside `shared/out` by someone who can write `shared`.
fs::path plant(const fs::path& shared, const std::string& name) {
  const fs::path planted = shared / name;
  fs::create_directories(planted);
  std::ofstream(planted / ".whirl-commit") << "campbell.gp\n";
  std::ofstream(planted / "campbell.gp") << kHostile;
  return planted;
}

TEST(CliStagingSecurity, APlantedStagingFolderIsNotMerged) {
  const fs::path shared = freshDir("staging_planted");
  // The reproducer (the naming of whirl before mkdtemp), one with today's naming but the
  // default mode (0755 under umask 022), and one of mode 0700 without whirl's marker.
  const fs::path old_name = plant(shared, ".out.whirl-999996");
  const fs::path open_mode = plant(shared, ".out.whirl-4194305-abcdef");
  ::chmod(open_mode.c_str(), 0755);
  const fs::path no_marker = plant(shared, ".out.whirl-4194306-abcdef");
  ::chmod(no_marker.c_str(), 0700);
  const whirl::test::Run r = whirl(kLinearize + (shared / "out").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("completed the output of an interrupted run")));
  EXPECT_FALSE(fs::exists(shared / "out" / "campbell.gp")) << "a planted file was merged into the results";
  // Left as they were: whirl did not create them, so it neither reads nor removes them.
  for (const fs::path& p : {old_name, open_mode, no_marker}) EXPECT_EQ(slurp(p / "campbell.gp"), kHostile) << p;
}

TEST(CliStagingSecurity, ASymlinkedStagingFolderIsNotFollowed) {
  const fs::path shared = freshDir("staging_symlink");
  const fs::path target = shared / "elsewhere";
  fs::create_directories(target);
  ::chmod(target.c_str(), 0700);
  std::ofstream(target / ".whirl-commit") << "campbell.gp\n";
  std::ofstream(target / "campbell.gp") << kHostile;
  fs::create_directory_symlink(target, shared / ".out.whirl-4194305-abcdef");
  std::ofstream(target / ".whirl-staging") << ".out.whirl-4194305-abcdef";
  const whirl::test::Run r = whirl(kLinearize + (shared / "out").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(shared / "out" / "campbell.gp"));
  EXPECT_EQ(slurp(target / "campbell.gp"), kHostile);
}

TEST(CliStagingSecurity, AUsersTmpFileSurvives) {
  const fs::path shared = freshDir("staging_user_tmp");
  fs::create_directories(shared / "out");
  std::ofstream(shared / "out" / "data.tmp999999") << "the user's";
  std::ofstream(shared / "out" / ".data.tmp999999") << "the user's";
  for (int run = 0; run < 2; ++run) ASSERT_EQ(whirl(kLinearize + (shared / "out").string()).code, 0);
  EXPECT_EQ(slurp(shared / "out" / "data.tmp999999"), "the user's");
  EXPECT_EQ(slurp(shared / "out" / ".data.tmp999999"), "the user's");
}

TEST(CliStagingSecurity, StagingFoldersAreUnguessableAndPrivate) {
  // A run killed while writing leaves its staging folder: look at it through a Gnuplot stand-in that
  // records the folder it runs in (campbell renders its plot inside the staging folder).
  const fs::path dir = freshDir("staging_mode");
  fs::create_directories(dir / "bin");
  const fs::path gp = dir / "bin" / "gnuplot";
  std::ofstream(gp) << "#!/bin/sh\nstat -c '%a %u %n' \"$PWD\" > '" << (dir / "seen.txt").string() << "'\nexit 1\n";
  ::chmod(gp.c_str(), 0755);
  const std::string cmd = "cd '" + std::string(WHIRL_SOURCE_DIR) + "' && PATH='" + (dir / "bin").string() +
                          ":'\"$PATH\" '" + WHIRL_BINARY +
                          "' campbell cases/landbased_2dof/landbased_2dof.yaml "
                          "--rpm 0:5:10 --azimuths 4 --out '" +
                          (dir / "out").string() + "' 2> '" + (dir / "err.txt").string() + "'";
  whirl::test::Run r;
  const int status = std::system(cmd.c_str());
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(dir / "err.txt");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string seen = slurp(dir / "seen.txt");
  ASSERT_FALSE(seen.empty()) << r.err;
  EXPECT_EQ(seen.substr(0, 4), "700 ") << seen;
  EXPECT_EQ(seen.substr(4, seen.find(' ', 4) - 4), std::to_string(::geteuid())) << seen;
  EXPECT_THAT(seen, ::testing::ContainsRegex("/\\.out\\.whirl-[0-9]+-[A-Za-z0-9]{6}\n$")) << seen;
}

}  // namespace
}  // namespace whirl::test
