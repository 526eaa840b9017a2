// The teetering hub of a 2-bladed ElastoDyn rotor (ElastoDyn `SetCoordSy`: frames e (azimuth), f
// (teeter), g (δ3); `CalculatePositions`: rPQ = −UndSling g1, rQC = HubCM g1; `Coeff`: the hub
// inertias; `Teeter`: the spring, stop and damper moments).
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/turbine/elastodyn_parts.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// One law of ElastoDyn's `Teeter` routine that acts where |β| > `from` (a stop: −k sign β (|β| − from);
// the damper: −c β̇), linearized on the piece that holds at the reference angle `ref`. A law acting
// from 0 is linear at every angle. (ElastoDyn's damper test |β| > TeetDmpP is false at β = 0 exactly;
// that single angle is taken as part of the damped range: the law on both sides of it.)
DofSpring piece(int dof, double from, double ref, double k, double c, const std::string& name, const char* key) {
  DofSpring s;
  s.dof = dof;
  if (from == 0.0) {
    s.k = k;
    s.c = c;
    return s;
  }
  const std::string at = fmt::format("{} = {:g} deg", key, from / deg);
  if (std::abs(ref) > from) {  // beyond the stop on the side of `ref`
    const double side = ref > 0 ? 1.0 : -1.0;
    s.k = k;
    s.c = c;
    s.q0 = side * from;
    (side > 0 ? s.q_min : s.q_max) = side * from;
    s.law = fmt::format("{} acting beyond {}, as at TeetDefl = {:g} deg", name, at, ref / deg);
  } else {  // inside: nothing acts
    s.q_min = -from;
    s.q_max = from;
    s.law = fmt::format("{} not acting within {}, as at TeetDefl = {:g} deg", name, at, ref / deg);
  }
  return s;
}

// Hub inertia about its centre of mass, teeter-body (f) axes. Files with HubIner_Teeter (OpenFAST
// after 2025): HubIner about the shaft f1, HubIner_Teeter about the teeter axis f2 through the pin;
// older files: HubIner about the teeter axis through the pin, and the hub a uniform cylinder with
// that inertia about g1 and g2 ("Hubg1Iner = Hubg2Iner = (HubIner − HubMass (UndSling − HubCM)²) / cos² δ3").
Mat3 hubInertia(const Builder& b) {
  const io::ElastoDynInput& ed = b.ed;
  const double m = ed.mass.HubMass, d = ed.config.UndSling - ed.config.HubCM, d3 = ed.config.Delta3 * deg;
  const double parallel = m * d * d;
  if (ed.mass.HubIner_Teeter) {
    const double f2 = *ed.mass.HubIner_Teeter - parallel;
    if (f2 < 0)
      throw InputError(b.where("HubIner_Teeter", fmt::format("must not be less than HubMass·(UndSling − HubCM)² = {:g} "
                                                             "kg m² for a 2-bladed rotor",
                                                             parallel)));
    return Mat3(Vec3(ed.mass.HubIner, f2, 0).asDiagonal());
  }
  const double g = (ed.mass.HubIner - parallel) / (std::cos(d3) * std::cos(d3));
  if (g < 0)
    throw InputError(b.where("HubIner", fmt::format("must not be less than HubMass·(UndSling − HubCM)² = {:g} kg m² "
                                                    "for a 2-bladed rotor (HubIner is about the teeter axis)",
                                                    parallel)));
  const Vec3 g2(0, std::cos(d3), std::sin(d3));
  return g * (Vec3::UnitX() * Vec3::UnitX().transpose() + g2 * g2.transpose());
}

}  // namespace

RotorHub addTeeteringHub(Builder& b, const DrivetrainParts& dt) {
  const io::ElastoDynInput& ed = b.ed;
  const io::ElastoDynConfiguration& c = ed.config;
  // The hub body of the drivetrain sits at the teeter pin P (OverHang is measured to it for 2 blades)
  // in the azimuth frame e: x = shaft, z = blade 1 at zero teeter and δ3, y = the teeter axis e2.
  // Teeter turns the rotor about y: f1 = cos β e1 − sin β e3, f3 = sin β e1 + cos β e3.
  Body hub;
  hub.name = "teetering hub";
  hub.parent = dt.hub;
  hub.joint = JointType::Revolute;
  hub.axis = Vec3::UnitY();
  hub.inertia = rigidBodyInertia(ed.mass.HubMass, Vec3(c.HubCM - c.UndSling, 0, 0), hubInertia(b));
  const int body = b.addBody(std::move(hub));
  const double ref = ed.init.TeetDefl * deg;
  const int dof = b.addDof("teeter", body, DofKind::Joint, 0, ed.dof.TeetDOF, ref);

  const io::ElastoDynTeeter& t = ed.teeter;
  if (ed.dof.TeetDOF && t.TeetMod.value_or(0) == 1) {
    const DofSpring laws[] = {
        piece(dof, *t.TeetSStP * deg, ref, *t.TeetSSSp, 0.0, "teeter soft-stop spring (TeetSSSp)", "TeetSStP"),
        piece(dof, *t.TeetHStP * deg, ref, *t.TeetHSSp, 0.0, "teeter hard-stop spring (TeetHSSp)", "TeetHStP"),
        piece(dof, *t.TeetDmpP * deg, ref, 0.0, *t.TeetDmp, "teeter damper (TeetDmp)", "TeetDmpP")};
    for (const DofSpring& s : laws)
      if (s.k != 0.0 || s.c != 0.0 || !s.law.empty()) b.model().springs.push_back(s);
  }
  return {body, Vec3(-c.UndSling, 0, 0), c.Delta3 * deg, dof};
}

}  // namespace whirl::elastodyn
