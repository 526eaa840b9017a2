// `generator:` of a case: ServoDyn's simple variable-speed torque law (VSContrl = 1) on a generator
// torque input, with the ServoDyn key names and units, as the deck path reads it
// (src/turbine/elastodyn_aero.cpp, addGeneratorTorqueLaw).
#include <numbers>

#include "src/io/case/case_reader.hpp"

namespace whirl {

void readGenerator(const CaseNode& g, CaseBuild& build) {
  g.allowKeys({"torque_input", "speed_output", "VS_RtGnSp", "VS_RtTq", "VS_Rgn2K", "VS_SlPc", "GenEff"});
  Model& m = build.model();
  const CaseNode in = g.at("torque_input");
  const int input = build.builder.inputIndex(in.text(), in.where());
  bool applied = false;
  for (const PointLoad& l : m.point_loads) applied = applied || l.input == input;
  if (!applied)
    in.fail("no point load names input '" + in.text() +
            "': the law's torque acts through the input's point loads "
            "(e.g. a moment on the rotor about the shaft, times the gear ratio)");
  const CaseNode out = g.at("speed_output");
  const auto k = m.findOutput(out.text());
  if (!k) out.fail("no output named '" + out.text() + "' (the generator speed: a dof output of order rate)");
  const Output& o = m.outputs[*k];
  if (o.kind != OutputKind::DofCombination || o.order != 1)
    out.fail("output '" + o.name + "' must be a dof output of order rate (the generator speed, rad/s)");
  GeneratorTorqueLaw& law = m.generator;
  law.speed_output = *k;
  m.roles.generator_torque_input = input;
  auto value = [&](const char* key, bool positive) {
    const CaseNode v = g.at(key);
    const double x = v.number();
    if (positive ? !(x > 0) : x < 0) v.fail(positive ? "must be positive" : "must not be negative");
    return x;
  };
  const double rpm = std::numbers::pi / 30.0;  // rad/s per rpm
  law.rated_speed = value("VS_RtGnSp", true) * rpm;
  law.rated_torque = value("VS_RtTq", false);
  law.k2 = value("VS_Rgn2K", false) / (rpm * rpm);
  law.slip = value("VS_SlPc", false) / 100.0;
  law.efficiency = g.number("GenEff", 100.0) / 100.0;
  if (!(law.efficiency > 0) || law.efficiency > 1) g.at("GenEff").fail("must be in (0, 100] %");
  for (Output& added : generatorOutputs()) {
    if (m.findOutput(added.name)) g.fail("output name '" + added.name + "' is taken: the generator adds it");
    m.outputs.push_back(std::move(added));
  }
}

}  // namespace whirl
