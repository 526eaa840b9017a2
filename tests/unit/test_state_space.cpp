// Inputs that drive frozen coordinates (pitch), outputs differentiated by AD (C, D), and the physics
// of the exported state-space model: static gains from stiffness and inertia, and resonance peaks
// at the modal frequencies.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "case_file_test_util.hpp"
#include "linearize/periodic.hpp"
#include "modal/campbell_sweep.hpp"
#include "modal/rotor_modes.hpp"
#include "src/dynamics/outputs.hpp"
#include "state_space_test_util.hpp"

namespace whirl {
namespace {

using testing::accelerations;
using testing::indexOf;
using testing::nrel5mw;

constexpr double kDeg = std::numbers::pi / 180;

// Q's pitch columns are ∂e/∂q_pitch (chain rule through the frozen pitch joint): central differences
// of the residual on the pitch coordinate, h = 1e-5 rad (truncation ~h² ≈ 1e-10 relative).
TEST(StateSpace, PitchInputIsTheDerivativeThroughThePitchJoint) {
  const Model m = nrel5mw();
  ASSERT_EQ(m.roles.blade_pitch.size(), 3u);
  OperatingCondition at = modelCondition(m);
  at.collective_pitch = 5.0 * std::numbers::pi / 180;
  const OperatingPoint op = solveOperatingPoint(m, at);
  const LinearModel lin = linearize(m, op);
  const int coll = *m.findInput("collective pitch");
  VecX sum = VecX::Zero(lin.Q.rows());
  for (int b = 1; b <= 3; ++b) {
    const int k = *m.findInput("blade " + std::to_string(b) + " pitch");
    const int d = *m.findDof("blade " + std::to_string(b) + " pitch");
    ASSERT_TRUE(m.dofs[d].frozen);
    Workspace<double> ws(m);
    VecX ep(m.ndof()), em(m.ndof());
    const double h = 1e-5;
    VecX q = op.q;
    q(d) += h;
    residual(m, ws, q, op.qd, op.qdd, op.u, ep);
    q(d) -= 2 * h;
    residual(m, ws, q, op.qd, op.qdd, op.u, em);
    const double scale = lin.Q.col(k).cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 1e3) << "pitch must load the blade DOFs";
    for (size_t r = 0; r < lin.dofs.size(); ++r)
      EXPECT_NEAR(lin.Q(r, k), (ep(lin.dofs[r]) - em(lin.dofs[r])) / (2 * h), 1e-7 * scale) << lin.dof_names[r];
    sum += lin.Q.col(k);
  }
  EXPECT_LE((lin.Q.col(coll) - sum).cwiseAbs().maxCoeff(), 1e-9 * sum.cwiseAbs().maxCoeff());
  const StateSpaceModel s = stateSpace(m, op, lin);
  EXPECT_DOUBLE_EQ(s.u[coll].op, 5.0 * kDeg);  // the pitch angle, not the increment
}

// C and D against central differences of y(q, q̇, q̈(q, q̇, u)) with q̈ from the nonlinear equations
// of motion: the q̈-dependent outputs (accelerations) must carry the M⁻¹ K, M⁻¹ C, M⁻¹ Q terms.
TEST(StateSpace, OutputMatricesMatchDifferencesThroughTheEquationsOfMotion) {
  const Model m = nrel5mw();
  OperatingCondition at = modelCondition(m);
  at.collective_pitch = 3.0 * std::numbers::pi / 180;
  const OperatingPoint op = solveOperatingPoint(m, at);
  const LinearModel lin = linearize(m, op);
  const StateSpaceModel s = stateSpace(m, op, lin);
  ASSERT_EQ(s.y.size(), m.outputs.size());
  Workspace<double> ws(m);
  auto outputs = [&](const VecX& q, const VecX& qd, const VecX& u) {
    VecX y(m.noutput());
    evaluateOutputs(m, ws, q, qd, accelerations(m, q, qd, u), y, &u);
    return y;
  };
  const int n = static_cast<int>(lin.dofs.size());
  MatX C(m.noutput(), 2 * n), D(m.noutput(), m.ninput());
  for (int j = 0; j < 2 * n; ++j) {
    const int d = lin.dofs[j % n];
    const double h = 1e-6 * (1.0 + std::abs(j < n ? op.q(d) : op.qd(d)));
    VecX qp = op.q, qm = op.q, vp = op.qd, vm = op.qd;
    (j < n ? qp : vp)(d) += h;
    (j < n ? qm : vm)(d) -= h;
    C.col(j) = (outputs(qp, vp, op.u) - outputs(qm, vm, op.u)) / (2 * h);
  }
  for (int i = 0; i < m.ninput(); ++i) {
    const double h = m.inputs[i].dofs.empty() ? 1.0 : 1e-6;
    VecX up = op.u, um = op.u, qp = op.q, qm = op.q;
    up(i) += h;
    um(i) -= h;
    for (const auto& t : m.inputs[i].dofs) qp(t.dof) += t.gain * h, qm(t.dof) -= t.gain * h;
    D.col(i) = (outputs(qp, op.qd, up) - outputs(qm, op.qd, um)) / (2 * h);
  }
  for (int r = 0; r < m.noutput(); ++r) {
    const double sc = std::max(1e-12, s.C.row(r).cwiseAbs().maxCoeff()),
                 sd = std::max(1e-12, s.D.row(r).cwiseAbs().maxCoeff());
    EXPECT_LE((s.C.row(r) - C.row(r)).cwiseAbs().maxCoeff(), 1e-5 * sc) << s.y[r].name;
    EXPECT_LE((s.D.row(r) - D.row(r)).cwiseAbs().maxCoeff(), 1e-5 * sd) << s.y[r].name;
  }
  // The accelerations react to the inputs instantly (D ≠ 0), the displacements do not.
  EXPECT_GT(std::abs(s.D(indexOf(s.y, "YawBrTAxp"), *m.findInput("tower-top force"))), 0.0);
  EXPECT_EQ(s.D(indexOf(s.y, "TTDspFA"), *m.findInput("tower-top force")), 0.0);
}

// Hand calculation: the generator (GenIner about the HSS, geared at N) and the rotor (rotor angle
// θ = ψ + δ, blades and hub) share no inertia once written in (ψ, θ): KE = ½ N² J_g ψ̇² + T_rotor(θ̇, …),
// and the torque T does virtual work −N T δψ. So ψ̈ = −T / (N J_g) and the generator acceleration
// N ψ̈ = −T / J_g at any instant: D(GenAccel, generator torque) = −1/GenIner = −1/534.116 kg m²
// (NRELOffshrBsline5MW_Onshore_ElastoDyn.dat). Tower and yaw are frozen: their rotation about the
// shaft would couple the generator's inertia to the nacelle.
TEST(StateSpace, GeneratorAccelerationPerTorqueIsOneOverGeneratorInertia) {
  Model m = nrel5mw({"TwFADOF1=False", "TwSSDOF1=False", "TwFADOF2=False", "TwSSDOF2=False", "YawDOF=False"});
  Output acc;
  acc.name = "GenAccel";
  acc.order = 2;
  acc.terms = {{*m.findDof("generator azimuth"), 97.0}};
  m.outputs.push_back(acc);
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const StateSpaceModel s = stateSpace(m, op, linearize(m, op));
  const double d = s.D(indexOf(s.y, "GenAccel"), indexOf(s.u, "generator torque"));
  EXPECT_NEAR(d, -1.0 / 534.116, 1e-12 / 534.116);
}

// Hand calculation for a uniform cantilever with the shape φ = 1 − cos(πx/2L) and no gravity:
// K = ∫ EI φ''² dx = EI (π/2L)⁴ L/2 = π⁴ EI / (32 L³); the static tower-top displacement per top
// force is 1/K. The exported model's static gain −C A⁻¹ B + D must equal it.
TEST(StateSpace, TowerTopStaticGainIsOneOverTheStiffness) {
  testing::TempCaseDir dir;
  const std::string path = dir.write("tower.yaml", R"(
name: tower with thrust
gravity: 0
inputs:
  - {name: rotor thrust, unit: N}
bodies:
  - name: tower
    type: beam
    rotation: {y_deg: -90}
    length: 80
    uniform: {m: 5000, EIy: 2.0e11, EIz: 2.0e11}
    shapes:
      - {name: tower FA 1, type: one_minus_cos, direction: z}
    points:
      - {name: top, x: 80}
  - {name: rna, type: rigid, parent: tower, at: top, mass: 3.0e5}
loads:
  - {type: point, body: rna, force: [1, 0, 0], frame: ground, input: rotor thrust}
outputs:
  - {name: TTDspFA, type: point, body: tower, point: top, frame: ground, direction: [1, 0, 0]}
  - {name: TTAccFA, type: point, body: rna, order: acceleration, direction: [1, 0, 0]}
  - {name: TwrBsMFA, type: moment, body: tower, component: z}
)");
  Model m = readCase(path);
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const StateSpaceModel s = stateSpace(m, op, linearize(m, op));
  const MatX G = s.D - s.C * s.A.partialPivLu().solve(s.B);
  const double L = 80, EI = 2.0e11, K = std::pow(std::numbers::pi, 4) * EI / (32 * L * L * L);
  EXPECT_NEAR(G(0, 0), 1.0 / K, 1e-9 / K);
  EXPECT_NEAR(G(1, 0), 0.0, 1e-12);  // no static acceleration
  // Base moment from the curvature, EI φ''(0) q = EI (π/2L)² q, at the static deflection q = −F/K
  // (the shape points along body z = ground −X): F · (8 L/π²), the exact F L times 0.81 — the
  // one-shape Ritz curvature, documented in README.
  EXPECT_NEAR(std::abs(G(2, 0)), 8 * L / (std::numbers::pi * std::numbers::pi), 1e-9 * L);
  EXPECT_EQ(s.y[0].unit, "m");
  EXPECT_EQ(s.y[1].unit, "m/s^2");
  EXPECT_EQ(s.y[2].unit, "N m");
}

// The exported (multiblade-averaged) model at 9 rpm resonates where the Campbell analysis of the
// same operating point puts the modes: |G(jω)| of tower-top acceleration per tower-top force peaks
// at the tower FA 1 and SS 1 frequencies, generator speed per generator torque at the drivetrain mode.
TEST(StateSpace, FrequencyResponsePeaksAtTheModalFrequencies) {
  const Model m = nrel5mw();
  OperatingCondition at;
  at.rotor_speed = 9 * std::numbers::pi / 30;
  ExportOptions opt;
  opt.azimuths = 12;
  const ExportPoint e = exportOperatingPoint(m, at, opt);
  ASSERT_TRUE(e.model.multiblade);
  PeriodicOptions popt;
  popt.azimuths = 12;
  const RotorModes r = rotorModes(m, linearizePeriodic(m, at, popt));
  auto modeFreq = [&](const std::string& name) {
    for (const auto& md : r.modes)
      if (md.name == name) return md.freq_hz;
    ADD_FAILURE() << "no mode " << name;
    return 0.0;
  };
  auto peak = [&](const std::string& y, const std::string& u, double f0) {
    const int iy = indexOf(e.model.y, y), iu = indexOf(e.model.u, u);
    double best = 0, fbest = 0;
    for (double f = 0.97 * f0; f <= 1.03 * f0; f += 1e-5 * f0) {
      const double g = std::abs(testing::frequencyResponse(e.model, 2 * std::numbers::pi * f)(iy, iu));
      if (g > best) best = g, fbest = f;
    }
    return fbest;
  };
  // A peak of a lightly damped mode sits at f_n/√(1 − 2ζ²) for acceleration (ζ < 1 %: < 1e-4 off)
  // and is pulled by the neighbouring modes' tails; 2e-3 covers both for these well-separated modes.
  for (const auto& [y, u, mode] : {std::tuple{"YawBrTAxp", "tower-top force", "tower FA 1"},
                                   std::tuple{"YawBrTAyp", "tower-top side force", "tower SS 1"},
                                   std::tuple{"GenSpeed", "generator torque", "drivetrain"}}) {
    const double f0 = modeFreq(mode);
    EXPECT_NEAR(peak(y, u, f0), f0, 2e-3 * f0) << y << " / " << u << " at " << mode;
  }
}

TEST(StateSpace, SelectionAndDroppingTheAzimuth) {
  Model m = nrel5mw();
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const StateSpaceModel s = stateSpace(m, op, linearize(m, op));
  const StateSpaceModel r = selectInputsOutputs(s, {"collective pitch", "generator torque"}, {"GenSpeed"});
  ASSERT_EQ(r.u.size(), 2u);
  EXPECT_EQ(r.u[0].name, "collective pitch");
  EXPECT_EQ(r.B.col(1), s.B.col(indexOf(s.u, "generator torque")));
  EXPECT_EQ(r.D(0, 0), s.D(indexOf(s.y, "GenSpeed"), indexOf(s.u, "collective pitch")));
  EXPECT_NE(testing::inputErrorOf([&] {
              selectInputsOutputs(s, {"blade pitch"}, {});
            }).find("unknown input 'blade pitch'"),
            std::string::npos);
  const StateSpaceModel d = dropAzimuth(s);
  ASSERT_EQ(d.x.size(), s.x.size() - 1);
  EXPECT_EQ(indexOf(d.x, "generator azimuth"), -1);
  const int rate = indexOf(d.x, "d(generator azimuth)/dt");
  ASSERT_GE(rate, 0);
  EXPECT_EQ(d.x[rate].rate_of, -1);
  EXPECT_EQ(d.A(rate, rate), s.A(indexOf(s.x, "d(generator azimuth)/dt"), indexOf(s.x, "d(generator azimuth)/dt")));
}

TEST(StateSpace, CaseFileInputDrivingAnUnfrozenDofIsRefused) {
  testing::TempCaseDir dir;
  const std::string path = dir.write("bad.yaml", R"(
name: bad
inputs:
  - {name: pitch, dofs: [hinge]}
bodies:
  - {name: arm, type: rigid, mass: 1, cog: [1, 0, 0], inertia: [1, 1, 1], joint: {type: revolute, axis: [0, 0, 1], dof: hinge}}
)");
  const std::string msg = testing::inputErrorOf([&] { readCase(path); });
  EXPECT_NE(msg.find("not frozen"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bad.yaml:4"), std::string::npos) << msg;
}

}  // namespace
}  // namespace whirl
