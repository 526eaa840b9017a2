// modal/campbell_diagram.hpp: the instability summary `whirl campbell` warns with, and the title.
#include <gtest/gtest.h>

#include "modal/campbell_diagram.hpp"

namespace whirl {
namespace {

Mode mode(double zeta, bool rigid = false) {
  Mode m;
  m.freq_hz = 1;
  m.damping_ratio = zeta;
  m.rigid_body = rigid;
  return m;
}

TEST(CampbellDiagram, LineInstabilitiesCountNegativeDampingAndFindTheLowest) {
  CampbellDiagram d;
  for (double z : {0.01, -0.02, -0.05, 0.0}) {
    CampbellPoint p;
    p.modes = {mode(z), mode(-0.3, true), mode(0.02)};
    d.points.push_back(p);
  }
  d.lines = {{"edge 1 BW", {0, 0, 0, 0}}, {"rigid", {1, 1, -1, 1}}, {"flap 1", {2, 2, 2, -1}}};
  const std::vector<LineInstability> u = lineInstabilities(d);
  ASSERT_EQ(u.size(), 1u);  // a rigid-body mode is no instability, nor zero damping
  EXPECT_EQ(u[0].name, "edge 1 BW");
  EXPECT_EQ(u[0].points, 2);
  EXPECT_DOUBLE_EQ(u[0].lowest_damping, -0.05);
  EXPECT_EQ(u[0].at, 2u);
}

TEST(CampbellDiagram, TitleIsTheModelsFirstSentenceOrTheFile) {
  Model m;
  m.name = "NREL 5.0 MW Baseline Wind Turbine. Onshore, with AeroDyn";
  EXPECT_EQ(campbellTitle(m, "cases/x/Main.fst"), "Campbell diagram: NREL 5.0 MW Baseline Wind Turbine");
  m.name = "";
  EXPECT_EQ(campbellTitle(m, "cases/x/Main.fst"), "Campbell diagram: Main.fst");
}

}  // namespace
}  // namespace whirl
