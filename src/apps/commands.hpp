#pragma once
// Each subcommand family registers itself on the top-level CLI11 app. Command bodies stay thin:
// parse, call the library, print. Errors thrown as riemesh::InputError become exit code 2.
#include <CLI/CLI.hpp>

namespace riemesh::cli {

/// `riemesh metric ...` (the metric calculator and, later, metric construction).
void register_metric(CLI::App& app);
/// `riemesh demo`: a short tour on embedded inputs.
void register_demo(CLI::App& app);

}  // namespace riemesh::cli
