// The riemesh command-line tool: one binary with subcommands, each with its own -h.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
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
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    riemesh::cli::translate_mmg_spellings(args);
  } catch (const riemesh::InputError& e) {
    std::fprintf(stderr, "riemesh: error: %s\n", e.what());
    return 2;
  }
  // The subcommands, in the order of `riemesh -h`. When the first argument names one, only that
  // one is set up (CLI11 builds every option of every subcommand: ~1 ms of a 0.05 s run).
  struct Command {
    const char* name;
    void (*add)(CLI::App&);
  };
  const Command commands[] = {
      {"metric", riemesh::cli::register_metric},       {"demo", riemesh::cli::register_demo},
      {"check", riemesh::cli::register_check},         {"stats", riemesh::cli::register_stats},
      {"convert", riemesh::cli::register_convert},     {"render", riemesh::cli::register_render},
      {"adapt", riemesh::cli::register_adapt},         {"loop", riemesh::cli::register_loop},
      {"transfer", riemesh::cli::register_transfer},   {"unsteady", riemesh::cli::register_unsteady},
      {"mesh", riemesh::cli::register_mesh},           {"distance", riemesh::cli::register_distance},
  };
  const std::string first = args.empty() ? std::string() : args.front();
  const bool named = std::any_of(std::begin(commands), std::end(commands),
                                 [&first](const Command& c) { return first == c.name; });
  for (const Command& c : commands)
    if (!named || first == c.name) c.add(app);
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
  } catch (const std::bad_alloc&) {
    // Not an internal error: the sizes asked for more than the machine gives (it was reported
    // as "internal error: std::bad_alloc", exit 3).
    std::fprintf(stderr,
                 "riemesh: error: out of memory: the run needs more memory than is available "
                 "(coarser sizes, or fewer of them, need less)\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "riemesh: internal error: %s\n", e.what());
    return 3;
  }
  return 0;
}
