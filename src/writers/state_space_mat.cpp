// MATLAB .mat writer (matio, level 5) for state-space exports; layout in README.md.
#include <matio.h>

#include <cmath>
#include <limits>
#include <memory>

#include "src/writers/state_space_files.hpp"
#include "src/model/error.hpp"

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

/// n × (number of models) operating points.
Var stackOps(const char* name, const std::vector<StateSpaceModel>& ms,
             std::vector<StateSpaceVariable> StateSpaceModel::*field) {
  std::vector<double> data;
  for (const auto& m : ms) {
    const auto o = ops(m.*field);
    data.insert(data.end(), o.begin(), o.end());
  }
  return doubles(name, data.data(), {(ms.front().*field).size(), ms.size()});
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
}

void perAzimuth(MatFile& f, const std::vector<StateSpaceModel>& az) {
  f.put(stack("A_az", az, &StateSpaceModel::A));
  f.put(stack("B_az", az, &StateSpaceModel::B));
  f.put(stack("C_az", az, &StateSpaceModel::C));
  f.put(stack("D_az", az, &StateSpaceModel::D));
  f.put(stackOps("x_op_az", az, &StateSpaceModel::x));
  f.put(stackOps("u_op_az", az, &StateSpaceModel::u));
  f.put(stackOps("y_op_az", az, &StateSpaceModel::y));
  std::vector<double> psi;
  for (const auto& m : az) psi.push_back(m.azimuth);
  f.put(row("azimuths", psi));
  names(f, az.front(), "_az");
}

double orNaN(const std::optional<double>& v) { return v.value_or(std::numeric_limits<double>::quiet_NaN()); }

}  // namespace

void writeStateSpaceMat(const StateSpaceExport& e, const std::string& path) {
  if (e.points.empty()) throw InputError(path + ": nothing to export");
  MatFile f(path);
  const StateSpaceModel& first = e.points.front().model;
  if (e.points.size() == 1) {
    const ExportPoint& p = e.points.front();
    const StateSpaceModel& m = p.model;
    f.put(matrix("A", m.A));
    f.put(matrix("B", m.B));
    f.put(matrix("C", m.C));
    f.put(matrix("D", m.D));
    f.put(column("x_op", ops(m.x)));
    f.put(column("u_op", ops(m.u)));
    f.put(column("y_op", ops(m.y)));
    f.put(column("xdot_op", std::vector<double>(m.xdot_op.data(), m.xdot_op.data() + m.xdot_op.size())));
    f.put(scalar("rotor_speed", m.rotor_speed));
    f.put(scalar("rpm", p.rpm));
    f.put(scalar("wind_speed", orNaN(p.wind_speed)));
    f.put(scalar("pitch_deg", orNaN(p.pitch_deg)));
    f.put(scalar("multiblade", m.multiblade ? 1.0 : 0.0));
    names(f, m, "");
    if (!p.azimuths.empty()) perAzimuth(f, p.azimuths);
  } else {
    // ROSCO's linear-model layout (LinearTurbineModel(fromMat=True)): 1 × n cell arrays.
    const size_t n = e.points.size();
    std::vector<Var> A, B, C, D, x, u, y, Aaz, Baz, Caz, Daz, psi;
    std::vector<double> wind, rpm, pitch;
    for (const ExportPoint& p : e.points) {
      const StateSpaceModel& m = p.model;
      if (m.A.rows() != first.A.rows() || m.B.cols() != first.B.cols() || m.C.rows() != first.C.rows())
        throw ComputeError("export: the operating points have different numbers of states, inputs or outputs");
      A.push_back(matrix(nullptr, m.A));
      B.push_back(matrix(nullptr, m.B));
      C.push_back(matrix(nullptr, m.C));
      D.push_back(matrix(nullptr, m.D));
      x.push_back(column(nullptr, ops(m.x)));
      std::vector<double> uo{orNaN(p.wind_speed)};  // ROSCO schedules over the first row of u_ops
      for (double v : ops(m.u)) uo.push_back(v);
      u.push_back(column(nullptr, uo));
      y.push_back(column(nullptr, ops(m.y)));
      wind.push_back(orNaN(p.wind_speed));
      rpm.push_back(p.rpm);
      pitch.push_back(orNaN(p.pitch_deg));
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
    f.put(cells("u_ops", u, 1, n));
    f.put(cells("y_ops", y, 1, n));
    std::vector<double> ind_u, ind_y;
    for (size_t i = 0; i < first.u.size(); ++i) ind_u.push_back(static_cast<double>(i + 2));
    for (size_t i = 0; i < first.y.size(); ++i) ind_y.push_back(static_cast<double>(i + 1));
    f.put(row("indInps", ind_u));
    f.put(row("indOuts", ind_y));
    f.put(row("WindSpeed", wind));
    f.put(row("RotSpeed_rpm", rpm));
    f.put(row("BldPitch_deg", pitch));
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
  }
  f.put(text("source", e.source));
  f.put(text("model", e.model_name));
  f.close();
}

}  // namespace whirl
