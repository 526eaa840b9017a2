#include "linearize/mbc.hpp"

#include <Eigen/Sparse>

#include <cmath>
#include <numbers>

#include "src/base/error.hpp"

namespace whirl {
namespace {

using Index = Eigen::Index;

[[noreturn]] void fail(const std::string& key, const std::string& reason) {
  throw InputError(where("", 0, "MBC " + key, reason));
}

MbcCoordinate coordinateOf(int m, int N) {
  if (m == 0) return {MbcKind::Collective, 0};
  if (N % 2 == 0 && m == N - 1) return {MbcKind::Differential, 0};
  return m % 2 == 1 ? MbcCoordinate{MbcKind::Cosine, (m + 1) / 2} : MbcCoordinate{MbcKind::Sine, m / 2};
}

/// Row b, column m of T1 (deriv = 0), of T2 = ∂T1/∂ψ (1) or of T3 = ∂²T1/∂ψ² (2).
double basis(int m, int N, int b, double psi, int deriv) {
  const MbcCoordinate c = coordinateOf(m, N);
  if (c.kind == MbcKind::Collective) return deriv == 0 ? 1.0 : 0.0;
  if (c.kind == MbcKind::Differential) return deriv == 0 ? (b % 2 == 0 ? -1.0 : 1.0) : 0.0;  // (−1)^(blade number)
  const double k = c.harmonic;
  const double psi_b = psi + 2.0 * std::numbers::pi * b / N;
  const double co = std::cos(k * psi_b), si = std::sin(k * psi_b);
  const bool cosine = c.kind == MbcKind::Cosine;
  if (deriv == 0) return cosine ? co : si;
  if (deriv == 1) return cosine ? -k * si : k * co;
  return cosine ? -k * k * co : -k * k * si;
}

/// Rotating sets of one vector (states, inputs or outputs).
struct Sets {
  std::vector<std::vector<Index>> members;  ///< per set, the entry of blade b = 0 … N−1
  std::vector<std::vector<Index>> rates;    ///< per set, the velocity state of each member (states only)
  std::vector<MbcCoordinate> coords;        ///< (dim n)
};

Sets findSets(const std::vector<int>& blade, const std::vector<int>& velocity_of, int N, Index n,
              const std::string& key) {
  Sets s;
  s.coords.assign(static_cast<std::size_t>(n), MbcCoordinate{});
  if (blade.empty()) return s;
  if (static_cast<Index>(blade.size()) != n)
    fail(key, "has " + std::to_string(blade.size()) + " entries for a vector of " + std::to_string(n));
  if (!velocity_of.empty() && static_cast<Index>(velocity_of.size()) != n)
    fail("velocity_of", "has " + std::to_string(velocity_of.size()) + " entries for " + std::to_string(n) + " states");
  std::vector<Index> rate(static_cast<std::size_t>(n), -1);
  std::vector<std::vector<Index>> per_blade(static_cast<std::size_t>(N));
  for (Index i = 0; i < n; ++i) {
    const int b = blade[i];
    if (b < -1 || b >= N) fail(key, "entry " + std::to_string(i) + ": blade " + std::to_string(b) + " not in -1 … N-1");
    const int p = velocity_of.empty() ? -1 : velocity_of[i];
    if (p < 0) {
      if (b >= 0) per_blade[b].push_back(i);
      continue;
    }
    if (p >= n || p == i || velocity_of[p] >= 0 || rate[p] >= 0)
      fail("velocity_of", "state " + std::to_string(i) + " is given as the rate of state " + std::to_string(p) +
                              ", which is not a displacement state or already has a rate");
    if (blade[p] != b)
      fail(key, "state " + std::to_string(i) + " (blade " + std::to_string(b) + ") is the rate of state " +
                    std::to_string(p) + " (blade " + std::to_string(blade[p]) + ")");
    rate[p] = i;
  }
  for (int b = 1; b < N; ++b)
    if (per_blade[b].size() != per_blade[0].size())
      fail(key, "blade " + std::to_string(b + 1) + " has " + std::to_string(per_blade[b].size()) +
                    " rotating entries, blade 1 has " + std::to_string(per_blade[0].size()));
  for (std::size_t j = 0; j < per_blade[0].size(); ++j) {
    std::vector<Index> set(N), rates(N);
    for (int b = 0; b < N; ++b) set[b] = per_blade[b][j], rates[b] = rate[set[b]];
    for (int b = 0; b < N; ++b) {
      if ((rates[b] < 0) != (rates[0] < 0))
        fail(key, "set " + std::to_string(j + 1) + " mixes second-order DOFs and first-order states (entries " +
                      std::to_string(set[0]) + ", " + std::to_string(set[b]) + ")");
      s.coords[set[b]] = coordinateOf(b, N);
      if (rates[b] >= 0) s.coords[rates[b]] = coordinateOf(b, N);
    }
    s.members.push_back(std::move(set));
    s.rates.push_back(std::move(rates));
  }
  return s;
}

/// The transform of a vector and its inverse, sparse: per rotating set, the N × N block B(b, m) of the
/// multiblade basis on its members (B on their rates too, and W ∂B/∂ψ from members to rates: the rates
/// of the multiblade coordinates follow from q = B q_nr as q̇ = B q̇_nr + W B' q_nr); the identity on
/// fixed entries. The inverse holds B⁻¹ per block and −B⁻¹ (W B') B⁻¹ from members to rates, so every
/// sample costs products with a few non-zeros per column instead of a dense factorization.
struct Transform {
  Eigen::SparseMatrix<double> T, Tinv, Tdot;  ///< Tdot = dT/dt (states only; empty otherwise)
};

/// The sparsity of a set's transform, built once for all samples: the identity on fixed entries and
/// the blade blocks (values set per sample by fillTransform).
Transform transformPattern(const Sets& s, int N, Index n, bool rates_of_time) {
  std::vector<Eigen::Triplet<double>> t, td;
  for (Index i = 0; i < n; ++i)
    if (s.coords[i].kind == MbcKind::Fixed) t.emplace_back(i, i, 1.0);
  for (std::size_t j = 0; j < s.members.size(); ++j) {
    const std::vector<Index>& q = s.members[j];
    const std::vector<Index>& v = s.rates[j];
    for (int b = 0; b < N; ++b)
      for (int m = 0; m < N; ++m) {
        t.emplace_back(q[b], q[m], 0.0);
        td.emplace_back(q[b], q[m], 0.0);
        if (v[0] < 0) continue;  // first-order state (or an input or output)
        t.emplace_back(v[b], v[m], 0.0);
        t.emplace_back(v[b], q[m], 0.0);
        td.emplace_back(v[b], q[m], 0.0);
        td.emplace_back(v[b], v[m], 0.0);
      }
  }
  Transform x;
  x.T.resize(n, n);
  x.T.setFromTriplets(t.begin(), t.end());
  x.Tinv = x.T;
  if (rates_of_time) {
    x.Tdot.resize(n, n);
    x.Tdot.setFromTriplets(td.begin(), td.end());
  }
  return x;
}

/// The values of T, T⁻¹ (and Ṫ) at azimuth psi, rotor speed W and acceleration Wdot into the pattern.
void fillTransform(const Sets& s, int N, double psi, double W, double Wdot, Transform& x) {
  Eigen::MatrixXd B(N, N), B1(N, N), B2(N, N);  // T1, ∂T1/∂ψ, ∂²T1/∂ψ² (blade b, coordinate m)
  for (int b = 0; b < N; ++b)
    for (int m = 0; m < N; ++m) {
      B(b, m) = basis(m, N, b, psi, 0);
      B1(b, m) = basis(m, N, b, psi, 1);
      B2(b, m) = basis(m, N, b, psi, 2);
    }
  const Eigen::MatrixXd dB = W * B1;
  const Eigen::MatrixXd Bi = B.partialPivLu().inverse();
  const Eigen::MatrixXd coupling = -Bi * dB * Bi;
  const bool tdot = x.Tdot.rows() > 0;
  for (std::size_t j = 0; j < s.members.size(); ++j) {
    const std::vector<Index>& q = s.members[j];
    const std::vector<Index>& v = s.rates[j];
    for (int b = 0; b < N; ++b)
      for (int m = 0; m < N; ++m) {
        x.T.coeffRef(q[b], q[m]) = B(b, m);
        x.Tinv.coeffRef(q[b], q[m]) = Bi(b, m);
        const double t2 = B1(b, m);
        if (tdot) x.Tdot.coeffRef(q[b], q[m]) = W * t2;
        if (v[0] < 0) continue;
        x.T.coeffRef(v[b], v[m]) = B(b, m);
        x.T.coeffRef(v[b], q[m]) = dB(b, m);
        x.Tinv.coeffRef(v[b], v[m]) = Bi(b, m);
        x.Tinv.coeffRef(v[b], q[m]) = coupling(b, m);
        if (!tdot) continue;
        x.Tdot.coeffRef(v[b], q[m]) = W * W * B2(b, m) + Wdot * t2;
        x.Tdot.coeffRef(v[b], v[m]) = W * t2;
      }
  }
}

void checkMatrix(const Eigen::MatrixXd& X, Index rows, Index cols, const std::string& name) {
  if (X.rows() != rows || X.cols() != cols)
    fail(name, "is " + std::to_string(X.rows()) + " x " + std::to_string(X.cols()) + ", expected " +
                   std::to_string(rows) + " x " + std::to_string(cols));
  for (Index j = 0; j < cols; ++j)
    for (Index i = 0; i < rows; ++i)
      if (!std::isfinite(X(i, j)))
        fail(name, "entry (" + std::to_string(i) + "," + std::to_string(j) + ") is not finite");
}

struct Prepared {
  Sets x, u, y;
  Index nx = 0, nu = 0, ny = 0;
  Transform tx, tu, ty;  ///< patterns; each sample fills them
};

Prepared prepare(const MbcLayout& L, const MbcSample& s) {
  if (L.num_blades < 3)
    fail("num_blades", std::to_string(L.num_blades) +
                           " blades: the multiblade transform needs at least 3 (with 2 "
                           "blades the equations stay periodic; use a Floquet analysis)");
  Prepared p;
  p.nx = s.A.rows();
  p.nu = s.B.size() ? s.B.cols() : s.D.cols();
  p.ny = s.C.size() ? s.C.rows() : s.D.rows();
  if (static_cast<Index>(L.state_blade.size()) != p.nx)
    fail("state_blade",
         "has " + std::to_string(L.state_blade.size()) + " entries, A has " + std::to_string(p.nx) + " rows");
  if (!L.input_blade.empty() && (s.B.size() || s.D.size()))
    p.u = findSets(L.input_blade, {}, L.num_blades, p.nu, "input_blade");
  else p.u.coords.assign(static_cast<std::size_t>(p.nu), MbcCoordinate{});
  if (!L.output_blade.empty() && (s.C.size() || s.D.size()))
    p.y = findSets(L.output_blade, {}, L.num_blades, p.ny, "output_blade");
  else p.y.coords.assign(static_cast<std::size_t>(p.ny), MbcCoordinate{});
  p.x = findSets(L.state_blade, L.velocity_of, L.num_blades, p.nx, "state_blade");
  p.tx = transformPattern(p.x, L.num_blades, p.nx, true);
  p.tu = transformPattern(p.u, L.num_blades, p.nu, false);
  p.ty = transformPattern(p.y, L.num_blades, p.ny, false);
  return p;
}

MbcSample transformPrepared(Prepared& p, int N, const MbcSample& s, const std::string& tag) {
  checkMatrix(s.A, p.nx, p.nx, "A" + tag);
  if (s.B.size()) checkMatrix(s.B, p.nx, p.nu, "B" + tag);
  if (s.C.size()) checkMatrix(s.C, p.ny, p.nx, "C" + tag);
  if (s.D.size()) checkMatrix(s.D, p.ny, p.nu, "D" + tag);
  if (!std::isfinite(s.azimuth) || !std::isfinite(s.rotor_speed) || !std::isfinite(s.rotor_acceleration))
    fail("azimuth" + tag, "azimuth, rotor speed and acceleration must be finite");

  const double psi = s.azimuth, W = s.rotor_speed, Wdot = s.rotor_acceleration;
  Transform& X = p.tx;
  fillTransform(p.x, N, psi, W, Wdot, X);
  MbcSample out;
  out.azimuth = s.azimuth;
  out.rotor_speed = s.rotor_speed;
  out.rotor_acceleration = s.rotor_acceleration;
  Eigen::MatrixXd AT = s.A * X.T;
  AT -= X.Tdot;
  out.A = X.Tinv * AT;
  Transform &U = p.tu, &Y = p.ty;
  fillTransform(p.u, N, psi, 0.0, 0.0, U);
  fillTransform(p.y, N, psi, 0.0, 0.0, Y);
  if (s.B.size()) out.B = X.Tinv * Eigen::MatrixXd(s.B * U.T);
  if (s.C.size()) out.C = Y.Tinv * Eigen::MatrixXd(s.C * X.T);
  if (s.D.size()) out.D = Y.Tinv * Eigen::MatrixXd(s.D * U.T);
  return out;
}

}  // namespace

std::string toString(MbcCoordinate c) {
  switch (c.kind) {
    case MbcKind::Fixed: return "fixed";
    case MbcKind::Collective: return "collective";
    case MbcKind::Differential: return "differential";
    case MbcKind::Cosine: return c.harmonic == 1 ? "cos" : "cos " + std::to_string(c.harmonic);
    case MbcKind::Sine: return c.harmonic == 1 ? "sin" : "sin " + std::to_string(c.harmonic);
  }
  return "?";
}

MbcLayout secondOrderLayout(int num_blades, const std::vector<int>& dof_blade,
                            const std::vector<int>& first_order_blade) {
  const int n = static_cast<int>(dof_blade.size());
  MbcLayout L;
  L.num_blades = num_blades;
  L.state_blade = dof_blade;
  L.state_blade.insert(L.state_blade.end(), dof_blade.begin(), dof_blade.end());
  L.state_blade.insert(L.state_blade.end(), first_order_blade.begin(), first_order_blade.end());
  L.velocity_of.assign(L.state_blade.size(), -1);
  for (int i = 0; i < n; ++i) L.velocity_of[n + i] = i;
  return L;
}

MbcSample mbcTransform(const MbcLayout& layout, const MbcSample& sample) {
  Prepared p = prepare(layout, sample);
  return transformPrepared(p, layout.num_blades, sample, "");
}

MbcResult mbcAverage(const MbcLayout& layout, const std::vector<MbcSample>& samples) {
  if (samples.empty()) fail("samples", "no azimuth given");
  Prepared p = prepare(layout, samples.front());
  MbcResult r;
  r.states = p.x.coords;
  r.inputs = p.u.coords;
  r.outputs = p.y.coords;
  const bool hasB = samples.front().B.size() > 0, hasC = samples.front().C.size() > 0,
             hasD = samples.front().D.size() > 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::string tag = " (azimuth sample " + std::to_string(k + 1) + ")";
    const MbcSample& s = samples[k];
    if ((s.B.size() > 0) != hasB || (s.C.size() > 0) != hasC || (s.D.size() > 0) != hasD)
      fail("samples" + tag, "B, C, D must be present in all samples or in none");
    r.samples.push_back(transformPrepared(p, layout.num_blades, s, tag));
  }
  const double inv = 1.0 / static_cast<double>(samples.size());
  auto mean = [&](Eigen::MatrixXd MbcSample::*field) {
    Eigen::MatrixXd sum = r.samples.front().*field;
    for (std::size_t k = 1; k < r.samples.size(); ++k) sum += r.samples[k].*field;
    return Eigen::MatrixXd(sum * inv);
  };
  r.A = mean(&MbcSample::A);
  if (hasB) r.B = mean(&MbcSample::B);
  if (hasC) r.C = mean(&MbcSample::C);
  if (hasD) r.D = mean(&MbcSample::D);
  return r;
}

}  // namespace whirl
