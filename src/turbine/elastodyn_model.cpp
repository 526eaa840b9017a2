// buildElastoDynModel: the parts (tower, nacelle and drivetrain, blades), inputs and outputs, springs, gravity;
// readElastoDynModel: the deck read in one pass (io::readOpenFastDeck) with the overrides; readElastoDynFlexibleBeams:
// tower and blades for `whirl shapes`.
#include "src/turbine/elastodyn_model.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"
#include "src/io/openfast/aerodyn/aero_support.hpp"
#include "src/io/openfast/openfast_deck.hpp"
#include "src/io/openfast/openfast_overrides.hpp"
#include "src/io/openfast/openfast_support.hpp"
#include "src/turbine/elastodyn_fem_shapes.hpp"
#include "src/turbine/elastodyn_parts.hpp"
#include "src/turbine/elastodyn_tower_beam.hpp"

namespace whirl {
namespace elastodyn {

int Builder::addDof(const std::string& name, int body, DofKind kind, int local, bool active, double value,
                    double rate) {
  Dof d;
  d.name = name;
  d.kind = kind;
  d.body = body;
  d.local = local;
  d.frozen = !active;
  d.value = value;
  d.rate = rate;
  return builder.addDof(d, Where{ed.source.path().string(), 0, "", ""});
}

}  // namespace elastodyn

namespace {

constexpr double deg = std::numbers::pi / 180.0;

double gravityOf(const io::OpenFastTurbine& t, const ElastoDynModelOptions& opt) {
  if (opt.gravity) {
    if (!std::isfinite(*opt.gravity)) throw InputError("gravity: not a finite number");
    return *opt.gravity;
  }
  if (t.fst.Gravity) return *t.fst.Gravity;
  if (t.elastodyn.Gravity) return *t.elastodyn.Gravity;
  if (t.fst.source.path().empty()) return 9.80665;  // an ElastoDyn file alone (OpenFAST's default)
  return io::gravity(t);                            // throws, naming the .fst
}

// ServoDyn's yaw spring when the yaw is free and ServoDyn is on.
std::optional<io::ServoDynInput> yawSpring(const io::OpenFastTurbine& t, const ElastoDynModelOptions& opt) {
  if (!opt.yaw_spring_from_servodyn || !t.elastodyn.dof.YawDOF || t.fst.CompServo == 0) return std::nullopt;
  return opt.servodyn;  // read with the deck (io::readOpenFastDeck)
}

}  // namespace

Model buildElastoDynModel(const io::OpenFastTurbine& t, const ElastoDynModelOptions& opt) {
  io::requireSupported(t);
  const io::ElastoDynInput& ed = t.elastodyn;
  elastodyn::Builder b{ed, opt, ModelBuilder{}, t.beamdyn.empty() ? nullptr : &t.beamdyn};
  // The title names the model and titles the Campbell plot.
  requirePrintable(ed.source.title(), ed.source.path().string(), ed.source.titleLine(), "title");
  b.model().name = ed.source.title();
  b.model().gravity = Vec3(0, 0, -gravityOf(t, opt));

  const elastodyn::PlatformParts platform = t.subdyn ? elastodyn::addSubstructurePlatform(b, t)
                                                     : elastodyn::addPlatform(b);
  const elastodyn::TowerParts tower = elastodyn::addTower(b, platform);
  const elastodyn::DrivetrainParts dt = elastodyn::addNacelleAndDrivetrain(b, tower);
  const elastodyn::RotorHub hub = ed.config.NumBl == 2 ? elastodyn::addTeeteringHub(b, dt)
                                                       : elastodyn::RotorHub{dt.hub, Vec3::Zero(), 0.0, -1};
  const elastodyn::RotorParts rotor = elastodyn::addBlades(b, hub);
  elastodyn::addInputsAndOutputs(b, tower, dt, rotor);
  elastodyn::addPlatformOutputs(b, platform);
  if (opt.aero) {
    elastodyn::addAerodynamics(b, dt, rotor, *opt.aero);
    if (opt.torque_law) elastodyn::addGeneratorTorqueLaw(b, *opt.torque_law);
  }

  b.model().deck_controller = opt.controller;
  elastodyn::addOffshoreLoads(b, platform, t);
  if (ed.dof.DrTrDOF) b.model().springs.push_back({dt.drivetrain, ed.drivetrain.DTTorSpr, ed.drivetrain.DTTorDmp, 0.0});
  if (const std::optional<io::ServoDynInput> s = yawSpring(t, opt))
    b.model().springs.push_back({dt.yaw, s->YawSpr, s->YawDamp, s->YawNeut * deg});

  return std::move(b.builder).finish();
}

io::OpenFastTurbine readElastoDynTurbine(const std::string& path, const std::vector<std::string>& overrides,
                                         ElastoDynModelOptions& opt) {
  std::vector<io::KeyOverride> file_overrides;
  for (const std::string& text : overrides) {
    io::KeyOverride o = io::parseOverride(text);
    if (io::toLower(o.key) == "gravity") {  // a whirl option, whichever file has (or lacks) Gravity
      const std::optional<double> g = io::parseFortranDouble(o.value);
      if (!g || !std::isfinite(*g)) throw InputError("--set '" + text + "': gravity: not a finite number");
      if (!(*g >= 0.0 && *g <= limits::kMaxGravity))
        throw InputError(
            fmt::format("--set '{}': gravity: must lie in [0, {:g}] m/s² (100 g at most)", text, limits::kMaxGravity));
      opt.gravity = *g;
      continue;
    }
    if (io::toLower(o.key) == "shapes") {  // a whirl option: the tower and blade shape functions
      const std::string v = io::toLower(o.value);
      if (v != "fem" && v != "polynomial")
        throw InputError("--set '" + text +
                         "': shapes: expected polynomial (the files' mode-shape polynomials) or fem");
      opt.fem_shapes = v == "fem";
      continue;
    }
    if (io::toLower(o.key) == "blade_elements" || io::toLower(o.key) == "blade_modes") {  // BeamDyn blades
      const std::optional<double> v = io::parseFortranDouble(o.value);
      if (!v || *v != std::floor(*v) || *v < 1 || *v > 10000)
        throw InputError("--set '" + text + "': " + o.key + ": expected a positive integer");
      (io::toLower(o.key) == "blade_modes" ? opt.blade_modes : opt.blade_elements) = static_cast<int>(*v);
      continue;
    }
    file_overrides.push_back(std::move(o));
  }
  io::OverrideSet set(std::move(file_overrides));
  io::OpenFastDeck deck = io::readOpenFastDeck(path, &set, {opt.yaw_spring_from_servodyn});
  const io::OpenFastTurbine& t = deck.turbine;
  if (opt.yaw_spring_from_servodyn && t.elastodyn.dof.YawDOF && t.fst.CompServo != 0) opt.servodyn = deck.servodyn;
  if (deck.aero) {
    opt.aero = std::move(deck.aero);
    opt.torque_law = deck.servodyn;
    opt.controller = std::move(deck.controller);
    if (opt.torque_law)
      if (std::optional<std::string> note = io::externalTorqueController(*opt.torque_law)) {
        opt.aero->notes.push_back(std::move(*note));
        opt.torque_law.reset();
      }
  }
  set.requireAllUsed();
  return std::move(deck.turbine);
}

Model readElastoDynModel(const std::string& path, const std::vector<std::string>& overrides) {
  ElastoDynModelOptions opt;
  const io::OpenFastTurbine t = readElastoDynTurbine(path, overrides, opt);
  return buildElastoDynModel(t, opt);
}

std::vector<fem::FlexibleBeam> readElastoDynFlexibleBeams(const std::string& path,
                                                          const std::vector<std::string>& overrides,
                                                          std::optional<double> rpm) {
  ElastoDynModelOptions opt;
  const io::OpenFastTurbine t = readElastoDynTurbine(path, overrides, opt);
  io::requireSupported(t);
  const io::ElastoDynInput& ed = t.elastodyn;
  std::vector<fem::FlexibleBeam> out;
  // Tower: the FE input of shapes=fem; current shapes as the model would have them.
  const ElastoDynTowerBeam tower = elastoDynTowerBeam(ed);
  fem::FlexibleBeam tw{"tower", elastoDynTowerModeInput(ed, tower.props, gravityOf(t, opt)), tower.shapes};
  if (opt.fem_shapes) tw.shapes = elastoDynTowerFemShapes(tw.input);
  out.push_back(std::move(tw));
  const int nodes = ed.BldNodes.value_or(opt.blade_nodes > 0 ? opt.blade_nodes : 17);
  const double speed = rpm.value_or(ed.init.RotSpeed) * std::numbers::pi / 30.0;
  for (std::size_t k = 0; k < ed.blades.size(); ++k) {
    const ElastoDynBladeBeam blade = elastoDynBladeBeam(ed.blades[k], ed.config.TipRad - ed.config.HubRad, nodes,
                                                        ed.mass.TipMass[k]);
    fem::FlexibleBeam b{"blade " + std::to_string(k + 1), elastoDynBladeModeInput(blade, ed.config.HubRad, speed),
                        blade.shapes};
    // shapes=fem builds the model's blades at RotSpeed; --rpm only changes the FE modes compared.
    if (opt.fem_shapes)
      b.shapes = elastoDynBladeFemShapes(
          elastoDynBladeModeInput(blade, ed.config.HubRad, ed.init.RotSpeed * std::numbers::pi / 30.0));
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace whirl
