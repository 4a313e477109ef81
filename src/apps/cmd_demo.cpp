#include <cstdio>

#include "apps/commands.hpp"

namespace riemesh::cli {
void register_demo(CLI::App& app) {
  auto* demo = app.add_subcommand("demo", "A short tour on embedded inputs");
  demo->callback([] { std::printf("riemesh demo\n"); });
}
}  // namespace riemesh::cli
