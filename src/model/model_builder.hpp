#pragma once
/// \file
/// The one builder of a Model (used by the YAML case reader and the ElastoDyn turbine builder): it
/// owns the model under construction, appends bodies and DOFs remembering where each was written,
/// rejects an empty or repeated DOF name, looks parts up by name (failing with the list of the names
/// there are) and hands over the finalized model. Indices are those of the unfinalized model;
/// finalize() renumbers them.
#include <string>
#include <vector>

#include "src/base/error.hpp"
#include "src/model/model.hpp"

namespace whirl {

class ModelBuilder {
 public:
  /// The model under construction (its name, gravity, inputs, loads, outputs … are set directly).
  Model& model() { return model_; }
  const Model& model() const { return model_; }

  /// Appends a body written at `at` (for messages); returns its index.
  int addBody(Body body, const Where& at = {});
  /// Appends a DOF; returns its index in model().dofs.
  /// \throws InputError at `at` when its name is empty or already used ("… already used at line N",
  ///         the line where the first one was written, when known).
  int addDof(Dof dof, const Where& at = {});

  /// Where body `k` / DOF `k` was written (as given to addBody / addDof).
  const Where& bodyWhere(int k) const { return body_where_[k]; }
  const Where& dofWhere(int k) const { return dof_where_[k]; }

  /// Index of a DOF by name; fails at `at` listing the DOFs when there is none.
  int dofIndex(const std::string& name, const Where& at) const;
  /// Index of a body by name; fails at `at` listing the bodies when there is none.
  int bodyIndex(const std::string& name, const Where& at) const;
  /// Index of an input by name; fails at `at` listing the inputs when there is none.
  int inputIndex(const std::string& name, const Where& at) const;
  /// Index of a point of body `body` by name; fails at `at` listing its points when there is none.
  int pointIndex(int body, const std::string& name, const Where& at) const;

  /// finalize() (model.hpp) and the finished, immutable model; the builder is spent.
  /// \throws InputError from finalize.
  Model finish() &&;

 private:
  Model model_;
  std::vector<Where> body_where_;
  std::vector<Where> dof_where_;
};

}  // namespace whirl
