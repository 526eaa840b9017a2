// The ElastoDyn blades on the hub (ElastoDyn `SetCoordSy`: frames g', i (cone), j (pitch)).
#include <cmath>
#include <numbers>

#include "src/base/error.hpp"
#include "src/turbine/beamdyn_blade.hpp"
#include "src/turbine/elastodyn_blade_shapes.hpp"
#include "src/turbine/elastodyn_fem_shapes.hpp"
#include "src/turbine/elastodyn_parts.hpp"

namespace whirl::elastodyn {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

}  // namespace

Mat3 axisRotation(int axis, double angle) { return Eigen::AngleAxisd(angle, Vec3::Unit(axis)).toRotationMatrix(); }

RotorParts addBlades(Builder& b, const RotorHub& hub) {
  RotorParts out;
  out.teeter = hub.teeter;
  const io::ElastoDynInput& ed = b.ed;
  const io::ElastoDynConfiguration& c = ed.config;
  const int nodes = ed.BldNodes.value_or(b.opt.blade_nodes);
  if (!ed.BldNodes && nodes < 1)
    throw InputError(b.where("BldNodes",
                             "not in this file (ElastoDyn v1.00–v1.01 took the blade nodes from "
                             "AeroDyn): set ElastoDynModelOptions::blade_nodes"));
  if (nodes < 1) throw InputError(b.where("BldNodes", "must be at least 1"));
  const double L = c.TipRad - c.HubRad;
  // Blade body axes in the pitched frame j: x = j3 (span), y = j1 (out of plane), z = j2 (in plane).
  Mat3 span_first;
  span_first.col(0) = Vec3::UnitZ();
  span_first.col(1) = Vec3::UnitX();
  span_first.col(2) = Vec3::UnitY();
  const bool on[3] = {ed.dof.FlapDOF1, ed.dof.EdgeDOF, ed.dof.FlapDOF2};

  const int nb = c.NumBl;
  for (int k = 0; k < nb; ++k) {
    const std::string name = "blade " + std::to_string(k + 1);
    // BeamDyn (CompElast = 2): the FE blade's fixed-root modes as shapes, its exact modal stiffness and
    // damping; ElastoDyn's TipMass is not applied (OpenFAST applies it to ElastoDyn's blades only).
    std::optional<BeamDynBladeBody> fe;
    if (b.beamdyn)
      fe = beamDynBladeBody(b.beamdyn->at(static_cast<std::size_t>(k)), {b.opt.blade_elements, b.opt.blade_modes});
    const double tip_mass = fe ? 0.0 : ed.mass.TipMass[static_cast<std::size_t>(k)];
    ElastoDynBladeBeam beam = fe ? fe->beam
                                 : elastoDynBladeBeam(ed.blades.at(static_cast<std::size_t>(k)), L, nodes, tip_mass);
    // shapes=fem: the FE modes of the blade's properties at the initial rotor speed RotSpeed.
    if (b.opt.fem_shapes && !fe)
      beam.shapes = elastoDynBladeFemShapes(elastoDynBladeModeInput(beam, c.HubRad, ed.init.RotSpeed * pi / 30));
    BeamOptions o;
    // The FE shapes are linear between the FE nodes: 4 trapezoid points per element.
    o.integration = fe ? BeamIntegration{BeamIntegration::Trapezoid, 4 * b.opt.blade_elements}
                       : BeamIntegration{BeamIntegration::Midpoint, nodes};
    o.axial_shortening = b.opt.axial_shortening;
    const BeamBody bb = buildBeamBody(beam.props, beam.shapes, o, name);

    // Hub frame (x = shaft, blade 1 along z at zero azimuth) → blade k's azimuth (about x; with δ3,
    // ElastoDyn's g frame, turned by δ3 more) → cone (about y, ElastoDyn's i frame:
    // i3 = sin β g1' + cos β g3') → span-first body axes; the pitch joint turns about −x (ElastoDyn:
    // j1 = cos θ i1 − sin θ i2). The root is HubRad along i3 from the apex.
    const Mat3 coned = axisRotation(0, hub.azimuth_offset + 2 * pi * k / nb) *
                       axisRotation(1, c.PreCone[static_cast<std::size_t>(k)] * deg);
    Body bl;
    bl.name = name;
    bl.parent = hub.body;
    bl.offset = hub.apex + c.HubRad * coned.col(2);
    bl.rotation = coned * span_first;
    bl.joint = JointType::Revolute;
    bl.axis = -Vec3::UnitX();
    bl.inertia = bb.inertia;
    if (fe) {
      bl.elastic.K = fe->K;
      bl.elastic.D = fe->D;
    } else {
      bl.elastic.K = applyStiffnessTuners(bb.elastic.K, beam.stiffness_tuner);
      bl.elastic.D = elastoDynModalDamping(bl.elastic.K, beam.generalized_mass.array() - tip_mass, beam.damping_ratio);
    }
    const double length = fe ? fe->length : L;
    bl.points.push_back(beamPoint(beam.props, beam.shapes, o.axial_shortening, length, "tip"));
    bl.nodes = beamNodes(beam.props, beam.shapes, o.axial_shortening, length);
    const int body = b.addBody(std::move(bl));
    out.pitch.push_back(
        b.addDof(name + " pitch", body, DofKind::Joint, 0, false, ed.init.BlPitch[static_cast<std::size_t>(k)] * deg));
    out.blades.push_back({body, out.pitch.back(), beam, fe.has_value()});
    std::vector<int> dofs(beam.shapes.size());
    for (std::size_t s = 0; s < beam.shapes.size(); ++s) {
      const int d = b.addDof(name + " " + beam.shapes[s]->name, body, DofKind::Elastic, static_cast<int>(s),
                             fe ? true : on[s]);
      b.model().dofs[d].blade = k;  // rotating frame, blade k: multiblade coordinates
      dofs[s] = d;
    }
    out.shape_dofs.push_back(dofs);

    if (tip_mass > 0) {
      Body tip;
      tip.name = name + " tip mass";
      tip.parent = body;
      tip.parent_point = 0;
      tip.inertia = rigidBodyInertia(tip_mass, Vec3::Zero(), Mat3::Zero());
      b.addBody(std::move(tip));
    }
  }
  return out;
}

}  // namespace whirl::elastodyn
