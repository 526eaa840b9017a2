// [BranlardGeisler2022, §4.4]: two-DOF land-based NREL 5MW (tower fore-aft + azimuth).
// ν_y, Me, Ke, the two geometric stiffnesses, ω_e, Mq, Kq and the fore-aft frequency, each from the
// general engine (the closed form of eq. 37–46 is not used).
#include <numbers>

#include "modal/modes.hpp"
#include "tests/support/reference.hpp"

namespace whirl {
namespace {

constexpr const char* kCase = "landbased_2dof";

// K of the fore-aft coordinate with and without gravity, at the equilibrium.
double kFa(const std::vector<std::string>& sets) {
  const LinearModel l = test::linearizeAtEquilibrium(test::loadCase(kCase, sets));
  const int i = test::dofIndex(l, "tower FA 1");
  return l.K(i, i);
}

TEST(Landbased2Dof, MatchesSeed001Section44) {
  const Model m = test::loadCase(kCase);
  const Body& tower = m.bodies[*m.findBody("tower")];
  // Tower-top slope: the point's rotation about body y is −u_z'.
  const double nu_y = -tower.points.at(0).theta(1, 0);
  double Me = 0;
  for (int k = 0; k < 3; ++k) Me += tower.inertia.S[4 * k](1, 1);
  const double Ke = tower.elastic.K(0, 0);
  // Self weight: tower alone. Top mass: nacelle and rotor masses on the tower axis, minus self weight.
  const std::vector<std::string> no_rna = {"bodies.nacelle.mass=0", "bodies.rotor.mass=0"};
  const std::vector<std::string> on_axis = {"bodies.nacelle.cog=[0, 0, 0]",
                                            "bodies.nacelle.points.rotor centre.position=[0, 0, 0]"};
  auto with = [](std::vector<std::string> a, const std::string& b) {
    a.push_back(b);
    return a;
  };
  const double Kg_self = kFa(no_rna) - kFa(with(no_rna, "gravity=0"));
  const double Kg_top = kFa(on_axis) - kFa(with(on_axis, "gravity=0")) - Kg_self;
  const LinearModel l = test::linearizeAtEquilibrium(m);
  const int i = test::dofIndex(l, "tower FA 1");
  const auto modes = computeModes(l.M, l.C, l.K, l.dof_names);
  double f_fa = 0;
  for (const auto& mode : modes)
    if (mode.name == "tower FA 1") f_fa = mode.freq_hz;
  test::expectMatchesReference(kCase, {{"nu_y", nu_y},
                                       {"Me", Me},
                                       {"Ke", Ke},
                                       {"Kg_topmass", Kg_top},
                                       {"Kg_selfweight", Kg_self},
                                       {"omega_e", std::sqrt((Ke + Kg_top + Kg_self) / Me)},
                                       {"Mq", l.M(i, i)},
                                       {"Kq", l.K(i, i)},
                                       {"f_tower_fa", f_fa}});
}

}  // namespace
}  // namespace whirl
