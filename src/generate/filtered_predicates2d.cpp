// The exact fallbacks of the inline 2D filters: core/predicates.hpp has the same sign conventions.
#include "generate/filtered_predicates2d.hpp"

#include "core/predicates.hpp"

namespace riemesh::detail {

namespace {
int sign(double x) { return (x > 0) - (x < 0); }
}  // namespace

int orient2d_exact_sign(const double* a, const double* b, const double* c) {
  return sign(orient2d(a, b, c));
}

int incircle_sign_cold(const double* a, const double* b, const double* c, const double* d) {
  return incircle_sign(a, b, c, d);
}

int incircle_exact_sign(const double* a, const double* b, const double* c, const double* d) {
  return sign(incircle(a, b, c, d));
}

}  // namespace riemesh::detail
