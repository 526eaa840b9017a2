#pragma once
/// \file
/// Internal to the case reader (src/io/case/case_*.cpp): the model under construction with where each
/// part was written, and the readers of each section. Users call readCase() (case_file.hpp).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "src/fem/mode_shapes.hpp"
#include "src/io/case/case_file.hpp"
#include "src/io/case/case_node.hpp"
#include "src/model/model.hpp"
#include "src/model/model_builder.hpp"
#include "src/shapes/beam.hpp"
#include "src/shapes/shape.hpp"

namespace whirl {

struct FemPending;

/// The model being built (ModelBuilder: indices before finalize() reorders them) with what only a
/// case file has: its beams, which DOFs are angles, the FE bodies awaiting their geometric stiffness.
struct CaseBuild {
  /// A beam body's properties and shapes, kept for its bending-moment outputs and `whirl shapes`.
  struct Beam {
    int body = -1;
    BeamProperties props;
    std::vector<ShapePtr> shapes;
    fem::ModeShapeInput fem;       ///< FE input for `whirl shapes`: the `{from: fem}` settings, else properties only
    bool axial_shortening = true;  ///< as built (the points of the blade elements follow it)
    /// An `fe_blade` (6 × 6 sections): the blade elements' aerodynamic-centre offsets are rigid arms that
    /// turn with the section (offsetOnRigidArm), so the lift loads the torsion modes.
    bool finite_element = false;
    /// The bending-moment gains at x [m] (2 × shapes) when the shapes' curvature does not give them
    /// (an fe_blade: fem::blade6MomentGains); empty: beamMomentGains of the shapes.
    std::function<MatX(double)> moment_gains;
  };
  ModelBuilder builder;  ///< the model, where its bodies and DOFs were written, the lookups by name
  std::vector<Beam> beams;
  std::vector<bool> dof_angular;                 ///< an angle [rad]: `value_deg` and `rate_rpm` allowed
  std::vector<std::shared_ptr<FemPending>> fem;  ///< FE bodies awaiting their geometric stiffness

  Model& model() { return builder.model(); }
  const Model& model() const { return builder.model(); }
  /// Appends a DOF; fails at `w` when the name is empty or already used (ModelBuilder::addDof).
  void addDof(const std::string& name, DofKind kind, int body, int local, const Where& w, bool angular);
};

/// Applies `--set` overrides to the parsed document (case_overrides.cpp); records them in `source`.
void applyOverrides(YAML::Node& root, const std::vector<CaseOverride>& overrides, CaseSource& source);

/// `bodies:` — every body, its joint, points and DOFs, parents resolved (case_bodies.cpp).
void readBodies(const CaseNode& list, CaseBuild& build);

/// Attachment frame → joint frame: a 3×3 matrix (rows) or a map of elementary rotations
/// {x|y|z|x_deg|y_deg|z_deg: angle} applied in the order written, R = R_a1(θ1) R_a2(θ2) ….
Mat3 readRotation(const CaseNode& node);

/// The rigid-body keys of `node` (mass, cog, inertia, points) into `body` (case_rigid.cpp).
void readRigidBody(const CaseNode& node, Body& body);

/// The beam keys of `node` into body `index` of the build, with its elastic DOFs (case_beam.cpp).
void readBeamBody(const CaseNode& node, int index, CaseBuild& build);

/// The keys of a `fem_beam` body into body `index`, with its elastic DOFs (case_fem.cpp).
void readFemBody(const CaseNode& node, int index, CaseBuild& build);

/// The keys of an `fe_blade` body (6 × 6 sections on a curved reference axis, BeamDyn's description)
/// into body `index`, with its modal DOFs "<body> flap 1", … (case_blade6.cpp).
void readBlade6Body(const CaseNode& node, int index, CaseBuild& build);

/// After finalize(): adds to each FE body the geometric stiffness of the gravity loads it carries
/// (its own weight and that of the bodies attached at its nodes), at the initial DOF values.
void addFemGeometricStiffness(Model& model, const std::vector<std::shared_ptr<FemPending>>& pending);

/// The `shapes:` of beam `node` (properties `props`, body `index`), each adding its elastic DOF
/// (case_shapes.cpp): a list of shapes, or a map `{from: fem, …}` (case_fem_shapes.cpp).
std::vector<ShapePtr> readShapes(const CaseNode& node, const BeamProperties& props, int index, CaseBuild& build);

/// `shapes: {from: fem, …}`: the FE modes of the beam's properties as table shapes (case_fem_shapes.cpp).
std::vector<ShapePtr> readFemShapes(const CaseNode& shapes, const BeamProperties& props, int index, CaseBuild& build);

/// The FE settings of a `{from: fem}` shapes map (tip mass, axial loads, elements), modes not read.
fem::ModeShapeInput readFemShapeSettings(const CaseNode& shapes, const BeamProperties& props);

/// `inputs:`, `dofs:` settings and `loads:` (case_loads.cpp).
void readInputs(const CaseNode& list, CaseBuild& build);
void readDofSettings(const CaseNode& map, CaseBuild& build);
void readLoads(const CaseNode& list, CaseBuild& build);
/// The `dofs:` (frozen coordinates driven) of each input, once the DOFs exist (case_outputs.cpp).
void readInputTargets(const CaseNode& list, CaseBuild& build);
/// The model roles a case gives by its structure (case_outputs.cpp), for operating conditions:
/// blade k's pitch coordinate and pitch input = the input with `blade: k` that drives exactly one
/// frozen angular coordinate (every blade 1…N needs one, else the case has no pitch roles); the
/// collective pitch input = the first fixed-frame input that drives exactly those N coordinates.
/// The rotating coordinates (`rotating: true`) become the azimuth in finalize().
void assignRoles(CaseBuild& build);
/// `outputs:` (case_outputs.cpp).
void readOutputs(const CaseNode& list, CaseBuild& build);

/// `wind:` and `aero:` at the top level with the `aero:` of the beam bodies in `bodies` (case_aero.cpp):
/// the blade elements, airfoil polars, BEM options, steady wind, the `wind speed` input and its role,
/// and the rotor outputs. Call after the outputs are read (the names it adds must be free).
void readAerodynamics(const CaseNode& top, CaseBuild& build);

/// `generator:` (case_generator.cpp): ServoDyn's simple variable-speed torque law on the input named
/// `torque_input` (whose point loads apply it), the speed from the `dof` output `speed_output`; adds the
/// outputs GenTq and GenPwr. Call after the outputs and loads are read.
void readGenerator(const CaseNode& g, CaseBuild& build);

/// Re-throws an InputError from the core (buildBeamBody, shapes, finalize) prefixed with `w`.
[[noreturn]] void rethrowAt(const Where& w, const std::exception& e);

}  // namespace whirl
