#include "src/io/case/case_reader.hpp"

#include "src/base/error.hpp"

namespace whirl {

void CaseBuild::addDof(const std::string& name, DofKind kind, int body, int local, const Where& w, bool angular) {
  Dof d;
  d.name = name;
  d.kind = kind;
  d.body = body;
  d.local = local;
  builder.addDof(d, w);
  dof_angular.push_back(angular);
}

void rethrowAt(const Where& w, const std::exception& e) { throw InputError(where(w.file, w.line, "", e.what())); }

}  // namespace whirl
