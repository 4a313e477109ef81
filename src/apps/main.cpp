// The riemesh command-line tool: one binary with subcommands, each with its own -h.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/memory_tuning.hpp"
#include "apps/mmg_spellings.hpp"
#include "core/error.hpp"
#include "core/version.hpp"

int main(int argc, char** argv) {
  riemesh::cli::tune_memory();
  CLI::App app{"Riemesh: metric-based mesh generation and adaptation"};
  app.name("riemesh");
  app.set_version_flag("--version", riemesh::version());
  app.require_subcommand(1);
  riemesh::cli::register_metric(app);
  riemesh::cli::register_demo(app);
  riemesh::cli::register_check(app);
  riemesh::cli::register_stats(app);
  riemesh::cli::register_convert(app);
  riemesh::cli::register_render(app);
  riemesh::cli::register_adapt(app);
  riemesh::cli::register_loop(app);
  riemesh::cli::register_transfer(app);
  riemesh::cli::register_unsteady(app);
  riemesh::cli::register_mesh(app);
  riemesh::cli::register_distance(app);
  std::vector<std::string> args(argv + 1, argv + argc);
  riemesh::cli::translate_mmg_spellings(args);
  std::reverse(args.begin(), args.end());  // CLI11 parses a vector from its back
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    // Help and version print and exit 0; usage errors are one line and exit 2.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "riemesh: error: %s (see -h)\n", e.what());
    return 2;
  } catch (const riemesh::cli::ExitStatus& e) {
    return e.code;
  } catch (const riemesh::InputError& e) {
    std::fprintf(stderr, "riemesh: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "riemesh: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
