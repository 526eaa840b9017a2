// MATLAB .mat writer (matio, level 5) for state-space exports; layout in README.md.
#include <matio.h>

#include <cmath>
#include <limits>
#include <memory>

#include "src/base/error.hpp"
#include "src/writers/lin_channels.hpp"
#include "src/writers/state_space_files.hpp"

namespace whirl {
namespace {

using Var = matvar_t*;

Var doubles(const char* name, const double* data, std::vector<size_t> dims) {
  static const double none = 0.0;
  Var v = Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, static_cast<int>(dims.size()), dims.data(),
                        const_cast<double*>(data ? data : &none), 0);
  if (!v) throw ComputeError(std::string(".mat: cannot create variable ") + (name ? name : "(cell)"));
  return v;
}

Var matrix(const char* name, const MatX& M) {
  return doubles(name, M.data(), {static_cast<size_t>(M.rows()), static_cast<size_t>(M.cols())});
}

Var scalar(const char* name, double v) { return doubles(name, &v, {1, 1}); }

Var row(const char* name, const std::vector<double>& v) { return doubles(name, v.data(), {1, v.size()}); }

Var column(const char* name, const std::vector<double>& v) { return doubles(name, v.data(), {v.size(), 1}); }

/// A row of 1-based indices as 32-bit integers: numpy indexes with them as loaded (ROSCO's
/// LinearTurbineModel takes `indInps[0] - 1` as an index array; doubles would not index).
Var indices(const char* name, std::vector<int32_t> v) {
  size_t dims[2] = {1, v.size()};
  static int32_t none = 0;
  Var m = Mat_VarCreate(name, MAT_C_INT32, MAT_T_INT32, 2, dims, v.empty() ? &none : v.data(), 0);
  if (!m) throw ComputeError(std::string(".mat: cannot create variable ") + name);
  return m;
}

Var text(const char* name, const std::string& s) {
  std::string ascii = s;
  for (char& c : ascii)
    if (static_cast<unsigned char>(c) > 127 || static_cast<unsigned char>(c) < 32 || c == 127)
      c = '?';  // MATLAB char from bytes: printable ASCII, one line
  size_t dims[2] = {ascii.empty() ? 0u : 1u, ascii.size()};
  Var v = Mat_VarCreate(name, MAT_C_CHAR, MAT_T_UINT8, 2, dims, ascii.empty() ? nullptr : ascii.data(), 0);
  if (!v) throw ComputeError(".mat: cannot create a string");
  return v;
}

/// rows × cols cell array (column-major) of variables (each created with a null name).
Var cells(const char* name, std::vector<Var> items, size_t rows, size_t cols) {
  size_t dims[2] = {rows, cols};
  Var c = Mat_VarCreate(name, MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0);
  if (!c) throw ComputeError(std::string(".mat: cannot create cell array ") + name);
  for (size_t i = 0; i < items.size(); ++i) Mat_VarSetCell(c, static_cast<int>(i), items[i]);
  return c;
}

Var strings(const char* name, const std::vector<std::string>& s) {
  std::vector<Var> items;
  for (const auto& x : s) items.push_back(text(nullptr, x));
  return cells(name, items, s.size(), 1);
}

std::vector<double> ops(const std::vector<StateSpaceVariable>& v) {
  std::vector<double> o;
  for (const auto& x : v) o.push_back(x.op);
  return o;
}

std::vector<std::string> names(const std::vector<StateSpaceVariable>& v) {
  std::vector<std::string> o;
  for (const auto& x : v) o.push_back(x.name);
  return o;
}

std::vector<std::string> units(const std::vector<StateSpaceVariable>& v) {
  std::vector<std::string> o;
  for (const auto& x : v) o.push_back(x.unit);
  return o;
}

// OpenFAST's channel texts ("ED GenSpeed", "IfW Extended input: …"), without units: the .mat keeps
// SI units (`*_units`), a `.lin` file OpenFAST's (src/writers/lin_channels.hpp).
std::vector<std::string> descriptions(const std::vector<StateSpaceVariable>& v,
                                      LinChannel (*channel)(const StateSpaceVariable&)) {
  std::vector<std::string> o;
  for (const auto& x : v) o.push_back(channel(x).text);
  return o;
}

std::vector<double> rotating(const std::vector<StateSpaceVariable>& v) {
  std::vector<double> o;
  for (const auto& x : v) o.push_back(x.blade >= 0 ? x.blade + 1 : 0);
  return o;
}

/// n1 × n2 × (number of models) array of one matrix of every model.
Var stack(const char* name, const std::vector<StateSpaceModel>& ms, MatX StateSpaceModel::*field) {
  const MatX& f = ms.front().*field;
  std::vector<double> data;
  for (const auto& m : ms) data.insert(data.end(), (m.*field).data(), (m.*field).data() + (m.*field).size());
  return doubles(name, data.data(), {static_cast<size_t>(f.rows()), static_cast<size_t>(f.cols()), ms.size()});
}

class MatFile {
 public:
  explicit MatFile(const std::string& path) : path_(path) {
    mat_ = Mat_CreateVer(path.c_str(), "whirl " WHIRL_VERSION " state-space export", MAT_FT_MAT5);
    if (!mat_) throw InputError(path + ": cannot create the .mat file");
  }
  ~MatFile() {
    if (mat_) Mat_Close(mat_);
  }
  void put(Var v) {
    const int err = Mat_VarWrite(mat_, v, MAT_COMPRESSION_NONE);
    Mat_VarFree(v);
    if (err) throw InputError(path_ + ": write failed (disk full?)");
  }
  void close() {
    if (Mat_Close(mat_) != 0) throw InputError(path_ + ": write failed on close");
    mat_ = nullptr;
  }

 private:
  std::string path_;
  mat_t* mat_ = nullptr;
};

void names(MatFile& f, const StateSpaceModel& m, const std::string& suffix) {
  f.put(strings(("x_names" + suffix).c_str(), names(m.x)));
  f.put(strings(("u_names" + suffix).c_str(), names(m.u)));
  f.put(strings(("y_names" + suffix).c_str(), names(m.y)));
  f.put(strings(("x_units" + suffix).c_str(), units(m.x)));
  f.put(strings(("u_units" + suffix).c_str(), units(m.u)));
  f.put(strings(("y_units" + suffix).c_str(), units(m.y)));
  f.put(column(("x_rotframe" + suffix).c_str(), rotating(m.x)));
  f.put(column(("u_rotframe" + suffix).c_str(), rotating(m.u)));
  f.put(column(("y_rotframe" + suffix).c_str(), rotating(m.y)));
  std::vector<std::string> xd;
  const bool ed = elastoDynStates(m.x);
  for (const auto& v : m.x) xd.push_back(linStateDescription(v, m.x, ed));
  f.put(strings(("x_desc" + suffix).c_str(), xd));
  f.put(strings(("u_desc" + suffix).c_str(), descriptions(m.u, linInputChannel)));
  f.put(strings(("y_desc" + suffix).c_str(), descriptions(m.y, linOutputChannel)));
}

double orNaN(const std::optional<double>& v) { return v.value_or(std::numeric_limits<double>::quiet_NaN()); }

// The point's wind speed: the schedule's, else the model's wind input, else NaN (no aerodynamics).
double windOf(const ExportPoint& p) {
  if (p.wind_speed) return *p.wind_speed;
  for (const auto& v : p.model.u)
    if (v.name == "wind speed") return v.op;
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

// One layout for one or many operating points, ROSCO's (LinearTurbineModel(fromMat=True) in ROSCO's
// rosco/toolbox/linear/linear_models.py): 1 × n cell arrays A, B, C, D, x_ops, u_ops, y_ops; the first
// row of every u_ops column is the wind speed ROSCO schedules over (u_ops[0]), the model's inputs
// follow and indInps / indOuts (1-based) pick B's and C's channels out of u_ops / y_ops. A single point
// is n = 1 (a separate layout made ROSCO fail with KeyError: 'u_ops', issue 41).
void writeStateSpaceMat(const StateSpaceExport& e, const std::string& path) {
  if (e.points.empty()) throw InputError(path + ": nothing to export");
  MatFile f(path);
  const StateSpaceModel& first = e.points.front().model;
  const size_t n = e.points.size();
  std::vector<Var> A, B, C, D, x, xdot, u, y, Aaz, Baz, Caz, Daz, psi;
  std::vector<double> wind, rpm, pitch, omega;
  for (const ExportPoint& p : e.points) {
    const StateSpaceModel& m = p.model;
    if (m.A.rows() != first.A.rows() || m.B.cols() != first.B.cols() || m.C.rows() != first.C.rows())
      throw ComputeError("export: the operating points have different numbers of states, inputs or outputs");
    A.push_back(matrix(nullptr, m.A));
    B.push_back(matrix(nullptr, m.B));
    C.push_back(matrix(nullptr, m.C));
    D.push_back(matrix(nullptr, m.D));
    x.push_back(column(nullptr, ops(m.x)));
    xdot.push_back(column(nullptr, std::vector<double>(m.xdot_op.data(), m.xdot_op.data() + m.xdot_op.size())));
    std::vector<double> uo{windOf(p)};
    for (double v : ops(m.u)) uo.push_back(v);
    u.push_back(column(nullptr, uo));
    y.push_back(column(nullptr, ops(m.y)));
    wind.push_back(windOf(p));
    rpm.push_back(p.rpm);
    pitch.push_back(orNaN(p.pitch_deg));
    omega.push_back(m.rotor_speed);
    if (!p.azimuths.empty()) {
      Aaz.push_back(stack(nullptr, p.azimuths, &StateSpaceModel::A));
      Baz.push_back(stack(nullptr, p.azimuths, &StateSpaceModel::B));
      Caz.push_back(stack(nullptr, p.azimuths, &StateSpaceModel::C));
      Daz.push_back(stack(nullptr, p.azimuths, &StateSpaceModel::D));
      std::vector<double> az;
      for (const auto& m2 : p.azimuths) az.push_back(m2.azimuth);
      psi.push_back(row(nullptr, az));
    }
  }
  f.put(cells("A", A, 1, n));
  f.put(cells("B", B, 1, n));
  f.put(cells("C", C, 1, n));
  f.put(cells("D", D, 1, n));
  f.put(cells("x_ops", x, 1, n));
  f.put(cells("xdot_ops", xdot, 1, n));
  f.put(cells("u_ops", u, 1, n));
  f.put(cells("y_ops", y, 1, n));
  std::vector<int32_t> ind_u, ind_y;
  for (size_t i = 0; i < first.u.size(); ++i) ind_u.push_back(static_cast<int32_t>(i + 2));
  for (size_t i = 0; i < first.y.size(); ++i) ind_y.push_back(static_cast<int32_t>(i + 1));
  f.put(indices("indInps", ind_u));
  f.put(indices("indOuts", ind_y));
  f.put(row("WindSpeed", wind));
  f.put(row("RotSpeed_rpm", rpm));
  f.put(row("RotSpeed", omega));
  f.put(row("BldPitch_deg", pitch));
  f.put(scalar("multiblade", first.multiblade ? 1.0 : 0.0));
  names(f, first, "");
  if (Aaz.size() == n) {
    f.put(cells("A_az", Aaz, 1, n));
    f.put(cells("B_az", Baz, 1, n));
    f.put(cells("C_az", Caz, 1, n));
    f.put(cells("D_az", Daz, 1, n));
    f.put(cells("azimuths", psi, 1, n));
    names(f, e.points.front().azimuths.front(), "_az");
  } else {
    for (auto* list : {&Aaz, &Baz, &Caz, &Daz, &psi})
      for (Var v : *list) Mat_VarFree(v);
  }
  f.put(text("source", e.source));
  f.put(text("model", e.model_name));
  f.close();
}

}  // namespace whirl
