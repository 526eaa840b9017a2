#pragma once
/// \file
/// The aerodynamic part of a model: blade elements on beam bodies, their airfoil polars, the steady
/// wind and the BEM options. Plain data like the rest of the Model: the wind speed is an input
/// (u), so the operating condition sets it and ∂e/∂u gives the wind column of Q.
///
/// Frames: a blade body's frame is pitched (its pitch coordinate turns it about −x, x = span). The
/// element's "no-pitch" frame is the body frame turned back by the pitch angle; its axes in the
/// order of AeroDyn's blade frame are (x_a, y_a, z_a) = (body y, body z, body x): x_a out of the
/// rotor plane (downwind), y_a in the plane against the direction of rotation, z_a along the span.
/// The element's annulus frame is that frame turned about y_a by the out-of-plane slope of the
/// deflected span axis — AeroDyn's "orientationAnnulus" without sweep, pitch and twist
/// (Calculate_MeshOrientation_NoSweepPitchTwist, AeroDyn v15 / OpenFAST 3.x).
#include <string>
#include <vector>

#include "src/aero/bem.hpp"
#include "src/aero/polar.hpp"
#include "src/aero/ua_coefficients.hpp"
#include "src/base/types.hpp"

namespace whirl {

/// One blade element: a node of AeroDyn's blade mesh.
struct AeroStation {
  int point = -1;    ///< body point at the aerodynamic centre (shape values at the station's span)
  double span = 0;   ///< distance from the blade root along the undeflected span axis [m]
  double z = 0;      ///< distance from the rotor apex along the blade (AeroDyn zLocal, loss constants) [m]
  double chord = 0;  ///< [m]
  double twist = 0;  ///< aerodynamic twist, positive towards feather [rad]
  /// AeroDyn's BlCrvAng [rad]: the section's plane turned about the edgewise axis y_r, its span axis
  /// leaning downwind (out of the rotor plane) by it at zero pitch; it tilts the annulus frame
  /// (src/dynamics/aero_element.hxx: elementFrame) on top of the elastic slope.
  double curve = 0;
  int polar = -1;     ///< index into AeroModel::polars
  double weight = 0;  ///< length the element's load per unit length acts over (trapezoid rule) [m]
  /// Carries unsteady-airfoil states (AeroModel::ua_mod > 0, inside UAStartRad … UAEndRad and a table that
  /// allows them: src/aero/ua_span.hpp).
  bool ua = false;
  /// Distance from the rotor axis over the largest of the rotor's elements, undeflected (AeroDyn DBEMT
  /// p%spanRatio: rLocal at initialization over its largest), for DBEMT's τ2; set with AeroModel::dbemt_mod.
  double span_ratio = 0;
};

/// The elements of one blade.
struct AeroBlade {
  int body = -1;       ///< the beam body the elements sit on
  int pitch_dof = -1;  ///< the coordinate that pitches the body (−1: none, pitch 0)
  std::vector<AeroStation> stations;
};

/// Steady wind (InflowWind WindType = 1): horizontal speed U at the reference height, power-law shear
/// U (z/z_ref)^α, propagation direction and upflow. U is the value of the model's wind-speed input
/// (ModelRoles::wind_speed_input).
struct SteadyWind {
  double reference_height = 0;  ///< z_ref above the ground frame origin [m]
  double shear_exponent = 0;    ///< α [-]
  double direction = 0;         ///< propagation direction, positive turning the wind towards −Y [rad]
  double upflow = 0;            ///< upflow angle, positive upwards [rad]
};

struct AeroModel {
  std::vector<aero::Polar> polars;
  std::vector<AeroBlade> blades;
  int hub_body = -1;                      ///< its frame: origin at the rotor apex, x along the rotor axis (disk normal)
  double air_density = 1.225;             ///< [kg/m³]
  double kinematic_viscosity = 1.464e-5;  ///< [m²/s], for polars with tables on the Reynolds number
  double hub_radius = 0;                  ///< AeroDyn zHub: apex to blade root along the blade (hub loss) [m]
  double tip_radius = 0;                  ///< AeroDyn zTip: apex to the last element along the blade (tip loss) [m]
  double rotor_radius = 0;                ///< radius of the swept disk (AeroDyn rTipFix: coned tip) for Cp, Ct, TSR [m]
  bool induction = true;  ///< BEM induction (AeroDyn WakeMod = 1); false: geometric inflow (WakeMod = 0)
  aero::BemOptions bem;
  SteadyWind wind;
  /// Unsteady airfoil aerodynamics (AeroDyn UA_Mod): 0 none, 4 (HGM) or 6 (Øye); other values leave it 0.
  /// Used only by linearizations that ask for the states (LinearizeOptions::unsteady_aero).
  int ua_mod = 0;
  std::vector<aero::UaTable> ua_tables;  ///< per polar (same index) when ua_mod > 0
  std::vector<bool> ua_has_cm;           ///< per polar: the table has a Cm column read (AeroDyn ColCm > 0)
  /// Dynamic inflow (AeroDyn DBEMT_Mod): 3 (Øye's continuous model, src/aero/dynamic_inflow.hpp) or 0; the
  /// discrete models 1, 2 leave it 0. Used only by linearizations with the states (LinearizeOptions::unsteady_aero).
  int dbemt_mod = 0;
  double tau1 = 0;  ///< DBEMT's τ1 (tau1_const) [s]
  /// The skewed-wake correction's constant K (AeroDyn `SkewModFactor`, 15π/32 by default) when the deck
  /// asks for the correction (`SkewMod = 2`, or `Skew_Mod = 1` with `SkewRedistr_Mod = 1`); 0: none
  /// (src/dynamics/aero_skew.hxx).
  double skew_factor = 0;

  bool active() const { return !blades.empty(); }
  /// Number of elements over all blades (the length of an AeroInflow).
  int nstations() const {
    int n = 0;
    for (const AeroBlade& b : blades) n += static_cast<int>(b.stations.size());
    return n;
  }
};

/// ServoDyn's simple variable-speed torque law (VSContrl = 1): region 2 k ω², the linear region 2½
/// up to rated speed, constant torque above. Generator speed ω_g (high-speed shaft) is the output
/// `speed_output`; the torque is added to the value of the generator-torque input
/// (ModelRoles::generator_torque_input: the trim or controller offset), whose loads apply it.
struct GeneratorTorqueLaw {
  int speed_output = -1;    ///< the "GenSpeed" output [rad/s], a combination of coordinate rates
  double rated_speed = 0;   ///< VS_RtGnSp [rad/s]
  double rated_torque = 0;  ///< VS_RtTq [N m]
  double k2 = 0;            ///< VS_Rgn2K [N m s²/rad²]
  double slip = 0;          ///< VS_SlPc / 100 [-]
  double efficiency = 1;    ///< GenEff / 100: electrical over mechanical power [-]
  /// Which law: ServoDyn's simple variable-speed law (VSContrl = 1: rated_speed, rated_torque, k2,
  /// slip), its simple induction generator (VSContrl = 0, GenModel = 1: torque rated_torque (ω − ω_sync)
  /// / (rated_speed − ω_sync) within ± pullout_ratio · rated_torque, rated_speed = ω_sync (1 +
  /// SIG_SlPc/100)) or its Thevenin-equivalent induction generator (GenModel = 2: the tec_* terms).
  enum class Kind { VariableSpeed, SimpleInduction, Thevenin } kind = Kind::VariableSpeed;
  double sync_speed = 0;     ///< SIG_SySp, or 4π TEC_Freq / TEC_NPol [rad/s]
  double pullout_ratio = 1;  ///< SIG_PORt: pull-out over rated torque [-]
  /// Thevenin: torque = tec_a (s) / (tec_c0 + tec_c1 s + tec_c2 s²), s = (ω − ω_sync)/ω_sync; tec_a =
  /// A0 · TEC_VLL² (ServoDyn's A0 = TEC_RRes K2 / ω_sync) [N m], tec_c* [Ω²].
  double tec_a = 0, tec_c0 = 0, tec_c1 = 0, tec_c2 = 0;
  bool induction() const { return kind != Kind::VariableSpeed; }
  bool active() const { return speed_output >= 0; }
};

}  // namespace whirl
