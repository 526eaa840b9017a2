// NREL 5MW full-system natural frequencies against the FAST column of [Jonkman2009, Table 9-1]
// (NREL/TP-500-38060; values and their sources in cases/nrel5mw/table9_1.csv):
// land-based turbine, parked rotor (RotSpeed = 0), generator locked (GenDOF = False), gravity on,
// ServoDyn's yaw spring (YawSpr 9.02832e9 N m/rad, YawDamp 1.916e7 N m s/rad) present.
//
// The model is the ElastoDyn-equivalent turbine built from whirl's bodies and joints
// (src/turbine/elastodyn_model.hpp) from the OpenFAST inputs in cases/nrel5mw, linearized about its
// static equilibrium under gravity (blade 1 up). Modes are matched to the reference rows by content:
// the dominant DOF group by energy share and, for blade modes, the phase pattern of the three blades
// (tests/validation/blade_mode_pattern.hpp); the asymmetric-flap pairs, whose pitch/yaw labels are
// uncertain in the sources, are compared as sets (both sorted by frequency).
//
// Tolerance 1.5 % on every mode. Results (whirl, this test; FAST, Table 9-1; whirl − FAST):
//   1st tower fore-aft                      0.3244  0.3240  +0.14 %
//   1st tower side-to-side                  0.3139  0.3120  +0.62 %
//   1st drivetrain torsion                  0.6196  0.6205  −0.15 %
//   1st blade asymmetric flapwise (set)     0.6656  0.6664  −0.11 %   (whirl: yaw-type)
//                                           0.6667  0.6675  −0.12 %   (whirl: pitch-type)
//   1st blade collective flap               0.6991  0.6993  −0.03 %
//   1st blade asymmetric edgewise pitch     1.0799  1.0793  +0.06 %
//   1st blade asymmetric edgewise yaw       1.0909  1.0898  +0.10 %
//   2nd blade asymmetric flapwise (set)     1.9110  1.9223  −0.59 %   (whirl: pitch-type)
//                                           1.9229  1.9337  −0.56 %   (whirl: yaw-type)
//   2nd blade collective flap               2.0073  2.0205  −0.65 %
//   2nd tower fore-aft                      2.9159  2.9003  +0.54 %
//   2nd tower side-to-side                  2.9537  2.9361  +0.60 %
// (also in cases/nrel5mw/README.md). whirl's remaining modes: second drivetrain/collective edge 3.684 Hz,
// yaw 6.143 Hz. The blade modes depend on the blade discretization (BldNodes = 60 instead of 17 raises
// them by 0.7–1.6 %): FAST 2009 integrated the blades on AeroDyn's 17 unequal elements (rotor mass
// 110,000 kg, for which AdjBlMs was tuned), today's ElastoDyn and whirl on BldNodes = 17 equal ones
// (109,390 kg), which is of the size of the −0.6 % on the second flap modes. The tower side-to-side and
// second tower modes (+0.5 to +0.6 %) hardly depend on the discretization (BldNodes = 60 or
// TwrNodes = 80 move them by < 0.2 %); their offset from FAST 2009 is not explained here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "linearize/linearize.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "tests/validation/blade_mode_pattern.hpp"

namespace whirl {
namespace {

struct RefRow {
  std::string mode;
  double freq_hz = 0;
};

// The first two fields of each row (mode names hold no commas or quotes).
std::vector<RefRow> readReference(const std::string& path) {
  std::ifstream in(path);
  if (!in) ADD_FAILURE() << "cannot open " << path;
  std::vector<RefRow> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto c1 = line.find(','), c2 = line.find(',', c1 + 1);
    rows.push_back({line.substr(0, c1), std::stod(line.substr(c1 + 1, c2 - c1 - 1))});
  }
  return rows;
}

// Reference row name → the whirl mode label prefix it corresponds to, and which occurrence (1-based).
struct Key {
  std::string prefix;
  int nth = 1;
  bool set = false;  // pitch/yaw label uncertain: compare the pair as a set
};

Key keyOf(const std::string& ref) {
  const bool second = ref.rfind("2nd", 0) == 0;
  const std::string flap = second ? "flap 2" : "flap 1";
  if (ref.find("tower fore-aft") != std::string::npos) return {"tower FA", second ? 2 : 1};
  if (ref.find("tower side-to-side") != std::string::npos) return {"tower SS", second ? 2 : 1};
  if (ref.find("drivetrain") != std::string::npos) return {"drivetrain", 1};
  if (ref.find("collective flap") != std::string::npos) return {flap + " collective", 1};
  if (ref.find("asymmetric flapwise") != std::string::npos) return {flap + " asymmetric", 1, true};
  if (ref.find("asymmetric edgewise pitch") != std::string::npos) return {"edge 1 asymmetric pitch", 1};
  if (ref.find("asymmetric edgewise yaw") != std::string::npos) return {"edge 1 asymmetric yaw", 1};
  ADD_FAILURE() << "reference row not understood: " << ref;
  return {};
}

struct ModelModes {
  std::vector<Mode> modes;
  std::vector<std::string> labels;
};

ModelModes parkedNrel5mwModes(const std::vector<std::string>& extra = {}) {
  const std::string fst = std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/Main_Onshore.fst";
  std::vector<std::string> sets = {"RotSpeed=0", "GenDOF=False"};
  sets.insert(sets.end(), extra.begin(), extra.end());
  const Model m = readElastoDynModel(fst, sets);
  const OperatingPoint op = solveOperatingPoint(m, initialPoint(m));
  const LinearModel lin = linearize(m, op);
  EXPECT_LT(lin.residual.lpNorm<Eigen::Infinity>(), 1e-3) << "not an equilibrium";
  const double psi = op.q(*m.findDof("generator azimuth")) + op.q(*m.findDof("drivetrain"));
  ModelModes out;
  out.modes = computeModes(lin.M, lin.C, lin.K, lin.dof_names);
  for (const Mode& md : out.modes) out.labels.push_back(test::classify(md, lin.dof_names, psi).label());
  return out;
}

// Every Table 9-1 row against the matching whirl mode of `mm`, within tolerance(row, key prefix) [relative].
// Returns the whirl frequency of each row (pairs: the set, sorted) by row name.
template <class Tol>
std::map<std::string, double> compareWithTable91(const ModelModes& mm, Tol&& tolerance) {
  std::map<std::string, double> out;
  const std::vector<RefRow> ref = readReference(std::string(WHIRL_SOURCE_DIR) + "/cases/nrel5mw/table9_1.csv");
  EXPECT_EQ(ref.size(), 13u);
  for (std::size_t i = 0; i < mm.modes.size(); ++i)
    std::printf("whirl mode %2zu  %8.4f Hz  %-28s (%s)\n", i + 1, mm.modes[i].freq_hz, mm.labels[i].c_str(),
                mm.modes[i].name.c_str());

  // The whirl modes of each key, lowest first.
  auto modesOf = [&](const std::string& prefix) {
    std::vector<double> f;
    for (std::size_t i = 0; i < mm.modes.size(); ++i)
      if (mm.labels[i].rfind(prefix, 0) == 0) f.push_back(mm.modes[i].freq_hz);
    return f;
  };
  std::map<std::string, std::vector<double>> set_refs;
  std::printf("%-46s %8s %8s %8s\n", "mode (Table 9-1)", "FAST", "whirl", "diff");
  for (const RefRow& r : ref) {
    const Key k = keyOf(r.mode);
    const std::vector<double> f = modesOf(k.prefix);
    if (k.set) {
      set_refs[k.prefix].push_back(r.freq_hz);
      continue;
    }
    if (static_cast<int>(f.size()) < k.nth) {
      ADD_FAILURE() << "no whirl mode for " << r.mode;
      continue;
    }
    const double w = f[static_cast<std::size_t>(k.nth - 1)], d = (w - r.freq_hz) / r.freq_hz;
    std::printf("%-46s %8.4f %8.4f %+7.2f%%\n", r.mode.c_str(), r.freq_hz, w, 100 * d);
    EXPECT_NEAR(w, r.freq_hz, tolerance(r.mode) * r.freq_hz) << r.mode;
    out[r.mode] = w;
  }
  for (auto& [prefix, fr] : set_refs) {
    std::vector<double> f = modesOf(prefix);
    if (f.size() < fr.size()) {
      ADD_FAILURE() << "not enough whirl modes for " << prefix;
      continue;
    }
    f.resize(fr.size());
    std::sort(fr.begin(), fr.end());
    for (std::size_t i = 0; i < fr.size(); ++i) {
      std::printf("%-46s %8.4f %8.4f %+7.2f%%\n", (prefix + " (pair, as a set)").c_str(), fr[i], f[i],
                  100 * (f[i] - fr[i]) / fr[i]);
      EXPECT_NEAR(f[i], fr[i], tolerance(prefix) * fr[i]) << prefix << " #" << i + 1;
      out[prefix + " #" + std::to_string(i + 1)] = f[i];
    }
  }
  return out;
}

TEST(Nrel5mwTable91, EveryModeWithinOnePointFivePercentOfFast) {
  compareWithTable91(parkedNrel5mwModes(), [](const std::string&) { return 0.015; });
}

// The same turbine with the tower and blade polynomials replaced by FE modes of the same properties
// (--set shapes=fem; cases/nrel5mw/README.md, "With FE shapes"). FAST's numbers come from the
// polynomials, so two groups of modes move away from them by more than 1.5 %, both downwards, where the
// FE basis is better than the polynomials: the first tower fore-aft mode (0.3140 Hz, −3.09 %; the
// tower alone with its top mass has its exact first mode at 0.3200 Hz, below the polynomial turbine's
// 0.3244 Hz) and the second flap modes (1.8774, 1.8816, 1.9588 Hz: −2.33, −2.69, −3.05 %; ElastoDyn's
// twisted flap 2 shape has MAC 0.956 with the coupled FE mode). Those get 3.5 % and must lie below
// the polynomial model's values; every other mode keeps the 1.5 % of the polynomial model (measured
// within −0.40 … +0.20 %).
TEST(Nrel5mwTable91, FemShapesAgainstFastAndThePolynomialModel) {
  auto wide = [](const std::string& row) {
    return row == "1st tower fore-aft" || row.find("2nd blade") == 0 || row.rfind("flap 2", 0) == 0;
  };
  const auto fem = compareWithTable91(parkedNrel5mwModes({"shapes=fem"}),
                                      [&](const std::string& row) { return wide(row) ? 0.035 : 0.015; });
  std::map<std::string, double> poly;
  {
    ::testing::ScopedTrace t(__FILE__, __LINE__, "polynomial model (already checked above)");
    poly = compareWithTable91(parkedNrel5mwModes(), [](const std::string&) { return 0.015; });
  }
  for (const auto& [row, f] : fem) {
    if (wide(row)) {
      EXPECT_LT(f, poly.at(row)) << row;
    }
  }
}

}  // namespace
}  // namespace whirl
