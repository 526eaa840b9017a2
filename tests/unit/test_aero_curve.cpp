// AeroDyn's BlCrvAng (AeroStation::curve): the element's annulus frame turned about y_a by the curve,
// as AeroDyn's Init_u turns the node's reference orientation (EulerConstruct(0, BlCrvAng, −BlTwist),
// AeroDyn.f90) and Calculate_MeshOrientation_NoSweepPitchTwist keeps that angle in orientationAnnulus,
// which projects the inflow (Vx, Vy) and turns the loads back. Checked against a hand computation of a
// rotor without induction, precone and pitch: the wind along the rotor axis reaches a section curved by
// c with Vx = U cos c, and the normal force turns with the section, its thrust fx cos c.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "linearize/operating_point.hpp"
#include "src/dynamics/aero_inflow.hpp"
#include "src/dynamics/residual.hpp"
#include "tests/support/aero_rotor_model.hpp"

namespace whirl {
namespace {

using test::aeroRotorModel;
using test::AeroRotorOptions;

AeroRecord recordAtRest(const Model& m) {
  const OperatingPoint op = initialPoint(m);
  Workspace<double> ws(m);
  VecX e(m.ndof());
  AeroRecord rec;
  residual(m, ws, op.q, op.qd, op.qdd, op.u, e, nullptr, &rec);
  return rec;
}

AeroRotorOptions straightRotor(double curve_deg) {
  AeroRotorOptions o;
  o.induction = false;  // the geometric inflow: the hand computation needs no BEM solution
  o.cd = 0;
  o.precone_deg = 0;
  o.pitch_deg = 0;
  o.curve_deg = curve_deg;
  return o;
}

TEST(AeroCurve, CurvedSectionsTakeTheNormalInflowAndTurnTheirLoads) {
  const double curve_deg = 12;
  const AeroRotorOptions o = straightRotor(curve_deg);
  const Model m = aeroRotorModel(o);
  const AeroRecord rec = recordAtRest(m);
  const double c = curve_deg * std::numbers::pi / 180, omega = o.rpm * std::numbers::pi / 30;
  const double rho = m.aero.air_density;
  ASSERT_EQ(rec.elements.size(), 3 * m.aero.blades[0].stations.size());
  double thrust = 0;
  for (std::size_t k = 0; k < m.aero.blades.size(); ++k) {
    const auto& stations = m.aero.blades[k].stations;
    for (std::size_t s = 0; s < stations.size(); ++s) {
      const AeroStation& st = stations[s];
      const AeroElementState& es = rec.elements[k * stations.size() + s];
      // The wind (along the rotor axis) on the tilted normal; the rotation's speed in the plane.
      const double vx = o.wind * std::cos(c), vy = omega * st.z;
      EXPECT_NEAR(es.vx, vx, 1e-12 * o.wind);
      EXPECT_NEAR(es.vy, vy, 1e-12 * vy + 1e-12);
      // Cl = 2π α, Cd = 0: fx = ½ ρ c W² Cl cos φ, φ = atan2(Vx, Vy), α = φ − twist.
      const double phi = std::atan2(vx, vy), w2 = vx * vx + vy * vy;
      const double fx = 0.5 * rho * st.chord * w2 * 2 * std::numbers::pi * (phi - st.twist) * std::cos(phi);
      EXPECT_NEAR(es.fx, fx, 1e-10 * std::abs(fx) + 1e-9);
      thrust += st.weight * fx * std::cos(c);  // fy lies in the rotor plane: no thrust
    }
  }
  EXPECT_NEAR(rec.thrust, thrust, 1e-10 * thrust);
  // The curve matters at this size: 12° takes ~4 % off the normal inflow and ~2 % off the force's
  // component along the rotor axis.
  const AeroRecord straight = recordAtRest(aeroRotorModel(straightRotor(0)));
  EXPECT_LT(rec.thrust, 0.97 * straight.thrust);
}

TEST(AeroCurve, CurveAddsToThePreconeDownwind) {
  // Positive BlCrvAng leans the span axis downwind (+x of the blade-root frame; AeroDyn's
  // EulerConstruct(0, c, 0) maps the local z to (sin c, 0, cos c)), like a positive precone: the
  // normal inflow is U cos(precone + c). A curve of −precone makes the sections face the wind.
  for (const double curve_deg : {-2.5, 2.5}) {
    AeroRotorOptions o = straightRotor(curve_deg);
    o.precone_deg = 2.5;
    const AeroRecord rec = recordAtRest(aeroRotorModel(o));
    const double tilt = (o.precone_deg + curve_deg) * std::numbers::pi / 180;
    for (const AeroElementState& es : rec.elements) EXPECT_NEAR(es.vx, o.wind * std::cos(tilt), 1e-12 * o.wind);
  }
}

}  // namespace
}  // namespace whirl
