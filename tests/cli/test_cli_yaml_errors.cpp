// Malformed YAML case files through the command line (issue 48, item 5): each is an input error
// naming the file and line (and the key where there is one), exit status 1, and none of yaml-cpp's
// own text ("yaml-cpp: error at line …", "bad conversion", `YAML::…`): whirl() checks every message
// for library text (tests/cli/cli_support.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/cli_support.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

struct BadYaml {
  const char* name;    ///< file name, and the test's label
  const char* text;    ///< the case file
  const char* expect;  ///< what the message says after "whirl: error: <file>:"
};

// Each text is a complete small case but for its one fault.
const std::vector<BadYaml> kBad = {
    {"unclosed_list", "name: x\nbodies: [\n", "3: YAML syntax error: end of sequence flow not found"},
    {"bad_indent", "name: x\n  bad: indent\n bodies: 1\n", "2: YAML syntax error: illegal map value"},
    {"unknown_anchor", "name: x\nbodies: *b\n", "2: YAML syntax error: the referenced anchor is not defined"},
    {"unterminated_string", "\"unterminated", "1: YAML syntax error: illegal EOF in scalar"},
    {"key_twice", "name: x\nname: y\nbodies: []\n", "2: name: key 'name' given twice"},
    {"map_for_list", "name: x\nbodies: {a: 1}\n", "2: bodies: expected a list, got a map"},
    {"list_key", "? [a, b]\n: c\n", "1: a key must be a plain name, got a list"},
    {"merge_key", "name: x\n<<: {gravity: 9.8}\nbodies: []\n", "2: <<: unknown key '<<'"},
    {"repeated_directive", "%YAML 1.1\n%YAML 1.1\n---\nname: x\n", "2: YAML syntax error: repeated YAML directive"},
    {"binary_number", "name: x\ngravity: !!binary AAAA\nbodies: []\n", "2: gravity: expected a number"},
    {"tagged_number", "name: x\ngravity: !<tag:yaml.org,2002:int> abc\nbodies: []\n", "2: gravity: expected a number"},
    {"tab_indent", "name: x\nbodies:\n\t- name: b\n", "3: YAML syntax error"},
    {"single_value", "\"just a string\n",
     "1: a case file is a map of keys (name, gravity, bodies, ...), this one is "
     "empty, a list or a single value"},
};

TEST(CliYamlErrors, MalformedCasesNameFileAndLine) {
  const auto dir = test::freshDir("yaml_errors");
  for (const BadYaml& b : kBad) {
    const auto file = dir / (std::string(b.name) + ".yaml");
    std::ofstream(file) << b.text;
    const test::Run r = test::whirl("modes '" + file.string() + "'");
    EXPECT_EQ(r.code, 1) << b.name << ": " << r.err;
    EXPECT_THAT(r.err, StartsWith("whirl: error: " + file.string() + ":" + b.expect)) << b.name;
    EXPECT_EQ(r.out, "") << b.name;
  }
}

TEST(CliYamlErrors, SecondDocumentIsRefused) {
  // yaml-cpp's Load reads the first document only: the rest of a file after a `---` line was ignored.
  const auto dir = test::freshDir("yaml_two_documents");
  const std::string one = test::slurp(std::filesystem::path(WHIRL_SOURCE_DIR) /
                                      "cases/landbased_2dof/landbased_2dof.yaml");
  const auto file = dir / "two.yaml";
  std::ofstream(file) << one << "---\nname: other\ngravity: 3.7\n";
  const test::Run r = test::whirl("modes '" + file.string() + "'");
  EXPECT_EQ(r.code, 1) << r.out;
  const int second_line = static_cast<int>(std::count(one.begin(), one.end(), '\n')) + 2;
  EXPECT_THAT(r.err, HasSubstr(file.string() + ":" + std::to_string(second_line) +
                               ": a second YAML document (after a '---' line): a case file holds one"));
  // A `---` that only ends the file (an empty second document) stays accepted.
  const auto ended = dir / "ended.yaml";
  std::ofstream(ended) << one << "---\n";
  EXPECT_EQ(test::whirl("modes '" + ended.string() + "'").code, 0);
}

// The memory cap of the run below: 1 GB of address space, or under AddressSanitizer (whose shadow memory
// reserves terabytes of address space, so `ulimit -v` stops it before main) its own 1 GB cap on RSS.
#if defined(__SANITIZE_ADDRESS__)
#define WHIRL_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WHIRL_TEST_ASAN 1
#endif
#endif
#ifdef WHIRL_TEST_ASAN
const char* const kMemoryCap = "export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=1000; ";
#else
const char* const kMemoryCap = "ulimit -v 1000000; ";
#endif

TEST(CliYamlErrors, BytesOnWhichYamlCppFindsEndlessDocuments) {
  // tests/data/yaml/README.md: YAML::LoadAll never ended on these bytes (fuzz_cli). The run's memory is
  // capped (kMemoryCap), so a regression fails here instead of swapping the machine.
  const std::string file = std::string(WHIRL_SOURCE_DIR) + "/tests/data/yaml/loadall_endless.yaml";
  const auto err = test::freshDir("yaml_endless") / "err";
  const std::string cmd = std::string(kMemoryCap) + "'" + std::string(WHIRL_BINARY) + "' modes '" + file +
                          "' > /dev/null 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_EQ(test::slurp(err), "whirl: error: " + file +
                                  ":1: a case file is a map of keys (name, gravity, bodies, ...), this one is empty, a "
                                  "list or a single value\n");
}

TEST(CliYamlErrors, OverrideValuesThatAreNotYaml) {
  const std::string c = "cases/landbased_2dof/landbased_2dof.yaml";
  const test::Run list = test::whirl("modes " + c + " --set 'bodies.tower.length=[1,2'");
  EXPECT_EQ(list.code, 1);
  EXPECT_THAT(list.err, HasSubstr("landbased_2dof.yaml: bodies.tower.length: --set bodies.tower.length=[1,2: the value "
                                  "is not valid YAML: end of sequence flow not found"));
  const test::Run anchor = test::whirl("modes " + c + " --set 'bodies.tower={a: *b}'");
  EXPECT_EQ(anchor.code, 1);
  EXPECT_THAT(anchor.err, HasSubstr("the value is not valid YAML: the referenced anchor is not defined"));
  const test::Run scalar = test::whirl("modes " + c + " --set name.x=1");
  EXPECT_EQ(scalar.code, 1);
  EXPECT_THAT(scalar.err, HasSubstr("landbased_2dof.yaml:9: name: 'name' is a single value, it has no 'x'"));
}

}  // namespace
}  // namespace whirl
