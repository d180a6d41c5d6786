// OutputFile: the temporary-then-rename contract and the early writeback a long sweep uses
// (start_writeback after each chunk). Reference: the bytes written.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "output/output_file.hpp"

using namespace mh;
namespace fs = std::filesystem;

namespace {
std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
std::string temp_dir() {
  std::string t = (fs::temp_directory_path() / "mh_output_file_XXXXXX").string();
  REQUIRE(::mkdtemp(t.data()) != nullptr);
  return t;
}
}  // namespace

TEST_CASE("OutputFile: bytes written around start_writeback arrive whole, in order", "[output]") {
  const std::string dir = temp_dir();
  const std::string path = dir + "/cases.csv";
  std::string expect;
  {
    OutputFile f(path);
    // 5 chunks of 3 MB: start_writeback acts from 8 MB on, and is called after every chunk.
    for (int k = 0; k < 5; ++k) {
      std::string chunk(3u << 20, static_cast<char>('a' + k));
      chunk.back() = '\n';
      f.stream() << chunk;
      expect += chunk;
      f.start_writeback();
    }
    f.stream() << "tail\n";
    expect += "tail\n";
    CHECK_FALSE(fs::exists(path));  // nothing under the final name before commit
    f.commit();
  }
  const std::string got = slurp(path);
  CHECK(got.size() == expect.size());
  CHECK(got == expect);
  // Only the final file is left: no temporary beside it.
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) { (void)e; ++n; }
  CHECK(n == 1);
  fs::remove_all(dir);
}

TEST_CASE("OutputFile: destroyed without commit leaves nothing, even after a writeback", "[output]") {
  const std::string dir = temp_dir();
  {
    OutputFile f(dir + "/ellipses.csv");
    f.stream() << std::string(9u << 20, 'x');
    f.start_writeback();
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}
