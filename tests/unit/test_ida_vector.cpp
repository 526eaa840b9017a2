// linearize/ida_vector.hpp: the vector kernels handed to IDA give bitwise the results of SUNDIALS'
// own serial vector (N_VNew_Serial), case by case — so IDA takes the same steps with either.
#include <gtest/gtest.h>
#include <sundials/sundials_context.h>

#include <cstring>
#include <random>
#include <vector>

#include "linearize/ida_vector.hpp"

namespace whirl {
namespace {

struct Vectors {
  static constexpr int kN = 37;  // not a multiple of the SIMD width: the loops' remainders run too
  SUNContext ctx = nullptr;
  std::vector<N_Vector> fast, plain;
  explicit Vectors(int count) {
    SUNContext_Create(nullptr, &ctx);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-3, 3);
    for (int k = 0; k < count; ++k) {
      fast.push_back(newFastSerialVector(kN, ctx));
      plain.push_back(N_VNew_Serial(kN, ctx));
      for (int i = 0; i < kN; ++i) NV_Ith_S(fast[k], i) = NV_Ith_S(plain[k], i) = u(rng) * std::exp(u(rng));
    }
  }
  ~Vectors() {
    for (N_Vector v : fast) N_VDestroy(v);
    for (N_Vector v : plain) N_VDestroy(v);
    SUNContext_Free(&ctx);
  }
  void expectSame(int k, const char* what) const {
    EXPECT_EQ(std::memcmp(NV_DATA_S(fast[k]), NV_DATA_S(plain[k]), kN * sizeof(double)), 0) << what;
  }
};

TEST(IdaVector, LinearSumEveryCaseMatchesSundialsBitwise) {
  // The special cases of N_VLinearSum_Serial (a, b = ±1, a = ±b, in place) and the general one.
  const std::vector<std::pair<double, double>> ab = {{1, 1},    {1, -1},   {-1, 1},    {1, 0.3},    {0.3, 1},
                                                     {-1, 0.3}, {0.3, -1}, {0.7, 0.7}, {0.7, -0.7}, {0.3, -2.9}};
  for (const auto& [a, b] : ab)
    for (int target : {2, 0, 1}) {  // z separate, z = x, z = y
      Vectors v(3);
      N_VLinearSum(a, v.fast[0], b, v.fast[1], v.fast[target]);
      N_VLinearSum(a, v.plain[0], b, v.plain[1], v.plain[target]);
      v.expectSame(target, "linear sum");
    }
}

TEST(IdaVector, ScaleNormsAndElementwiseMatchSundialsBitwise) {
  for (double c : {1.0, -1.0, 0.37}) {
    Vectors v(2);
    N_VScale(c, v.fast[0], v.fast[1]);
    N_VScale(c, v.plain[0], v.plain[1]);
    v.expectSame(1, "scale");
    N_VScale(c, v.fast[0], v.fast[0]);
    N_VScale(c, v.plain[0], v.plain[0]);
    v.expectSame(0, "scale in place");
  }
  Vectors v(4);
  EXPECT_EQ(N_VWrmsNorm(v.fast[0], v.fast[1]), N_VWrmsNorm(v.plain[0], v.plain[1]));
  EXPECT_EQ(N_VMin(v.fast[0]), N_VMin(v.plain[0]));
  N_VProd(v.fast[0], v.fast[1], v.fast[2]);
  N_VProd(v.plain[0], v.plain[1], v.plain[2]);
  v.expectSame(2, "product");
  N_VAbs(v.fast[0], v.fast[3]);
  N_VAbs(v.plain[0], v.plain[3]);
  v.expectSame(3, "abs");
  N_VInv(v.fast[3], v.fast[2]);
  N_VInv(v.plain[3], v.plain[2]);
  v.expectSame(2, "inverse");
  N_VAddConst(v.fast[1], 0.25, v.fast[2]);
  N_VAddConst(v.plain[1], 0.25, v.plain[2]);
  v.expectSame(2, "add constant");
  N_VConst(1.5, v.fast[2]);
  N_VConst(1.5, v.plain[2]);
  v.expectSame(2, "constant");
}

TEST(IdaVector, FusedOperationsMatchSundialsFallbackBitwise) {
  // SUNDIALS' serial vector has its fused operations off: the generic layer then loops over
  // N_VScale and N_VLinearSum. The fused kernels must give the same bits.
  double c[4] = {0.3, -1.0, 1.0, 2.7};
  for (int nvec : {1, 2, 3, 4})
    for (bool in_place : {false, true}) {
      Vectors v(5);
      N_Vector* X = v.fast.data();
      N_Vector* Y = v.plain.data();
      N_Vector zf = in_place ? X[0] : X[4], zp = in_place ? Y[0] : Y[4];
      N_VLinearCombination(nvec, c, X, zf);
      N_VLinearCombination(nvec, c, Y, zp);
      v.expectSame(in_place ? 0 : 4, "linear combination");
    }
  Vectors v(6);
  N_VLinearSumVectorArray(2, 0.3, &v.fast[0], -2.9, &v.fast[2], &v.fast[4]);
  N_VLinearSumVectorArray(2, 0.3, &v.plain[0], -2.9, &v.plain[2], &v.plain[4]);
  v.expectSame(4, "linear sum array");
  v.expectSame(5, "linear sum array");
  N_VScaleVectorArray(2, c, &v.fast[0], &v.fast[2]);
  N_VScaleVectorArray(2, c, &v.plain[0], &v.plain[2]);
  v.expectSame(2, "scale array");
  v.expectSame(3, "scale array");
}

}  // namespace
}  // namespace whirl
