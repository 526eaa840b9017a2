// AeroDyn's blade elements, airfoils and InflowWind's steady wind on the ElastoDyn turbine, and
// ServoDyn's generator torque law (simple variable-speed law or induction generator) on its generator.
#include <cmath>
#include <numbers>
#include <string>

#include "src/aero/ua_span.hpp"
#include "src/base/error.hpp"
#include "src/dynamics/generator_torque.hpp"
#include "src/io/openfast/aerodyn/airfoil_ua.hpp"
#include "src/shapes/beam.hpp"
#include "src/shapes/rigid_arm.hpp"
#include "src/turbine/elastodyn_parts.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

int outputIndex(const Model& m, const std::string& name) {
  for (int i = 0; i < m.noutput(); ++i)
    if (m.outputs[i].name == name) return i;
  return -1;
}

// The point pt of an FE blade's reference axis moved to AeroDyn's aerodynamic centre (x_r, y_r) =
// (BlCrvAC, BlSwpAC) [m] of the blade-root frame, body (y, z): AeroDyn places its nodes there and
// OpenFAST maps their loads to BeamDyn's axis through rigid arms (ModMesh_Mapping, line2-to-line2), so
// the offset from the axis turns with the section (offsetOnRigidArm): a lift ahead of the axis loads the
// torsion modes and the section's twist moves the centre (the aerodynamic stiffness of torsion).
void atAerodynamicCentre(BodyPoint& pt, double crv_ac, double swp_ac) {
  offsetOnRigidArm(pt, Vec3(0.0, crv_ac - pt.P(1, 0), swp_ac - pt.P(2, 0)));
}

// One blade's elements at the AeroDyn nodes: points on the blade body at the aerodynamic centre,
// trapezoid weights along the span, AeroDyn's curvilinear distance from the apex (loss constants).
AeroBlade bladeElements(Builder& b, const BladeParts& blade, const io::AeroDynBladeInput& file, double hub_radius,
                        double length) {
  AeroBlade out;
  out.body = blade.body;
  out.pitch_dof = blade.pitch;
  Body& body = b.model().bodies[blade.body];
  const int n = file.NumBlNds;
  const bool v14 = !file.element_width.empty();  // element centres from the rotor centre, with widths
  double z = hub_radius;
  Vec3 previous = Vec3::Zero();
  for (int j = 0; j < n; ++j) {
    const double span = file.BlSpn[j] - (v14 ? hub_radius : 0.0);
    if (span > length * (1 + 1e-9) || span < 0)
      throw InputError(
          file.source.path().string() + ":" + std::to_string(file.row_lines[j]) +
          (v14 ? ": RNodes: " + std::to_string(file.BlSpn[j]) + " m lies outside the blade (HubRad to TipRad = " +
                     std::to_string(hub_radius) + " to " + std::to_string(hub_radius + length) + " m)"
               : ": BlSpn: " + std::to_string(span) +
                     " m lies outside the blade (0 to TipRad − HubRad = " + std::to_string(length) + " m)"));
    BodyPoint pt = beamPoint(blade.beam.props, blade.beam.shapes, b.opt.axial_shortening, std::min(span, length),
                             "aero " + std::to_string(j + 1));
    // AeroDyn's (x, y) offsets of the aerodynamic centre are body (y, z): aero_model.hpp.
    if (blade.finite_element) atAerodynamicCentre(pt, file.BlCrvAC[j], file.BlSwpAC[j]);
    else {
      pt.P(1, 0) += file.BlCrvAC[j];
      pt.P(2, 0) += file.BlSwpAC[j];
    }
    const Vec3 node(span, file.BlCrvAC[j], file.BlSwpAC[j]);
    z += (node - previous).norm();
    previous = node;
    AeroStation st;
    st.point = static_cast<int>(body.points.size());
    body.points.push_back(std::move(pt));
    st.span = span;
    st.z = z;
    st.chord = file.BlChord[j];
    st.twist = file.BlTwist[j] * deg;
    st.curve = file.BlCrvAng[j] * deg;
    st.polar = file.BlAFID[j] - 1;
    const double lo = j > 0 ? file.BlSpn[j - 1] : file.BlSpn[j], hi = j + 1 < n ? file.BlSpn[j + 1] : file.BlSpn[j];
    st.weight = v14 ? file.element_width[j] : 0.5 * (hi - lo);
    out.stations.push_back(st);
  }
  return out;
}

// The unsteady-airfoil data of the deck (UA_Mod 4 or 6): each airfoil's table (the one kept, as the polar)
// and which elements carry states, by AeroDyn's span rule on the elements' distances from the rotor axis in
// the undeflected, coned rotor (AeroDyn Init_MiscVars: rLocal at initialization) and its airfoil rule.
void addUnsteadyAirfoils(AeroModel& am, const io::AeroDeckInput& deck, double hub_radius, double precone) {
  const io::AeroDynInput& ad = deck.aerodyn;
  if (ad.UA_Mod != 4 && ad.UA_Mod != 6) return;
  am.ua_mod = ad.UA_Mod;
  for (const io::AirfoilInput& af : deck.airfoils) {
    am.ua_tables.push_back(io::airfoilUa(af, 0, ad.UA_Mod));
    am.ua_has_cm.push_back(ad.UseBlCm && !af.tables.front().cm.empty());
  }
  std::vector<std::vector<double>> r(am.blades.size());
  double r_max = 0;
  for (std::size_t k = 0; k < am.blades.size(); ++k)
    for (const AeroStation& st : am.blades[k].stations) {
      r[k].push_back((hub_radius + st.span) * std::cos(precone));
      r_max = std::max(r_max, r[k].back());
    }
  if (!(r_max > 0)) return;
  for (std::size_t k = 0; k < am.blades.size(); ++k) {
    const std::vector<bool> on = aero::uaSpanMask(r[k], r_max, ad.UAStartRad, ad.UAEndRad);
    for (std::size_t j = 0; j < on.size(); ++j) {
      AeroStation& st = am.blades[k].stations[j];
      st.ua = on[j] && aero::uaPossible(am.ua_tables[static_cast<std::size_t>(st.polar)]);
    }
  }
}

// Dynamic inflow of the deck (BEMT with DBEMT_Mod 3, either syntax: the reader gives Wake_Mod 1 and the
// DBEMT_Mod): τ1 and each element's span ratio for τ2, its distance from the rotor axis in the undeflected,
// coned rotor over the largest (AeroDyn DBEMT_Init: rLocal at initialization over rTip). The node sits at
// (BlCrvAC, BlSwpAC, HubRad + BlSpn) in the coned blade frame (out of plane, in plane, along the span):
// r = √(((HubRad + BlSpn) cos β − BlCrvAC sin β)² + BlSwpAC²), β the precone (OpenFAST's r-test
// Fake5MW_AeroLin_B1_UA4_DBEMT3: its 1/τ2 to 13 digits, the straight blade's to 2e-4).
void addDynamicInflow(AeroModel& am, const io::AeroDeckInput& deck, double hub_radius, double precone) {
  const io::AeroDynInput& ad = deck.aerodyn;
  if (ad.Wake_Mod != 1 || ad.DBEMT_Mod != 3 || !ad.tau1_const) return;
  std::vector<std::vector<double>> r(am.blades.size());
  double r_max = 0;
  for (std::size_t k = 0; k < am.blades.size(); ++k) {
    const io::AeroDynBladeInput& file = deck.blades[k];
    for (std::size_t j = 0; j < am.blades[k].stations.size(); ++j) {
      const double radial = (hub_radius + am.blades[k].stations[j].span) * std::cos(precone) -
                            file.BlCrvAC[j] * std::sin(precone);
      r[k].push_back(std::hypot(radial, file.BlSwpAC[j]));
      r_max = std::max(r_max, r[k].back());
    }
  }
  if (!(r_max > 0)) return;
  am.dbemt_mod = 3;
  am.tau1 = *ad.tau1_const;
  for (std::size_t k = 0; k < am.blades.size(); ++k)
    for (std::size_t j = 0; j < r[k].size(); ++j) am.blades[k].stations[j].span_ratio = r[k][j] / r_max;
}

}  // namespace

void addAerodynamics(Builder& b, const DrivetrainParts& dt, const RotorParts& rotor, const io::AeroDeckInput& deck) {
  const io::ElastoDynConfiguration& c = b.ed.config;
  Model& m = b.model();
  AeroModel& am = m.aero;
  for (const io::AirfoilInput& af : deck.airfoils)
    am.polars.push_back(io::airfoilPolar(af, deck.aerodyn.UseBlCm, deck.reynolds));
  const double length = c.TipRad - c.HubRad;
  // AeroDyn needs a blade file per blade, ADBlFile(1) to ADBlFile(NumBl); the reader takes those present.
  if (deck.blades.size() < rotor.blades.size())
    throw InputError(deck.aerodyn.source.where("ADBlFile(" + std::to_string(deck.blades.size() + 1) + ")",
                                               "key not found in this file (ElastoDyn NumBl = " +
                                                   std::to_string(rotor.blades.size()) +
                                                   " needs a blade file per blade)"));
  for (std::size_t k = 0; k < rotor.blades.size(); ++k) {
    const io::AeroDynBladeInput& file = deck.blades[k];
    for (int j = 0; j < file.NumBlNds; ++j)
      if (file.BlAFID[j] < 1 || file.BlAFID[j] > static_cast<int>(am.polars.size()))
        throw InputError(file.source.path().string() + ":" + std::to_string(file.row_lines[j]) +
                         ": BlAFID: " + std::to_string(file.BlAFID[j]) +
                         " is not an airfoil of the AeroDyn file (1 to " + std::to_string(am.polars.size()) + ")");
    am.blades.push_back(bladeElements(b, rotor.blades[k], file, c.HubRad, length));
  }
  am.hub_body = dt.hub;
  am.hub_radius = c.HubRad;
  // AeroDyn v14's elements are strips whose outer edge is the tip (TipRad); v15's last node is the tip.
  const bool v14 = !deck.blades.front().element_width.empty();
  am.rotor_radius = (v14 ? c.TipRad : c.HubRad + deck.blades.front().BlSpn.back()) * std::cos(c.PreCone.front() * deg);
  am.tip_radius = v14 ? c.TipRad : 0;
  for (const AeroBlade& bl : am.blades) am.tip_radius = std::max(am.tip_radius, bl.stations.back().z);
  const io::AeroDynInput& ad = deck.aerodyn;
  am.air_density = ad.AirDens;
  am.kinematic_viscosity = ad.KinVisc;
  am.induction = ad.Wake_Mod == 1;
  am.bem.tip_loss = ad.TipLoss;
  am.bem.hub_loss = ad.HubLoss;
  am.bem.tan_ind = ad.TanInd;
  am.bem.ai_drag = ad.AIDrag;
  am.bem.ti_drag = ad.TIDrag;
  am.bem.max_iter = std::max(ad.MaxIter, 100);
  // AeroDyn v15+'s Pitt/Peters correction (v14 files carry their own skew model, not read).
  if (!v14 && ad.skew == io::SkewModel::Active && ad.SkewRedistr_Mod == 1) am.skew_factor = ad.SkewModFactor;
  if (!v14) addUnsteadyAirfoils(am, deck, c.HubRad, c.PreCone.front() * deg);
  if (!v14) addDynamicInflow(am, deck, c.HubRad, c.PreCone.front() * deg);

  const io::InflowWindInput& w = deck.inflow;
  Input wind;
  wind.name = "wind speed";
  wind.unit = "m/s";
  wind.value = w.HWindSpeed;
  m.inputs.push_back(wind);
  m.roles.wind_speed_input = m.ninput() - 1;
  am.wind.reference_height = w.RefHt;
  am.wind.shear_exponent = w.PLExp;
  am.wind.direction = w.PropagationDir * deg;
  am.wind.upflow = w.VFlowAng * deg;
  // AeroDyn's rotor outputs (names as OpenFAST's channels, SI units), with its RtSpeed (the rotor
  // speed ElastoDyn calls RotSpeed; ROSCO's linear models look it up by AeroDyn's name).
  for (Output& o : aeroRotorOutputs()) m.outputs.push_back(std::move(o));
  if (const int rot = outputIndex(m, "RotSpeed"); rot >= 0) {
    Output rt = m.outputs[rot];
    rt.name = "RtSpeed";
    m.outputs.push_back(std::move(rt));
  }
}

void addGeneratorTorqueLaw(Builder& b, const io::ServoDynInput& servo) {
  if (servo.VSContrl.value_or(0) == 0 && servo.GenModel.value_or(1) == 1 && !servo.SIG_SySp) return;
  const io::GeneratorTorqueLaw law = io::generatorTorqueLaw(servo);  // refuses controllers in user code
  GeneratorTorqueLaw& g = b.model().generator;
  g.speed_output = outputIndex(b.model(), "GenSpeed");
  if (!g.active() || b.model().roles.generator_torque_input < 0)
    throw InputError("ServoDyn torque law: the model has no generator torque input or GenSpeed output");
  const double rpm = std::numbers::pi / 30.0;  // rad/s per rpm
  if (law.mode == io::TorqueControl::SimpleInductionGenerator) {
    g.kind = GeneratorTorqueLaw::Kind::SimpleInduction;
    g.sync_speed = law.SIG_SySp * rpm;
    g.rated_speed = g.sync_speed * (1.0 + law.SIG_SlPc / 100.0);
    g.rated_torque = law.SIG_RtTq;
    g.pullout_ratio = law.SIG_PORt;
  } else if (law.mode == io::TorqueControl::TheveninInductionGenerator) {
    // ServoDyn's initialization of the equivalent circuit (SrvD_SetParameters, GenModel = 2).
    g.kind = GeneratorTorqueLaw::Kind::Thevenin;
    const double den = law.TEC_SRes * law.TEC_SRes + std::pow(law.TEC_SLR + law.TEC_MR, 2);
    const double re1 = law.TEC_SRes * law.TEC_MR * law.TEC_MR / den;
    const double xe1 = law.TEC_MR * (law.TEC_SRes * law.TEC_SRes + law.TEC_SLR * (law.TEC_SLR + law.TEC_MR)) / den;
    g.sync_speed = 4.0 * std::numbers::pi * law.TEC_Freq / law.TEC_NPol;
    const double k1 = std::pow(xe1 + law.TEC_RLR, 2), k2 = law.TEC_MR * law.TEC_MR / den;
    g.tec_a = law.TEC_RRes * k2 / g.sync_speed * law.TEC_VLL * law.TEC_VLL;
    g.tec_c0 = law.TEC_RRes * law.TEC_RRes;
    g.tec_c1 = -2.0 * re1 * law.TEC_RRes;
    g.tec_c2 = re1 * re1 + k1;
    g.rated_speed = pulloutSpeeds(g).second;  // the top of the trim's speed bracket
    g.rated_torque = generatorTorque(g, g.rated_speed);
  } else {
    g.rated_speed = law.VS_RtGnSp * rpm;
    g.rated_torque = law.VS_RtTq;
    g.k2 = law.VS_Rgn2K / (rpm * rpm);
    g.slip = law.VS_SlPc / 100.0;
  }
  g.efficiency = law.GenEff / 100.0;
  for (Output& o : generatorOutputs()) b.model().outputs.push_back(std::move(o));
}

}  // namespace whirl::elastodyn
