// The studies' one command-line parser (experiments/run_options.h) and guarded_main's exit
// status for a command line it refuses (experiments/cli.h).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "../experiments/cli.h"
#include "../experiments/run_options.h"

using namespace grassfire::experiments;

namespace {

// argv from words (argv[0] = "study"), kept alive with the vector of strings.
struct Argv {
  explicit Argv(std::vector<std::string> words) : words_(std::move(words)) {
    words_.insert(words_.begin(), "study");
    for (std::string& w : words_) pointers_.push_back(w.data());
    pointers_.push_back(nullptr);
  }
  int argc() const { return static_cast<int>(words_.size()); }
  char** argv() { return pointers_.data(); }

 private:
  std::vector<std::string> words_;
  std::vector<char*> pointers_;
};

RunOptions parse(std::vector<std::string> words, const RunOptionSpec& spec) {
  Argv a(std::move(words));
  int argc = a.argc();
  return parse_run_options(argc, a.argv(), spec);
}

const RunOptionSpec kSpec{{"--quick"}, {"--seeds", "--kind"}, 1, 2};

}  // namespace

TEST_CASE("run options: flags, options, positionals and the shard in one pass", "[experiments]") {
  const RunOptions r = parse({"shapes", "--seeds", "4", "--shard", "1/3", "--quick", "out", "--kind", "a", "--kind", "b"}, kSpec);
  CHECK(r.positional == std::vector<std::string>{"shapes", "out"});
  CHECK(r.flag("--quick"));
  CHECK(r.count("--seeds", 3) == 4);
  CHECK(r.values("--kind") == std::vector<std::string>{"a", "b"});
  CHECK(r.text("--kind", "") == "b");
  CHECK(r.shard.index == 1);
  CHECK(r.shard.count == 3);
  const RunOptions d = parse({"shapes"}, kSpec);
  CHECK_FALSE(d.flag("--quick"));
  CHECK(d.count("--seeds", 3) == 3);
  CHECK(d.positional_or(1, ".") == ".");
  CHECK(d.shard.whole());
  CHECK(parse({"shapes", "-2.5"}, kSpec).positional_or(1, "") == "-2.5");  // a negative number is a value
}

TEST_CASE("run options: what a study does not accept is a UsageError naming it", "[experiments]") {
  auto message = [](std::vector<std::string> words, const RunOptionSpec& spec = kSpec) {
    try {
      (void)parse(std::move(words), spec).count("--seeds", 0);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(message({"shapes", "--sedes", "4"}) == "unknown option --sedes");
  CHECK(message({"shapes", "--seeds"}) == "--seeds needs a value");
  CHECK(message({}) == "missing argument");
  CHECK(message({"a", "b", "c"}) == "unexpected argument c");
  CHECK(message({"shapes", "--seeds", "four"}) == "--seeds needs a non-negative integer, got 'four'");
  CHECK(message({"shapes", "--shard", "3/3"}).find("--shard must be I/N") != std::string::npos);
  RunOptionSpec no_shard = kSpec;
  no_shard.shard = false;
  CHECK(message({"shapes", "--shard", "0/2"}, no_shard) == "unknown option --shard");
  CHECK(parse({"x", "--seeds", "1e3"}, {{}, {"--seeds"}, 1, 1}).number("--seeds", 0) == 1000);
  CHECK_THROWS_AS(parse({"x", "--seeds", "1e3x"}, {{}, {"--seeds"}, 1, 1}).number("--seeds", 0), UsageError);
}

TEST_CASE("run options: guarded_main exits 2 on a refused command line, before the study runs", "[experiments]") {
  static bool ran = false;
  ran = false;
  auto study = [](int argc, char** argv) {
    (void)parse_run_options(argc, argv, kSpec);
    ran = true;
    return 0;
  };
  Argv bad({"--nope"}), good({"shapes"});
  CHECK(guarded_main(bad.argc(), bad.argv(), "study", "usage: study\n", study) == 2);
  CHECK_FALSE(ran);
  CHECK(guarded_main(good.argc(), good.argv(), "study", "usage: study\n", study) == 0);
  CHECK(ran);
}
