// The riemesh command-line tool: one binary with subcommands, each with its own -h.
#include <cstdio>
#include <exception>

#include "apps/commands.hpp"
#include "core/error.hpp"
#include "core/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Riemesh: metric-based mesh generation and adaptation"};
  app.set_version_flag("--version", riemesh::version());
  app.require_subcommand(1);
  riemesh::cli::register_metric(app);
  riemesh::cli::register_demo(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Usage errors exit 2 (help and version exit 0), as documented in the README.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const riemesh::InputError& e) {
    std::fprintf(stderr, "riemesh: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "riemesh: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
