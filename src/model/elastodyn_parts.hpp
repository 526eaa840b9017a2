#pragma once
/// \file
/// Internal pieces of buildElastoDynModel: each function adds the bodies and DOFs of one part of the
/// turbine to a model under construction (frames and units: see elastodyn_model.hpp). Body and DOF
/// indices are those of the unfinalized model; finalize() renumbers them.
#include <string>

#include "src/io/elastodyn_input.hpp"
#include "src/model/elastodyn_model.hpp"

namespace whirl::elastodyn {

/// The model under construction and where its data come from.
struct Builder {
  const io::ElastoDynInput& ed;
  const ElastoDynModelOptions& opt;
  Model model;

  /// Appends a body; returns its index.
  int addBody(Body body);
  /// Appends a DOF of `body` (joint coordinate or elastic coordinate `local`); frozen unless `active`.
  /// Returns its index in model.dofs.
  int addDof(const std::string& name, int body, DofKind kind, int local, bool active, double value = 0.0,
             double rate = 0.0);
  /// "ElastoDyn file:line: key: reason".
  std::string where(const char* key, const std::string& reason) const { return ed.source.where(key, reason); }
};

struct TowerParts {
  int body = -1;
  int top = -1;  ///< index of the tower-top point
};

/// The flexible tower (TwrNodes equal elements, FA/SS polynomial shapes, tuners, modal damping).
TowerParts addTower(Builder& b);

struct DrivetrainParts {
  int nacelle = -1, shaft = -1, generator = -1, hub = -1;  ///< bodies (shaft: low-speed side; generator: HSS)
  int yaw = -1, generator_azimuth = -1, drivetrain = -1;  ///< DOFs
};

/// Yaw bearing, nacelle (yaw joint), generator (generator azimuth) and hub (drivetrain twist).
DrivetrainParts addNacelleAndDrivetrain(Builder& b, const TowerParts& tower);

/// The three blades on the hub (pitch joints frozen at BlPitch, twisted ElastoDyn shapes, tip masses).
void addBlades(Builder& b, int hub);

/// Shorthand for an elementary rotation about a body axis (0 = x, 1 = y, 2 = z) by `angle` [rad].
Mat3 axisRotation(int axis, double angle);

}  // namespace whirl::elastodyn
