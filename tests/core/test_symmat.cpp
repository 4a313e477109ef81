// Packed symmetric tensors: the storage order, determinant, inverse, congruence.
#include <gtest/gtest.h>

#include "core/random_metrics.hpp"
#include "core/symmat.hpp"

using namespace riemesh;

TEST(SymMat, PackedOrderIsSolOrder) {
  // The .sol order: 2D m11 m12 m22; 3D m11 m12 m22 m13 m23 m33.
  const SymMat3 m{{11, 12, 22, 13, 23, 33}};
  EXPECT_EQ(m(0, 0), 11);
  EXPECT_EQ(m(0, 1), 12);
  EXPECT_EQ(m(1, 0), 12);
  EXPECT_EQ(m(1, 1), 22);
  EXPECT_EQ(m(0, 2), 13);
  EXPECT_EQ(m(2, 1), 23);
  EXPECT_EQ(m(2, 2), 33);
  const SymMat2 n{{11, 12, 22}};
  EXPECT_EQ(n(1, 0), 12);
  EXPECT_EQ(n(1, 1), 22);
}

TEST(SymMat, DeterminantAndInverse) {
  // det [[4,1,0],[1,3,1],[0,1,2]] = 4(6-1) - 1(2-0) = 18.
  const SymMat3 m{{4, 1, 3, 0, 1, 2}};
  EXPECT_DOUBLE_EQ(det(m), 18.0);
  const Mat3 p = m.to_mat() * inverse(m).to_mat();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p(i, j), i == j ? 1.0 : 0.0, 1e-15);
  const SymMat2 m2{{2, 1, 3}};
  EXPECT_DOUBLE_EQ(det(m2), 5.0);
  EXPECT_NEAR(inverse(m2)(0, 1), -0.2, 1e-16);
}

TEST(SymMat, CongruenceMatchesDenseProduct) {
  std::mt19937_64 rng(1);
  const Mat3 p = riemesh::test_support::random_rotation<3>(rng);
  const SymMat3 s{{1, 2, 3, 4, 5, 6}};
  const Mat3 dense = p * s.to_mat() * transpose(p);
  const SymMat3 c = congruence(p, s);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(c(i, j), dense(i, j), 1e-13);
}

TEST(SymMat, QuadraticForm) {
  const SymMat2 m{{1, 0.5, 4}};
  // (1,2) M (1,2)ᵀ = 1 + 2·0.5·2 + 4·4 = 19.
  EXPECT_DOUBLE_EQ(quadratic(m, Vec2{{1, 2}}), 19.0);
}
