// Checks and renumbering of the aerodynamic part of a model (called by finalize).
#include "src/model/aero_model.hpp"

#include <cmath>
#include <string>

#include "src/base/error.hpp"
#include "src/model/model.hpp"

namespace whirl {

void finalizeAero(Model& m, const std::vector<int>& new_body, const std::vector<int>& new_dof) {
  AeroModel& a = m.aero;
  auto body = [&](int& b, const std::string& what) {
    if (b < 0 || b >= static_cast<int>(new_body.size())) throw InputError(what + ": no such body");
    b = new_body[b];
  };
  if (a.active()) {
    body(a.hub_body, "aerodynamics: hub");
    if (!(a.air_density > 0) || !std::isfinite(a.air_density))
      throw InputError("aerodynamics: air density must be positive, got " + std::to_string(a.air_density));
    if (!(a.tip_radius > a.hub_radius) || !(a.hub_radius >= 0))
      throw InputError("aerodynamics: need 0 <= hub radius < tip radius");
    const SteadyWind& w = a.wind;
    if (m.roles.wind_speed_input < 0 || m.roles.wind_speed_input >= m.ninput())
      throw InputError("aerodynamics: the model has no wind-speed input (ModelRoles::wind_speed_input)");
    if (w.shear_exponent != 0 && !(w.reference_height > 0))
      throw InputError("wind: a shear exponent needs a positive reference height");
    if (!std::isfinite(w.shear_exponent) || !std::isfinite(w.direction) || !std::isfinite(w.upflow))
      throw InputError("wind: shear exponent, direction and upflow must be finite");
  }
  for (std::size_t k = 0; k < a.blades.size(); ++k) {
    AeroBlade& bl = a.blades[k];
    const std::string what = "aerodynamics: blade " + std::to_string(k + 1);
    body(bl.body, what);
    if (bl.pitch_dof >= 0) {
      if (bl.pitch_dof >= static_cast<int>(new_dof.size())) throw InputError(what + ": no such pitch DOF");
      bl.pitch_dof = new_dof[bl.pitch_dof];
      if (m.dofs[bl.pitch_dof].body != bl.body || m.dofs[bl.pitch_dof].kind != DofKind::Joint ||
          m.bodies[bl.body].joint != JointType::Revolute)
        throw InputError(what + ": the pitch DOF must be the revolute joint of the blade body");
    }
    const Body& b = m.bodies[bl.body];
    for (std::size_t s = 0; s < bl.stations.size(); ++s) {
      const AeroStation& st = bl.stations[s];
      const std::string at = what + " element " + std::to_string(s + 1);
      if (st.point < 0 || st.point >= static_cast<int>(b.points.size())) throw InputError(at + ": no such body point");
      if (st.polar < 0 || st.polar >= static_cast<int>(a.polars.size())) throw InputError(at + ": no such airfoil");
      if (!(st.chord > 0) || !std::isfinite(st.chord)) throw InputError(at + ": chord must be positive");
      if (!(st.weight >= 0) || !std::isfinite(st.weight) || !std::isfinite(st.twist) || !(st.z > 0))
        throw InputError(at + ": span weight, twist or distance from the apex not valid");
    }
  }
  for (const Output& o : m.outputs) {
    if (o.kind != OutputKind::Rotor) continue;
    const bool gen = o.rotor_quantity == RotorQuantity::GeneratorTorque ||
                     o.rotor_quantity == RotorQuantity::GeneratorPower;
    if (gen ? !m.generator.active() : !a.active())
      throw InputError("output '" + o.name + "': the model has no " + (gen ? "generator torque law" : "aerodynamics"));
  }
  GeneratorTorqueLaw& g = m.generator;
  if (g.active() && (m.roles.generator_torque_input < 0 || m.roles.generator_torque_input >= m.ninput()))
    throw InputError("generator torque law: the model has no generator-torque input (ModelRoles)");
  if (g.speed_output >= m.noutput()) throw InputError("generator torque law: no such output");
  if (g.speed_output >= 0 && m.outputs[g.speed_output].kind != OutputKind::DofCombination)
    throw InputError("generator torque law: the speed output must be a combination of coordinate rates");
  if (g.active() && (!(g.rated_speed > 0) || !(g.rated_torque >= 0) || !(g.k2 >= 0) || !(g.slip >= 0)))
    throw InputError("generator torque law: rated speed must be positive; rated torque, k and slip not negative");
}

}  // namespace whirl
