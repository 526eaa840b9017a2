// Steady aerodynamics of the NREL 5MW (cases/nrel5mw/Main_Aero.fst: AeroDyn BEMT, ElastoDyn with every
// structural DOF, ServoDyn simple VS torque law) against OpenFAST's steady operating data, and the
// trim's torque balance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "linearize/linearize.hpp"
#include "linearize/operating_point.hpp"
#include "linearize/trim.hpp"
#include "src/base/error.hpp"
#include "src/io/text/schedule.hpp"
#include "src/turbine/elastodyn_model.hpp"

namespace whirl {
namespace {

const std::string kDir = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/";

// Source: cases/nrel5mw/NREL5MW_Oper.csv (OpenFAST steady operating data of the NREL 5MW, 4–5 printed
// digits): RtAeroFxh (aerodynamic rotor thrust) and RtAeroMxh (aerodynamic rotor torque) at the rotor
// speed and pitch of each wind speed. Tolerance 2 % (the acceptance of the aeroelastic issue; the
// reference's digits are finer). 3 m/s (0.43 rpm, tip-speed ratio 0.94) holds only with AeroDyn's
// induction switched off below λ = 1 (whirl had thrust −1.2 % with BEM there; now −0.6 %, torque −1.5 %).
// 4 m/s (2.39 rpm, λ = 3.98) is not a steady point of the reference (the rotor is still spinning up
// there, see ReferenceRowsAtThreeAndFourMetresPerSecondAreSpinUps) and is checked separately
// (SpinUpRowLiesBetweenSteadyAndAbsentInduction).
TEST(Nrel5mwAeroSteady, ThrustAndTorqueMatchOpenFastOperatingData) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst");
  const std::vector<SweepPoint> points = readSchedule(kDir + "NREL5MW_Oper.csv");
  struct Ref {
    double wind, thrust_kn, torque_knm;
  };
  // RtAeroFxh [kN] and RtAeroMxh [kN m] of NREL5MW_Oper.csv.
  const Ref ref[] = {{3, 5.7920946, 24.3312234},      {5, 171.7068163, 534.3241612},   {6, 232.1685662, 927.1605643},
                     {7, 300.9974324, 1408.0558167},  {8, 379.5112723, 1946.9009021},  {9, 477.8789172, 2455.6832707},
                     {10, 586.311431, 3022.4045482},  {11, 682.5526581, 3814.5119603}, {12, 596.2327444, 4180.8431208},
                     {15, 414.8642352, 4181.0607615}, {20, 313.5326896, 4176.9003673}, {25, 273.4863367, 4176.0276416}};
  int checked = 0;
  for (const Ref& r : ref)
    for (const SweepPoint& p : points) {
      if (!p.wind_speed || std::abs(*p.wind_speed - r.wind) > 1e-9) continue;
      const SteadyState s = steadyState(m, sweepCondition(m, p));
      EXPECT_NEAR(s.thrust / 1e3, r.thrust_kn, 0.02 * r.thrust_kn) << r.wind << " m/s";
      EXPECT_NEAR(s.aero_torque / 1e3, r.torque_knm, 0.02 * r.torque_knm) << r.wind << " m/s";
      ++checked;
    }
  EXPECT_EQ(checked, static_cast<int>(std::size(ref)));
}

// Why the 4 m/s row is not a steady point: in NREL5MW_Oper.csv at 3 and 4 m/s the generator torque is 0
// and the low-speed-shaft torque RotTorq is a fraction of the aerodynamic torque (2.7985 of 24.33 and
// 46.73 of 406.55 kN m), while from 5 m/s on the two agree to 0.1 %. A rotor accelerated by its
// aerodynamic torque alone passes to the shaft the generator's share of the inertia: RtAeroMxh / RotTorq
// = (J_rotor + J_gen G²) / (J_gen G²). Both rows give that ratio of whirl's model of the same deck, so
// they are snapshots of a free spin-up (0.0093 rad/s² at 4 m/s), not equilibria. Inertias from the
// assembled mass matrix at rest: generator azimuth carries rotor + generator, drivetrain the rotor alone.
// Tolerance 0.5 %: the ratios of the two rows differ by 0.07 % (the reference's printed digits).
TEST(Nrel5mwAeroSteady, ReferenceRowsAtThreeAndFourMetresPerSecondAreSpinUps) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst", {"CompAero=0", "RotSpeed=0"});
  const LinearModel lin = linearize(m, solveOperatingPoint(m, initialPoint(m)));
  auto at = [&](const std::string& dof) {
    for (std::size_t i = 0; i < lin.dof_names.size(); ++i)
      if (lin.dof_names[i] == dof) return static_cast<Eigen::Index>(i);
    ADD_FAILURE() << dof;
    return Eigen::Index{0};
  };
  const double j_total = lin.M(at("generator azimuth"), at("generator azimuth"));
  const double j_rotor = lin.M(at("drivetrain"), at("drivetrain"));
  const double ratio = j_total / (j_total - j_rotor);
  // RtAeroMxh and RotTorq [kN m] of NREL5MW_Oper.csv at 3 and 4 m/s.
  EXPECT_NEAR(24.3312234 / 2.7985, ratio, 0.005 * ratio);
  EXPECT_NEAR(406.5542608 / 46.7301, ratio, 0.005 * ratio);
}

// During a spin-up a dynamic induction (AeroDyn's DBEMT: the OpenFAST toolbox's onshore NREL 5MW
// simulation deck has WakeMod = 2; the table does not say which deck made it) lags the steady value, so the thrust of
// the 4 m/s row must lie between whirl's steady BEM (induction in equilibrium) and no induction at all (AeroDyn WakeMod
// = 0). It does: 43.74 ≤ 44.91 ≤ 44.97 kN. (The torque, 406.55 kN m, is 0.3 % below whirl's steady 407.8 kN m rather
// than between it and the 428 kN m without induction: that deck also has tower potential flow and unsteady airfoils,
// which whirl's steady model leaves out; not separated.)
TEST(Nrel5mwAeroSteady, SpinUpRowLiesBetweenSteadyAndAbsentInduction) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst");
  Model frozen_out = m;
  frozen_out.aero.induction = false;
  for (const SweepPoint& p : readSchedule(kDir + "NREL5MW_Oper.csv")) {
    if (!p.wind_speed || std::abs(*p.wind_speed - 4.0) > 1e-9) continue;
    const double steady = steadyState(m, sweepCondition(m, p)).thrust / 1e3;
    const double none = steadyState(frozen_out, sweepCondition(frozen_out, p)).thrust / 1e3;
    EXPECT_LT(steady, 44.9062984);  // RtAeroFxh [kN] of NREL5MW_Oper.csv at 4 m/s
    EXPECT_GT(none, 44.9062984);
    return;
  }
  FAIL() << "no 4 m/s row";
}

// The trimmed point is a torque balance: below rated the aerodynamic torque equals the gear ratio
// times the generator torque of ServoDyn's law (k ω² in region 2), above rated the rotor turns at
// VS_RtGnSp / GBRatio and the generator gives VS_RtTq. Checked without gravity, where nothing else
// acts on the rotor azimuth at equilibrium; with gravity the quasi-statically deflected rotor adds a
// mean gravity torque of about 1e-4 N m per N m of aerodynamic torque (105 N m at 8 m/s, measured).
// Tolerance: the trim's own (1e-9 of the rated torque) and round-off of the azimuth average.
TEST(Nrel5mwAeroSteady, TrimBalancesTheTorqueLaw) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst", {"gravity=0"});
  const double gear = 97.0;  // GBRatio of the ElastoDyn file
  const SteadyState below = trimAtWindSpeed(m, 8.0);
  EXPECT_FALSE(below.above_rated);
  EXPECT_NEAR(below.aero_torque, gear * below.generator_torque, 1e-7 * below.aero_torque);
  const double k = 0.025576 * std::pow(30 / std::numbers::pi, 2);  // VS_Rgn2K [N m/rpm²] in SI
  EXPECT_NEAR(below.generator_torque, k * below.generator_speed * below.generator_speed, 1e-9 * below.generator_torque);
  const SteadyState above = trimAtWindSpeed(m, 18.0);
  EXPECT_TRUE(above.above_rated);
  EXPECT_NEAR(above.generator_speed, 1162.0 * std::numbers::pi / 30, 1e-9);  // VS_RtGnSp
  EXPECT_NEAR(above.aero_torque, gear * 47403.0, 1e-7 * above.aero_torque);  // VS_RtTq
  EXPECT_GT(*above.condition.collective_pitch, 10 * std::numbers::pi / 180);
}

// With gravity: the region-2 gain of the deck holds the rotor near the optimal tip-speed ratio of the
// NREL 5MW, about 7.5 (Jonkman et al. 2009, §7.1: 7.55); ±0.2 covers the deflected blades and the
// gain's rounding in the ServoDyn file.
TEST(Nrel5mwAeroSteady, RegionTwoRunsAtTheOptimalTipSpeedRatio) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst");
  for (double wind : {5.0, 8.0}) {
    const SteadyState s = trimAtWindSpeed(m, wind);
    EXPECT_NEAR(s.condition.rotor_speed * m.aero.rotor_radius / wind, 7.5, 0.2) << wind << " m/s";
  }
}

// A schedule's trims start next to their neighbour's balance (trimSchedule); each must be the balance the
// search over the whole range finds, to the trim's tolerance: the torque balance to 1e-9 of the rated
// torque, so rotor speed and pitch to ~1e-9 relative (measured max 8e-10 over 3:1:25).
TEST(Nrel5mwAeroSteady, ScheduleTrimsEqualSeparateTrims) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst");
  const std::vector<double> winds{6, 7, 8, 11, 12, 13, 16};
  const std::vector<SteadyState> schedule = trimSchedule(m, winds);
  ASSERT_EQ(schedule.size(), winds.size());
  int guessed = 0, separate = 0;
  for (std::size_t i = 0; i < winds.size(); ++i) {
    const SteadyState alone = trimAtWindSpeed(m, winds[i]);
    EXPECT_EQ(schedule[i].above_rated, alone.above_rated) << winds[i];
    EXPECT_NEAR(schedule[i].condition.rotor_speed, alone.condition.rotor_speed, 1e-8 * alone.condition.rotor_speed)
        << winds[i];
    EXPECT_NEAR(*schedule[i].condition.collective_pitch, *alone.condition.collective_pitch, 1e-8) << winds[i];
    guessed += schedule[i].evaluations;
    separate += alone.evaluations;
  }
  EXPECT_LT(guessed, separate);
}

// Down the wind speeds, the search next to a pitched neighbour finds no excess torque at fine pitch at
// 11 m/s (below rated) and must turn to the rotor-speed search: the schedule's trims are again the
// separate ones, the side of rated included.
TEST(Nrel5mwAeroSteady, ScheduleDownTheWindCrossesRated) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst");
  const std::vector<double> winds{14, 12, 11, 9};
  const std::vector<SteadyState> schedule = trimSchedule(m, winds);
  ASSERT_EQ(schedule.size(), winds.size());
  for (std::size_t i = 0; i < winds.size(); ++i) {
    const SteadyState alone = trimAtWindSpeed(m, winds[i]);
    EXPECT_EQ(schedule[i].above_rated, winds[i] >= 12) << winds[i];
    EXPECT_EQ(schedule[i].above_rated, alone.above_rated) << winds[i];
    EXPECT_NEAR(schedule[i].condition.rotor_speed, alone.condition.rotor_speed, 1e-8 * alone.condition.rotor_speed)
        << winds[i];
    EXPECT_NEAR(*schedule[i].condition.collective_pitch, *alone.condition.collective_pitch, 1e-8) << winds[i];
  }
}

// A rotor whose aerodynamic torque cannot overcome the torque law (here: held feathered at 80 deg; the
// simple VS law has no cut-in, so with fine pitch any wind finds a balance), and a rotor that cannot
// shed its excess torque within the pitch range, stop with a message that says which and at what
// wind speed.
TEST(Nrel5mwAeroSteady, TrimFailuresSayWhy) {
  const Model m = readElastoDynModel(kDir + "Main_Aero.fst");
  TrimOptions feathered;
  feathered.min_pitch = 80 * std::numbers::pi / 180;
  feathered.max_pitch = 85 * std::numbers::pi / 180;
  try {
    trimAtWindSpeed(m, 6.0, feathered);
    FAIL() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_NE(std::string(e.what()).find("trim at 6"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("does not overcome the generator torque law"), std::string::npos) << e.what();
  }
  TrimOptions narrow;
  narrow.max_pitch = 5 * std::numbers::pi / 180;  // 20 m/s needs about 17 deg
  try {
    trimAtWindSpeed(m, 20.0, narrow);
    FAIL() << "no error";
  } catch (const ComputeError& e) {
    EXPECT_NE(std::string(e.what()).find("trim at 20"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exceeds the rated generator torque even at 5"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace whirl
