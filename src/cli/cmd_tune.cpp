// `whirl tune`: ROSCO's pole placement of the pitch and torque PI loops (linearize/controller_tuning.hpp)
// with whirl's sensitivities along its trimmed schedule, or with a ROSCO Cp surface (--cp-surface);
// writes tune.csv and, with --discon, that DISCON.IN with the new gain schedule.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "linearize/controller_tuning.hpp"
#include "linearize/controller_tuning_whirl.hpp"
#include "linearize/trim.hpp"
#include "modal/placement_check.hpp"
#include "src/base/error.hpp"
#include "src/cli/commands.hpp"
#include "src/cli/common.hpp"
#include "src/io/openfast/servodyn/discon_input.hpp"
#include "src/io/openfast/servodyn/rotor_performance_input.hpp"
#include "src/io/text/csv.hpp"
#include "src/io/text/input_file.hpp"
#include "src/writers/discon_gains.hpp"
#include "src/writers/output_set.hpp"

namespace whirl::cli {
namespace {

constexpr double kPi = std::numbers::pi;

struct TuneOptions {
  ModelOptions model;
  TuningGoals goals;
  double v_min = 0, v_rated = 0, v_max = 0;
  std::optional<double> inertia, rated_rotor_speed, rated_power, rotor_radius;
  std::string cp_surface, discon, out;
  bool quasi_steady = false, pointwise = false, full_model = false, full_model_placement = false;
  int azimuths = 3;
  int fl_mode = 0;                ///< ROSCO's floating feedback to tune (1) or none (0)
  std::optional<double> fl_wind;  ///< its U_Fl [m/s]; default 1.05 v_rated (ROSCO's)
};

std::string readText(const std::string& path) {
  std::string text;
  if (!io::readInputFile(path, text)) throw InputError(where(path, 0, "", "cannot open the file"));
  return text;
}

TuningTurbine turbineOf(const TuneOptions& opt, const Model& m, const std::optional<RoscoController>& rosco) {
  TuningTurbine t;
  // ROSCO's R is ElastoDyn's TipRad, along the blade; whirl's default is the swept disk's radius.
  t.rotor_radius = opt.rotor_radius.value_or(m.aero.rotor_radius);
  t.air_density = m.aero.air_density;
  t.gearbox_ratio = gearboxRatio(m);
  t.inertia = opt.inertia ? *opt.inertia : rotorInertia(m);
  const GeneratorTorqueLaw& law = m.generator;
  // A ROSCO deck's rated point is its controller's: PC_RefSpd and VS_RtPwr (ServoDyn's VS_* are unused).
  if (opt.rated_rotor_speed) t.rated_rotor_speed = *opt.rated_rotor_speed;
  else if (rosco) t.rated_rotor_speed = rosco->PC_RefSpd / t.gearbox_ratio;
  else if (law.active() && law.rated_speed > 0) t.rated_rotor_speed = law.rated_speed / t.gearbox_ratio;
  else throw InputError("tune: --rated-rotor-speed: the deck has no rated generator speed; give it");
  if (opt.rated_power) t.rated_power = *opt.rated_power;
  else if (rosco) t.rated_power = rosco->VS_RtPwr;
  else if (law.active() && law.rated_torque > 0) t.rated_power = law.rated_speed * law.rated_torque * law.efficiency;
  else throw InputError("tune: --rated-power: the deck has no rated generator torque; give it");
  t.v_min = opt.v_min;
  t.v_rated = opt.v_rated;
  t.v_max = opt.v_max;
  return t;
}

/// whirl's trimmed points at ROSCO's wind speeds that the placement uses: the last below rated and
/// every one from rated up; the above-rated flag by the wind speed, as ROSCO's schedule has it.
std::vector<TuningPoint> whirlSchedule(const TuneOptions& opt, const Model& m, const TuningTurbine& t,
                                       const std::optional<RoscoController>& rosco, std::vector<SteadyState>& trimmed) {
  const std::vector<double> all = roscoWindSpeeds(t, opt.goals);
  const size_t n_below = static_cast<size_t>(opt.goals.ws_gs_n - opt.goals.pc_gs_n - 1);
  const std::vector<double> winds(all.begin() + static_cast<long>(n_below) - 1, all.end());
  WhirlTuningOptions w;
  w.frozen_wake = !opt.quasi_steady;
  w.trim.azimuths = opt.azimuths;
  if (rosco) w.trim.controller = &*rosco;  // a ROSCO deck settles where its controller does
  trimmed = trimSchedule(m, winds, w.trim);
  std::vector<TuningPoint> s = whirlTuningSchedule(m, trimmed, w);
  for (size_t i = 0; i < s.size(); ++i) s[i].above_rated = i > 0;
  return s;
}

std::string csvOf(const std::vector<TuningPoint>& s, const GainSchedule& g) {
  std::string t =
      "wind_speed_m_s,rotor_speed_rpm,pitch_deg,tsr,dq_dpitch_nm_rad,dq_domega_nms_rad,dq_dwind_nms_m,a_1_s,b_beta_1_"
      "s2,"
      "kp_s,ki\n";
  size_t k = 0;
  for (const TuningPoint& p : s) {
    const bool placed = p.above_rated && k < g.wind_speed.size() && std::abs(g.wind_speed[k] - p.wind_speed) < 1e-9;
    for (double v :
         {p.wind_speed, p.rotor_speed * 30 / kPi, p.pitch * 180 / kPi, p.tsr, p.dq_dpitch, p.dq_domega, p.dq_dwind})
      t += formatNumber(v) + ",";
    if (placed) {
      t += formatNumber(g.a[k]) + "," + formatNumber(g.b[k]) + "," + formatNumber(g.kp[k]) + "," +
           formatNumber(g.ki[k]);
      ++k;
    } else {
      t += ",,,";
    }
    t += "\n";
  }
  return t;
}

/// placement_check.csv: per pitch-schedule point the target and the whole model's nearest closed-loop root.
std::string checkCsv(const std::vector<PlacementCheck>& checks) {
  std::string t =
      "wind_speed_m_s,target_real_1_s,target_imag_1_s,pole_real_1_s,pole_imag_1_s,omega_rad_s,zeta,"
      "distance_1_s,stable\n";
  for (const PlacementCheck& c : checks) {
    for (double v : {c.wind_speed, c.target.real(), c.target.imag(), c.pole.real(), c.pole.imag(), c.omega, c.zeta,
                     std::abs(c.pole - c.target)})
      t += formatNumber(v) + ",";
    t += c.stable ? "1\n" : "0\n";
  }
  return t;
}

void printChecks(const std::vector<PlacementCheck>& checks) {
  if (checks.empty()) return;
  double w_lo = 1e300, w_hi = 0, z_lo = 1e300, z_hi = -1e300;
  int unstable = 0;
  for (const PlacementCheck& c : checks) {
    w_lo = std::min(w_lo, c.omega), w_hi = std::max(w_hi, c.omega);
    z_lo = std::min(z_lo, c.zeta), z_hi = std::max(z_hi, c.zeta);
    unstable += c.stable ? 0 : 1;
  }
  std::printf(
      "whole model, closed with these gains: rotor-speed root omega %.3g to %.3g rad/s, zeta %.3g to %.3g "
      "(target %.3g rad/s, %.3g); unstable at %d of %zu points\n",
      w_lo, w_hi, z_lo, z_hi, std::abs(checks.front().target),
      -checks.front().target.real() / std::abs(checks.front().target), unstable, checks.size());
}

void run(TuneOptions opt) {
  const auto start = std::chrono::steady_clock::now();
  const Model m = loadModel(opt.model, true);
  if (!m.aero.active() && opt.cp_surface.empty())
    throw InputError(opt.model.case_path + ": the model has no aerodynamics; give --cp-surface or an aeroelastic deck");
  opt.goals.fit_linear_in_wind = !opt.pointwise;
  // The deck's ROSCO controller, when it names one: its rated point and its trim.
  const std::optional<RoscoController>& rosco = m.deck_controller;
  const TuningTurbine t = turbineOf(opt, m, rosco);
  const std::string discon_text = opt.discon.empty() ? std::string() : readText(opt.discon);
  std::vector<SteadyState> trimmed;
  const std::vector<TuningPoint> s = opt.cp_surface.empty()
                                         ? whirlSchedule(opt, m, t, rosco, trimmed)
                                         : roscoTuningSchedule(io::readRotorPerformance(opt.cp_surface), t, opt.goals);
  GainSchedule g = placePoles(s, t, opt.goals);
  if (opt.fl_mode > 0) {
    g.fl_mode = opt.fl_mode;
    g.fl_wind = opt.fl_wind.value_or(1.05 * t.v_rated);
    g.fl_kp = floatingFeedbackGain(s, g.fl_wind);
  }
  std::vector<PlacementCheck> checks;
  int placed_on_full = -1;
  if (opt.full_model || opt.full_model_placement) {
    if (!m.aero.active()) throw InputError(opt.model.case_path + ": --full-model needs an aeroelastic deck");
    // The pitch schedule's points: whirl's trims from rated up, or the deck trimmed at the surface's.
    std::vector<SteadyState> above;
    if (trimmed.empty()) {
      TrimOptions to;
      to.azimuths = opt.azimuths;
      if (rosco) to.controller = &*rosco;
      above = trimSchedule(m, g.wind_speed, to);
    }
    for (double u : trimmed.empty() ? std::vector<double>{} : g.wind_speed)
      for (const SteadyState& st : trimmed)
        if (std::abs(*st.condition.wind_speed - u) < 1e-9) above.push_back(st);
    PlacementCheckOptions pc;
    if (!discon_text.empty()) pc.speed_filter = io::parseDiscon(discon_text, opt.discon).F_LPFCornerFreq;
    if (opt.full_model_placement) {
      const FullModelPlacement fp = placeOnFullModel(m, above, g, t, opt.goals, pc);
      g = fp.gains;
      checks = fp.checks;
      placed_on_full = static_cast<int>(std::count(fp.converged.begin(), fp.converged.end(), true));
    } else {
      checks = checkPlacement(m, above, g, t, opt.goals, pc);
    }
  }
  const std::string dir = opt.out.empty() ? defaultOutputFolder(opt.model.case_path) : opt.out;
  prepareOutputFolder(dir);
  OutputSet files(dir);
  files.write("tune.csv", csvOf(s, g));
  if (!checks.empty()) files.write("placement_check.csv", checkCsv(checks));
  if (!opt.discon.empty()) files.write("DISCON.IN", disconWithGains(discon_text, opt.discon, g));
  files.commit();
  std::printf("sensitivities from %s; J = %.9g kg m^2, N = %g, R = %g m, rho = %g kg/m^3\n",
              opt.cp_surface.empty() ? "whirl's trimmed linearization" : opt.cp_surface.c_str(), t.inertia,
              t.gearbox_ratio, t.rotor_radius, t.air_density);
  std::printf("%8s %8s %12s %12s %11s %11s\n", "wind", "pitch", "dQ/dpitch", "dQ/dOmega", "PC_GS_KP", "PC_GS_KI");
  size_t k = 0;
  for (const TuningPoint& p : s) {
    if (!p.above_rated || k >= g.wind_speed.size() || std::abs(g.wind_speed[k] - p.wind_speed) > 1e-9) continue;
    std::printf("%8.3f %8.3f %12.5g %12.5g %11.4g %11.4g\n", p.wind_speed, p.pitch * 180 / kPi, p.dq_dpitch,
                p.dq_domega, g.kp[k], g.ki[k]);
    ++k;
  }
  std::printf("VS_KP %.6g, VS_KI %.6g\n", g.vs_kp, g.vs_ki);
  if (g.fl_mode > 0) std::printf("Fl_Kp %.6g s at Fl_U %.4g m/s\n", g.fl_kp, g.fl_wind);
  if (placed_on_full >= 0)
    std::printf("placed on the whole model at %d of %zu points (the others keep the one-state gains)\n", placed_on_full,
                checks.size());
  printChecks(checks);
  std::printf("wrote");
  for (const auto& f : files.paths()) std::printf(" %s", f.c_str());
  std::printf("\n%.2f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace

void addTuneCommand(CLI::App& app) {
  auto opt = std::make_shared<TuneOptions>();
  CLI::App* cmd = app.add_subcommand(
      "tune",
      "Gains of ROSCO's PI pitch and torque loops by ROSCO's pole placement on the one-state rotor model, with "
      "whirl's sensitivities along its trimmed schedule (or a ROSCO Cp surface); writes tune.csv and a DISCON.IN");
  addModelOptions(*cmd, opt->model, false);
  addAeroStateOptions(*cmd, opt->model);
  cmd->add_option("--pc-omega", opt->goals.pc_omega, "pitch loop natural frequency [rad/s]")->required();
  cmd->add_option("--pc-zeta", opt->goals.pc_zeta, "pitch loop damping ratio [-]")->required();
  cmd->add_option("--vs-omega", opt->goals.vs_omega, "torque loop natural frequency [rad/s]")->required();
  cmd->add_option("--vs-zeta", opt->goals.vs_zeta, "torque loop damping ratio [-]")->required();
  cmd->add_option("--v-min", opt->v_min, "cut-in wind speed of ROSCO's schedule [m/s]")->required();
  cmd->add_option("--v-rated", opt->v_rated, "rated wind speed [m/s]")->required();
  cmd->add_option("--v-max", opt->v_max, "cut-out wind speed [m/s]")->required();
  cmd->add_option("--ws-gs-n", opt->goals.ws_gs_n, "wind speeds of the schedule (ROSCO's WS_GS_n)")
      ->check(CLI::Range(4, 1000));
  cmd->add_option("--pc-gs-n", opt->goals.pc_gs_n, "of them above rated (ROSCO's PC_GS_n)")->check(CLI::Range(2, 999));
  cmd->add_option("--inertia", opt->inertia,
                  "rotor + generator inertia about the low-speed shaft [kg m^2] (default: the model's)");
  cmd->add_option("--rotor-radius", opt->rotor_radius,
                  "R of the tip-speed ratio and the Cp surface [m] (default: the swept disk's, coned)");
  cmd->add_option(
      "--rated-rotor-speed", opt->rated_rotor_speed,
      "[rad/s] (default: the deck's rated generator speed / gearbox ratio; ROSCO's PC_RefSpd / gearbox ratio)");
  cmd->add_option("--rated-power", opt->rated_power,
                  "[W] (default: the deck's rated speed x torque x efficiency; ROSCO's VS_RtPwr)");
  cmd->add_option("--cp-surface", opt->cp_surface, "ROSCO rotor performance file (Cp_Ct_Cq.*.txt): ROSCO's own tuning");
  cmd->add_option("--discon", opt->discon, "DISCON.IN to write again with the new gain schedule");
  cmd->add_flag("--quasi-steady", opt->quasi_steady,
                "sensitivities with the induction following at once (default: frozen wake)");
  cmd->add_flag("--pointwise", opt->pointwise,
                "place each wind speed's own plant (default: ROSCO's line fit in the wind speed)");
  cmd->add_flag("--full-model", opt->full_model,
                "also close the whole linear model with the placed gains at each pitch-schedule point (with --discon: "
                "its speed filter) and report where the rotor-speed root lands (placement_check.csv)");
  cmd->add_option(
         "--fl-mode", opt->fl_mode,
         "tune ROSCO's floating feedback too (1: tower-top velocity): Fl_Kp = (dQ/dU)/(dQ/dpitch) at --fl-wind, "
         "written with --discon as Fl_Mode, Fl_Kp, Fl_U")
      ->check(CLI::Range(0, 1));
  cmd->add_option("--fl-wind", opt->fl_wind,
                  "wind speed of the floating-feedback gain [m/s] (default: 1.05 x --v-rated, as ROSCO)");
  cmd->add_flag("--full-model-placement", opt->full_model_placement,
                "place the pitch loop's root on the whole linear model (Newton on K_p, K_i from the one-state gains; "
                "with --discon its speed filter in the loop) and write those gains; implies --full-model");
  addTrimAzimuths(*cmd, opt->azimuths);
  cmd->add_option("--out", opt->out, "output folder (default reports/<case name>)");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace whirl::cli
