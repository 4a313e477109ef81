#include "apps/pass_report.hpp"

#include <cstdio>

namespace riemesh::cli {

void print_pass(const PassStats& s, int verbosity, const char* elements, const char* label) {
  char stage[48] = "";
  if (s.stages > 1)
    std::snprintf(stage, sizeof stage, " (toward the metric: stage %d/%d)", s.stage, s.stages);
  std::fprintf(stderr,
               "%spass %2d%s: %zu vertices %zu %s, lengths in [1/√2, √2] %.1f%%, q_min %.3f "
               "(%.2f s)\n",
               label, s.pass, stage, s.vertices, s.triangles, elements, 100.0 * s.len_in, s.q_min,
               s.seconds);
  if (verbosity > 0)
    std::fprintf(stderr,
                 "         %ld splits %ld collapses %ld swaps %ld moves %ld refused; length "
                 "min %.3f mean %.3f max %.3f; q mean %.3f\n",
                 s.splits, s.collapses, s.swaps, s.moves, s.rejected, s.len_min, s.len_mean,
                 s.len_max, s.q_mean);
}

}  // namespace riemesh::cli
