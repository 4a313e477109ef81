#pragma once
// Errors of the library: exceptions carry one line that names what went wrong and where.
// The library never prints and never exits; the CLI turns an Error into a message and an exit code.
#include <stdexcept>
#include <string>

namespace riemesh {

/// A real error (bad input, broken invariant, I/O), as opposed to an operator that declines.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input given by the user: a non-SPD metric, a degenerate simplex, a malformed number.
class InputError : public Error {
 public:
  using Error::Error;
};

namespace detail {
[[noreturn]] inline void check_failed(const char* cond, const char* file, int line) {
  throw Error(std::string("internal check failed: ") + cond + " at " + file + ":" +
              std::to_string(line));
}
}  // namespace detail

}  // namespace riemesh

/// Invariant check, always on: throws riemesh::Error naming the condition, file and line.
#define RIEMESH_CHECK(cond) \
  ((cond) ? (void)0 : ::riemesh::detail::check_failed(#cond, __FILE__, __LINE__))
