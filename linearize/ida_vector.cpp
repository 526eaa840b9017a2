#include "linearize/ida_vector.hpp"

#include <cmath>

namespace whirl {
namespace {

// Each operation follows nvector_serial.c of SUNDIALS 6.4.1 case by case (a·(x + y) is not
// a·x + a·y in floating point), so that IDA takes exactly the steps it takes with N_VNew_Serial.

struct View {
  double* d;
  sunindextype n;
};
View view(N_Vector v) { return {NV_DATA_S(v), NV_LENGTH_S(v)}; }

void axpy(double a, N_Vector x, N_Vector y) {  // y ← a x + y
  const View X = view(x), Y = view(y);
  if (a == 1.0) {
    for (sunindextype i = 0; i < X.n; ++i) Y.d[i] += X.d[i];
  } else if (a == -1.0) {
    for (sunindextype i = 0; i < X.n; ++i) Y.d[i] -= X.d[i];
  } else {
    for (sunindextype i = 0; i < X.n; ++i) Y.d[i] += a * X.d[i];
  }
}

void linearSum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
  if (b == 1.0 && z == y) return axpy(a, x, y);
  if (a == 1.0 && z == x) return axpy(b, y, x);
  const View X = view(x), Y = view(y), Z = view(z);
  const sunindextype n = X.n;
  if (a == 1.0 && b == 1.0) {
    for (sunindextype i = 0; i < n; ++i) Z.d[i] = X.d[i] + Y.d[i];
    return;
  }
  if ((a == 1.0 && b == -1.0) || (a == -1.0 && b == 1.0)) {
    const double* p = a == 1.0 ? X.d : Y.d;  // p − m
    const double* m = a == 1.0 ? Y.d : X.d;
    for (sunindextype i = 0; i < n; ++i) Z.d[i] = p[i] - m[i];
    return;
  }
  if (a == 1.0 || b == 1.0) {  // c v1 + v2
    const bool ta = a == 1.0;
    const double c = ta ? b : a;
    const double* v1 = ta ? Y.d : X.d;
    const double* v2 = ta ? X.d : Y.d;
    for (sunindextype i = 0; i < n; ++i) Z.d[i] = (c * v1[i]) + v2[i];
    return;
  }
  if (a == -1.0 || b == -1.0) {  // c v1 − v2
    const bool ta = a == -1.0;
    const double c = ta ? b : a;
    const double* v1 = ta ? Y.d : X.d;
    const double* v2 = ta ? X.d : Y.d;
    for (sunindextype i = 0; i < n; ++i) Z.d[i] = (c * v1[i]) - v2[i];
    return;
  }
  if (a == b) {
    for (sunindextype i = 0; i < n; ++i) Z.d[i] = a * (X.d[i] + Y.d[i]);
    return;
  }
  if (a == -b) {
    for (sunindextype i = 0; i < n; ++i) Z.d[i] = a * (X.d[i] - Y.d[i]);
    return;
  }
  for (sunindextype i = 0; i < n; ++i) Z.d[i] = (a * X.d[i]) + (b * Y.d[i]);
}

void constant(double c, N_Vector z) {
  const View Z = view(z);
  for (sunindextype i = 0; i < Z.n; ++i) Z.d[i] = c;
}

void scale(double c, N_Vector x, N_Vector z) {
  const View X = view(x), Z = view(z);
  if (z == x) {
    for (sunindextype i = 0; i < X.n; ++i) X.d[i] *= c;
  } else if (c == 1.0) {
    for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = X.d[i];
  } else if (c == -1.0) {
    for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = -X.d[i];
  } else {
    for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = c * X.d[i];
  }
}

void prod(N_Vector x, N_Vector y, N_Vector z) {
  const View X = view(x), Y = view(y), Z = view(z);
  for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = X.d[i] * Y.d[i];
}

void absolute(N_Vector x, N_Vector z) {
  const View X = view(x), Z = view(z);
  for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = std::abs(X.d[i]);
}

void inverse(N_Vector x, N_Vector z) {
  const View X = view(x), Z = view(z);
  for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = 1.0 / X.d[i];
}

void addConst(N_Vector x, double b, N_Vector z) {
  const View X = view(x), Z = view(z);
  for (sunindextype i = 0; i < X.n; ++i) Z.d[i] = X.d[i] + b;
}

double wrmsNorm(N_Vector x, N_Vector w) {
  const View X = view(x), W = view(w);
  double sum = 0;
  for (sunindextype i = 0; i < X.n; ++i) {
    const double p = X.d[i] * W.d[i];
    sum += p * p;
  }
  return std::sqrt(sum / static_cast<double>(X.n));
}

double minimum(N_Vector x) {
  const View X = view(x);
  double m = X.d[0];
  for (sunindextype i = 1; i < X.n; ++i)
    if (X.d[i] < m) m = X.d[i];
  return m;
}

// As SUNDIALS' generic N_VLinearCombination does for a serial vector (its fused operations are off by
// default): z = c0 X0, then z += c_i X_i one vector at a time.
int linearCombination(int nvec, double* c, N_Vector* X, N_Vector z) {
  if (nvec < 1) return -1;
  scale(c[0], X[0], z);
  for (int i = 1; i < nvec; ++i) axpy(c[i], X[i], z);
  return 0;
}

int scaleVectorArray(int nvec, double* c, N_Vector* X, N_Vector* Z) {
  if (nvec < 1) return -1;
  for (int i = 0; i < nvec; ++i) scale(c[i], X[i], Z[i]);  // c·x is exact for c = ±1
  return 0;
}

int linearSumVectorArray(int nvec, double a, N_Vector* X, double b, N_Vector* Y, N_Vector* Z) {
  if (nvec < 1) return -1;
  // As the generic N_VLinearSumVectorArray: one linear sum per vector.
  for (int i = 0; i < nvec; ++i) linearSum(a, X[i], b, Y[i], Z[i]);
  return 0;
}

}  // namespace

N_Vector newFastSerialVector(sunindextype n, SUNContext ctx) {
  N_Vector v = N_VNew_Serial(n, ctx);
  if (!v) return nullptr;
  N_Vector_Ops o = v->ops;
  o->nvlinearsum = linearSum;
  o->nvconst = constant;
  o->nvscale = scale;
  o->nvprod = prod;
  o->nvabs = absolute;
  o->nvinv = inverse;
  o->nvaddconst = addConst;
  o->nvwrmsnorm = wrmsNorm;
  o->nvmin = minimum;
  o->nvlinearcombination = linearCombination;
  o->nvscalevectorarray = scaleVectorArray;
  o->nvlinearsumvectorarray = linearSumVectorArray;
  return v;
}

}  // namespace whirl
