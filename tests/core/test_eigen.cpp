#include <gtest/gtest.h>

#include "core/eigen.hpp"

using namespace riemesh;

TEST(Eigen, DiagonalIsExact) {
  const SymEigen<3> e = eigen(SymMat3{{3.0, 0.0, 1.0, 0.0, 0.0, 2.0}});
  EXPECT_EQ(e.values[0], 1.0);
  EXPECT_EQ(e.values[1], 2.0);
  EXPECT_EQ(e.values[2], 3.0);
}
