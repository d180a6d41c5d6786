// mhcontact: thin main; everything lives in the library (lib/src/cli.cpp).
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  std::vector<std::string> args(argv + 1, argv + argc);
  return mh::run_cli(args, std::cout, std::cerr);
}
