// The exact fallbacks of the inline filters: core/predicates.hpp has the same sign conventions.
#include "generate/filtered_predicates3d.hpp"

#include "core/predicates.hpp"

namespace riemesh::detail {

namespace {
int sign(double x) { return (x > 0) - (x < 0); }
}  // namespace

int orient3d_exact_sign(const double* a, const double* b, const double* c, const double* d) {
  return sign(orient3d(a, b, c, d));
}

int insphere_exact_sign(const double* a, const double* b, const double* c, const double* d,
                        const double* e) {
  return sign(insphere(a, b, c, d, e));
}

int orient3d_filtered_sign(const double* a, const double* b, const double* c, const double* d) {
  return orient3d_sign(a, b, c, d);
}

int insphere_filtered_sign(const double* a, const double* b, const double* c, const double* d,
                           const double* e) {
  return insphere_sign(a, b, c, d, e);
}

}  // namespace riemesh::detail
