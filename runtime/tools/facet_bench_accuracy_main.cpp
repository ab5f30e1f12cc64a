// Standalone entry for the accuracy study until it is a `facet bench` subcommand.
#include <iostream>

#include "facet/runtime/accuracy.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return facet::runtime::accuracy::run_accuracy_command(args, std::cout, std::cerr);
}
