#pragma once
/// \file
/// The multibody model: a tree of bodies connected by joints, its generalized coordinates
/// (DOFs), named inputs and loads. Plain data, validated once by finalize(), immutable afterwards.
///
/// Frames: the inertial frame is "ground"; each body has a frame B whose pose follows from its
/// parent's frame through the attachment chain
///   parent point (elastic displacement P c and small rotations θ = Θ q_e, applied y, z, x)
///   → constant offset (attachment frame) → constant rotation → joint.
/// DOF order [Branlard2019, §3.1]: bodies by depth in the tree, for each body its joint coordinates
/// then its elastic coordinates.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "src/base/types.hpp"
#include "src/model/aero_model.hpp"
#include "src/model/body.hpp"
#include "src/model/body_state_space.hpp"
#include "src/model/mooring.hpp"
#include "src/model/output.hpp"
#include "src/model/rosco_controller.hpp"

namespace whirl {

enum class JointType { Fixed, Revolute, Prismatic, Free };
enum class DofKind { Joint, Elastic };

/// One generalized coordinate.
struct Dof {
  std::string name;
  DofKind kind = DofKind::Joint;
  int body = -1;          ///< body the coordinate belongs to
  int local = 0;          ///< index within the joint (0..5) or the body's elastic coordinates
  bool frozen = false;    ///< held at `value` (moving at `rate`): not a state of the linear model
  double value = 0.0;     ///< initial guess, or the frozen value [m or rad]
  double rate = 0.0;      ///< prescribed rate [m/s or rad/s]; e.g. the rotor speed of an azimuth
  bool rotating = false;  ///< an azimuth: its position is given, not solved for equilibrium
  int blade = -1;         ///< rotor blade (0-based) the coordinate belongs to, −1 = fixed frame (MBC)
};

/// One body and the joint that connects it to its parent.
struct Body {
  std::string name;
  int parent = -1;                   ///< index of the parent body, -1 = ground
  int parent_point = -1;             ///< point of the parent the joint sits at, -1 = parent origin
  Vec3 offset = Vec3::Zero();        ///< from the point to the joint, attachment frame [m]
  Mat3 rotation = Mat3::Identity();  ///< attachment frame → joint frame (columns: joint axes)
  JointType joint = JointType::Fixed;
  Vec3 axis = Vec3::UnitX();  ///< revolute/prismatic axis, joint frame (unit)
  /// Gear: a revolute joint driven by the revolute coordinate of body `joint_follows` (no coordinate
  /// of its own): angle = joint_ratio × q, e.g. a high-speed-shaft generator at the gearbox ratio.
  int joint_follows = -1;
  double joint_ratio = 1.0;
  int joint_dof = -1;    ///< index of the first joint coordinate (finalize)
  int elastic_dof = -1;  ///< index of the first elastic coordinate (finalize)
  BodyInertia inertia;
  ElasticProperties elastic;
  std::vector<BodyPoint> points;
  /// Stations where mode shapes are shown (modal/mode_shapes.hpp): material points like `points`, not
  /// used by the equations (the kinematics never evaluates them); a beam's run root to tip.
  std::vector<BodyPoint> nodes;
};

/// A frozen coordinate an input drives: q_dof = Dof::value + gain · u (e.g. blade pitch).
struct InputDofTarget {
  int dof = -1;
  double gain = 1.0;  ///< [rad or m per unit of the input]
};

/// A named input u (thrust, generator torque, blade pitch, ...): loads are scaled by it, and the
/// frozen coordinates it targets are offset by gain · u, so a prescribed motion (a pitch angle)
/// reaches the equations through the kinematics and ∂/∂u comes from AD like any other input.
struct Input {
  std::string name;
  double value = 0.0;                ///< operating-point value
  std::vector<InputDofTarget> dofs;  ///< frozen coordinates set by this input (may be empty)
  int blade = -1;                    ///< rotor blade (0-based) of an input in the rotating frame, −1 = fixed (MBC)
  std::string unit;                  ///< for exports, e.g. "N m", "rad" (may be empty)
};

/// Force and moment at a body point; if input >= 0 they are multiplied by u[input].
struct PointLoad {
  int body = -1;
  int point = -1;              ///< -1 = body origin
  Vec3 force = Vec3::Zero();   ///< [N]
  Vec3 moment = Vec3::Zero();  ///< [N m]
  bool body_frame = true;      ///< components in the body frame (follower) or ground frame
  int input = -1;
};

/// Generalized force on one coordinate; if input >= 0 multiplied by u[input].
struct DofLoad {
  int dof = -1;
  double value = 0.0;
  int input = -1;
};

/// Linear spring and damper on one coordinate: −k (q − q0) − c q̇.
/// A piecewise law (a teeter stop acting beyond its angle) is linearized on one piece: q_min … q_max
/// [m or rad] is where that piece holds, and an operating point outside it is not valid
/// (linearize/point_validity.hpp; `law` names the piece for that message).
struct DofSpring {
  int dof = -1;
  double k = 0.0, c = 0.0, q0 = 0.0;
  double q_min = -std::numeric_limits<double>::infinity();
  double q_max = std::numeric_limits<double>::infinity();
  std::string law = {};  ///< e.g. "teeter soft stop (TeetSStP = 5 deg) not reached"; empty for a linear law
};

/// Constant 6×6 stiffness, damping and added mass on the six coordinates of a free joint
/// (surge, sway, heave, roll, pitch, yaw): −K (x − x0) − C ẋ − A ẍ, e.g. hydrostatics, mooring.
struct BodyMatrices {
  int body = -1;
  Eigen::Matrix<double, 6, 6> K = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> x0 = Eigen::Matrix<double, 6, 1>::Zero();
};

/// One step of the kinematic chain from a parent frame to a child frame (built by finalize).
struct ChainStep {
  enum Kind { PointTranslate, ElasticRotate, ConstTranslate, ConstRotate, AxisRotate, AxisTranslate };
  Kind kind = ConstTranslate;
  int body = -1;            ///< PointTranslate/ElasticRotate: the parent body
  int point = -1;           ///< PointTranslate/ElasticRotate: the parent point
  int axis_index = 0;       ///< ElasticRotate: 0, 1, 2 for body x, y, z
  Vec3 vec = Vec3::Zero();  ///< ConstTranslate: offset; Axis*: unit axis
  Mat3 rot = Mat3::Identity();
  int dof = -1;        ///< Axis*: the joint coordinate
  double ratio = 1.0;  ///< AxisRotate: angle = ratio × q (gears)
};

/// Which coordinates and inputs play which part in an operating condition
/// (src/model/operating_condition.hpp), so that rotor speed, pitch, wind speed, … are applied by
/// role, never by matching names. Filled by the builders (ElastoDyn, YAML cases) with the indices of
/// the model they build; finalize() renumbers the DOF indices, fills `azimuth` and checks them all.
/// −1 / empty = the model has no such coordinate or input.
struct ModelRoles {
  std::vector<int> azimuth;             ///< the rotating coordinates (Dof::rotating; set by finalize)
  std::vector<int> blade_pitch;         ///< pitch coordinate of each blade (frozen joint, [rad]), index = blade
  int collective_pitch_input = -1;      ///< input adding to every blade's pitch [rad]
  std::vector<int> blade_pitch_inputs;  ///< per blade: the input adding to that blade's pitch [rad] (−1: none)
  int wind_speed_input = -1;            ///< hub-height wind speed [m/s] (none before the aerodynamics)
  int generator_torque_input = -1;      ///< generator torque [N m, high-speed shaft]
  int yaw_dof = -1;                     ///< nacelle yaw coordinate [rad]
  /// Teeter of a 2-bladed rotor [rad]: tilts the rotor about an axis across the shaft and blade 1,
  /// blade 1 downwind for a positive angle; seen from the fixed frame like a differential blade
  /// coordinate (+ on blade 1, − on blade 2; modal/floquet.hpp).
  int teeter_dof = -1;
};

struct Model {
  std::string name;
  Vec3 gravity = Vec3(0, 0, -9.80665);  ///< ground frame [m/s²]
  std::vector<Body> bodies;             ///< parents before children (finalize sorts)
  std::vector<Dof> dofs;
  std::vector<Input> inputs;
  std::vector<PointLoad> point_loads;
  std::vector<DofLoad> dof_loads;
  std::vector<DofSpring> springs;
  std::vector<BodyMatrices> body_matrices;
  std::vector<BodyStateSpace> body_states;  ///< first-order states on free joints (linear model only)
  /// The deck's ROSCO controller (ServoDyn VSContrl = 5 naming a DISCON.IN), read with the deck and its
  /// --set overrides; the commands trim and close the loop with it. Absent otherwise (a YAML case).
  std::optional<RoscoController> deck_controller;
  std::vector<MooringLine> mooring;  ///< quasi-static catenary lines (mooring.hpp)
  AeroModel aero;                    ///< blade elements, polars, wind (empty: no aerodynamics)
  GeneratorTorqueLaw generator;      ///< generator torque against speed (inactive: torque = its input)
  std::vector<Output> outputs;       ///< measured quantities y = h(q, q̇, q̈) (output.hpp)
  ModelRoles roles;                  ///< what plays rotor azimuth, pitch, wind speed, … (above)

  // Derived by finalize().
  std::vector<std::vector<ChainStep>> chains;  ///< per body
  std::vector<std::vector<int>> support;       ///< per body: DOFs its frame depends on (sorted)

  int ndof() const { return static_cast<int>(dofs.size()); }
  int ninput() const { return static_cast<int>(inputs.size()); }
  std::optional<int> findBody(const std::string& name) const;
  std::optional<int> findDof(const std::string& name) const;
  std::optional<int> findInput(const std::string& name) const;
  std::optional<int> findOutput(const std::string& name) const;
  int noutput() const { return static_cast<int>(outputs.size()); }
  /// Indices of the coordinates that are states of the linear model (not frozen).
  std::vector<int> activeDofs() const;
};

/// Number of coordinates a joint type carries.
int jointDofCount(JointType t);

/// Orders bodies parents-first (by depth), numbers the DOFs [Branlard2019, §3.1], builds the chains and
/// checks the data: names unique, parents and points exist, masses ≥ 0, inertia positive
/// semi-definite, everything finite. Bodies must carry their DOFs in `dofs` with `body`/`local`
/// set; DOFs are renumbered (and with them the DOF indices of `roles`, whose `azimuth` becomes the
/// rotating coordinates). Names and units must be printable text on one line (src/base/text.hpp).
/// Throws InputError naming the body/DOF and the reason.
void finalize(Model& model);

/// Part of finalize: renumbers the bodies and DOFs the aerodynamic model and the generator torque law
/// refer to (old → new index) and checks them.
void finalizeAero(Model& model, const std::vector<int>& new_body, const std::vector<int>& new_dof);

/// \throws InputError "<what>: the model has no active degree of freedom (all frozen or none defined):
///         nothing to linearize" when every coordinate is frozen or there is none. A finalized model
///         may be so (a rigid structure is a valid model); linearizing it is not.
void requireActiveDof(const Model& model, const std::string& what);

}  // namespace whirl
