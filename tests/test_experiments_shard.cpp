// --shard I/N (experiments/shard.h): the split is a partition, and the rows of three shards,
// concatenated and sorted, are the rows of the unsharded run (timing columns aside), for
// the studies that take a folder and for one that takes a list of spacings.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../experiments/shard.h"
#include "support.h"

using namespace grassfire;
using experiments::Shard;
using grassfire::testing::temp_path;

namespace {

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// The table with its wall-clock columns (named *_s or seconds, and ratios of them named
// *_ratio) blanked: they differ between any two runs.
std::vector<std::string> without_timings(const std::vector<std::string>& table) {
  const std::vector<std::string> header = split(table.at(0));
  std::vector<std::string> out;
  for (const std::string& line : table) {
    std::vector<std::string> f = split(line);
    std::string joined;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const std::string& name = i < header.size() ? header[i] : "";
      auto ends_with = [&](const std::string& tail) {
        return name.size() > tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
      };
      // The machine load (experiments/machine_load.h) varies between runs like the times.
      const bool timing = name == "seconds" || name == "load" || ends_with("_s") || ends_with("_ratio");
      joined += (i ? "," : "") + (timing && &line != &table[0] ? std::string("t") : f[i]);
    }
    out.push_back(joined);
  }
  return out;
}

// The recipe of experiments/shard.h: the header once, then every shard's rows, sorted.
std::vector<std::string> concatenate(const std::vector<std::vector<std::string>>& shards) {
  std::vector<std::string> rows;
  for (const auto& s : shards) rows.insert(rows.end(), s.begin() + 1, s.end());
  std::sort(rows.begin(), rows.end());
  rows.insert(rows.begin(), shards.at(0).at(0));
  return rows;
}

// Runs `command OUT` unsharded and as 3 shards (OUT a fresh folder each), and compares
// OUT/csv_name; `stdout_csv`: the rows go to stdout instead, redirected into OUT/csv_name.
void check_shards_concatenate(const std::string& name, const std::string& command, const std::string& csv_name,
                              bool stdout_csv = false) {
  auto run_into = [&](const std::string& dir, const std::string& shard) {
    std::filesystem::create_directories(dir);
    const std::string target = stdout_csv ? " > " + dir + "/" + csv_name : " " + dir;
    std::system((command + shard + target + " 2> /dev/null").c_str());
    return lines_of(dir + "/" + csv_name);
  };
  const std::string root = temp_path("shards_" + name);
  const std::vector<std::string> whole = run_into(root + "/whole", "");
  REQUIRE(whole.size() > 3);
  std::vector<std::vector<std::string>> shards;
  for (int i = 0; i < 3; ++i) {
    shards.push_back(run_into(root + "/" + std::to_string(i), " --shard " + std::to_string(i) + "/3"));
    CHECK(shards.back().at(0) == whole.at(0));
    CHECK(shards.back().size() < whole.size());
  }
  CHECK(without_timings(concatenate(shards)) == without_timings(whole));
  std::filesystem::remove_all(root);
}

// A small folder: five real shapes and one that is not simple (a failure row).
std::string small_folder() {
  const std::string dir = temp_path("shard_shapes");
  std::filesystem::create_directories(dir);
  for (const char* f : {"apple-1.json", "HCircle-1.json", "Heart-1.json", "bell-1.json", "hat-1.json"})
    std::filesystem::copy_file(std::string(GF_PROJECT_DATA) + "/shapes2d/" + f, dir + "/" + f,
                               std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(std::string(GF_TEST_DATA) + "/shapes/real_Glas-12.json", dir + "/Glas-12.json",
                             std::filesystem::copy_options::overwrite_existing);
  return dir;
}

}  // namespace

TEST_CASE("shard: I/N is parsed and checked", "[shard]") {
  const Shard s = experiments::parse_shard("2/5");
  CHECK(s.index == 2);
  CHECK(s.count == 5);
  for (const char* bad : {"5/5", "1/0", "a/3", "1", "-1/3", "1/3/4", "", "/3", "1/"})
    CHECK_THROWS_WITH(experiments::parse_shard(bad), Catch::StartsWith("--shard must be I/N"));
}

TEST_CASE("shard: the split is a partition in the original order", "[shard]") {
  std::vector<int> items(17);
  for (int i = 0; i < 17; ++i) items[i] = i;
  for (std::size_t n : {1, 2, 3, 5, 17, 20}) {
    std::vector<int> all;
    for (std::size_t i = 0; i < n; ++i) {
      const std::vector<int> mine = experiments::shard_of(items, Shard{i, n});
      CHECK(std::is_sorted(mine.begin(), mine.end()));
      all.insert(all.end(), mine.begin(), mine.end());
    }
    std::sort(all.begin(), all.end());
    CHECK(all == items);
  }
}

TEST_CASE("shard: take_shard removes the option from the command line", "[shard]") {
  std::string a0 = "study", a1 = "DIR", a2 = "--shard", a3 = "1/4", a4 = "OUT";
  char* argv[] = {a0.data(), a1.data(), a2.data(), a3.data(), a4.data(), nullptr};
  int argc = 5;
  const Shard s = experiments::take_shard(argc, argv);
  CHECK(s.index == 1);
  CHECK(s.count == 4);
  REQUIRE(argc == 3);
  CHECK(std::string(argv[1]) == "DIR");
  CHECK(std::string(argv[2]) == "OUT");
}

TEST_CASE("shard: three shards concatenate into the whole", "[shard][experiments]") {
  const std::string folder = small_folder();
  const std::string bin = GF_EXPERIMENTS;
  check_shards_concatenate("exact_axis", bin + "/study_exact_axis_throughput " + folder, "rows.csv", true);
  check_shards_concatenate("throughput", bin + "/bench_shapes_throughput " + folder, "shapes_throughput.csv");
  check_shards_concatenate("board_fin", bin + "/study_board_fin_convergence --quick", "board_fin_convergence.csv");
  std::filesystem::remove_all(folder);
}
