#pragma once
#include <optional>
/// \file
/// Blade-element momentum (BEM) theory at one blade station, as OpenFAST AeroDyn v15 computes it with
/// `BEM_Mod = 1` (legacy "NoSweepPitchTwist", BEMTUncoupled.f90 `BEMTU_InductionWithResidual` →
/// `inductionFactors0`, BEMT.f90 `BEMT_UnCoupledSolve`, `computeFrozenWake`, AeroDyn.f90 `SetOutputsFromBEMT`),
/// i.e. OpenFAST v3.3 behaviour, kept in v4/v5 under BEM_Mod = 1.
///
/// Formulation: Ning 2014, "A simple solution method for the blade element momentum equations with guaranteed
/// convergence" (Wind Energy 17:1327–1345): one residual in the inflow angle φ, solved by a bracketed root
/// finder; Buhl 2005 (NREL/TP-500-36834) high-thrust correction for a > 0.4 with the Prandtl factor F;
/// Prandtl tip/hub loss in AeroDyn's form (Jonkman et al., AeroDyn v15 theory/user documentation).
///
/// ## Frames and sign conventions (AeroDyn's, BEM_Mod = 1)
/// The local "annulus" frame of a station is the blade-root frame without pitch, twist or live sweep
/// (AeroDyn `orientationAnnulus`, `Calculate_MeshOrientation_NoSweepPitchTwist`):
/// - x: normal to the (coned) rotor plane, positive downwind;
/// - y: in the rotor plane, perpendicular to the blade, positive towards the trailing edge, i.e. opposite to the
///   section's motion due to rotation (a blade moving in −y sees the air coming at +y);
/// - z: along the blade, root to tip.
/// Inputs: `Vx`, `Vy` [m/s] are the components along x, y of (undisturbed wind − structural velocity) at the
/// station (AeroDyn `u%Vx`, `u%Vy`). In normal operation Vx > 0 (≈ U cos(precone)) and Vy > 0 (≈ Ω r).
/// Inflow angle φ [rad]: angle from the rotor plane (+y) to the relative flow, tan φ = Vx(1−a) / (Vy(1+a')),
/// φ = atan2(Vx(1−a), Vy(1+a')). Angle of attack α = φ − θ, with θ [rad] = twist + pitch (positive towards
/// feather: increasing θ decreases α). Induction: the induced velocities are −a·Vx along x and +a'·Vy along y.
/// Loads per unit blade length (AeroDyn SetOutputsFromBEMT, BEM_Mod = 1), in the annulus frame:
///   Cx = Cl cos φ + Cd sin φ,  Cy = Cl sin φ − Cd cos φ,  q = ½ ρ W²,
///   Fx = Cx q c  (positive downwind: thrust),  Fy = −Cy q c  (along +y; the driving, torque-producing force
///   is −Fy > 0 in normal operation),  Mz = Cm q c²  (about z, nose-up positive as in the polar).
///
/// Not included here (caller's business): the skewed-wake redistribution (ApplySkewedWakeCorrection, needs the
/// azimuth and skew angle χ0; no effect at zero skew), the low-TSR blending of the inductions
/// (check_turnOffBEMT, rotor-level TSR < 2), DBEMT, unsteady aerodynamics, Reynolds-number tables.
#include <string>
#include <utility>

#include "src/aero/polar.hpp"

namespace whirl::aero {

/// AeroDyn's BEMT VelocityIsZero: an inflow component below this [m/s] counts as zero
/// (BEMT_UnCoupledSolve: |Vx| below it, no induction and φ = 0; |Vy| below it, φ = ±π/2).
inline constexpr double kZeroVelocity = 1e-3;

/// One blade station (AeroDyn blade node).
struct BemStation {
  double r = 0;                  ///< distance from the rotor axis (AeroDyn rLocal), used in the solidity [m]
  double z = 0;                  ///< distance along the blade from the hub centre (AeroDyn zLocal), used in the loss
                                 ///< constants; 0 → r [m]
  double hub_radius = 0;         ///< AeroDyn zHub: distance from the hub centre to the blade root along the blade [m];
                                 ///< 0 → no hub loss (F_hub = 1)
  double tip_radius = 0;         ///< AeroDyn zTip: zLocal of the last blade node [m]
  int blades = 3;                ///< number of blades B
  double chord = 0;              ///< [m]
  double theta = 0;              ///< twist + pitch [rad] (used by the overloads that take no theta)
  const Polar* polar = nullptr;  ///< airfoil table (not owned)
  /// Kinematic viscosity [m²/s] for the Reynolds number chord·W/ν of a polar with tables on it: the
  /// undisturbed W = √(Vx² + Vy²) in the BEM residual, the one with the induction in the loads (as
  /// AeroDyn's BEMT and its outputs); limited to ≥ 0.001 as AeroDyn does.
  double kin_visc = 1.464e-5;
};

/// AeroDyn BEMT options (AeroDyn input keys in parentheses).
struct BemOptions {
  bool tip_loss = true;  ///< Prandtl tip loss (TipLoss)
  bool hub_loss = true;  ///< Prandtl hub loss (HubLoss)
  bool tan_ind = true;   ///< tangential induction (TanInd)
  bool ai_drag = false;  ///< drag in the axial-induction equation (AIDrag)
  bool ti_drag = false;  ///< drag in the tangential-induction equation (TIDrag)
  int max_iter = 100;    ///< Brent iterations per bracket (MaxIter)
  /// Residual tolerance (IndToler): an end of a bracket with |R| below it is a solution, and the root finder
  /// stops when |R| falls below it. AeroDyn's double-precision default is 5e-10; the default here is tighter
  /// because linearization needs φ to near machine precision. [-]
  double tolerance = 1e-13;
  /// Bracket half-width at which the root finder stops, added to 2 ε |φ| (AeroDyn's Brent uses 1e-6) [rad].
  double phi_tolerance = 1e-14;
  /// The previous inflow angle: only orders the brackets, as AeroDyn's GetSolveRegionOrdering does with the
  /// previous φ (|φ| < π/4 → the [−π/4, −ε] bracket before [π/2+ε, π−ε]) [rad].
  double phi_guess = 0;
  /// When no bracket holds a valid solution: true → AeroDyn's behaviour (BEMT_UnCoupledSolve, in its time
  /// simulation and its linearization alike, with an informational message): the geometric φ = atan2(Vx, Vy),
  /// a = a' = 0, `valid = false`; false → throw ComputeError listing the brackets tried.
  bool geometric_fallback = true;
};

/// Inductions and residual at a given φ (AeroDyn BEMTU_InductionWithResidual / inductionFactors0).
template <class T>
struct Induction {
  T a;         ///< axial induction factor (before AeroDyn's limits)
  T ap;        ///< tangential induction factor a'
  T F;         ///< Prandtl tip × hub loss factor (1 in the special cases)
  T k, kp;     ///< Ning's k = σ Cx / (4 F sin²φ) and k' = σ Cy / (4 F sin φ cos φ) (sign-flipped for Vx < 0)
  T residual;  ///< Ning's residual R(φ)
  Coefficients<T> coef;  ///< polar at α = φ − θ (zero in the special cases, where it is not evaluated)
  bool valid = true;  ///< AeroDyn IsValidSolution (false: k < −1 in the momentum region, k ≤ 1 in the brake region)
  bool fixed = false;  ///< φ-independent special case (fixed inductions at a loss constant of 0, φ = 0, |Vx| or
                       ///< |Vy| < 1e-3 m/s): R ≡ 0
};

/// Result of solveInflow at double precision.
struct BemSolution {
  double phi = 0;        ///< inflow angle solving R(φ) = 0 (AeroDyn's constraint state z%phi) [rad]
  double a = 0;          ///< axial induction as AeroDyn outputs it: 0 if not valid, else limited to [−1, 1.5]
  double ap = 0;         ///< tangential induction, 0 if not valid, else limited to [−1, 1]
  double F = 1;          ///< loss factor at phi
  double k = 0, kp = 0;  ///< Ning's k, k' at phi
  double residual = 0;   ///< R(phi) (AeroDyn accepts a sign change with a valid solution as a root, so a
                         ///< discontinuity can pass; |residual| shows it)
  double phi_out = 0;    ///< AeroDyn's output φ = atan2(Vx(1−a), Vy(1+a')) from the limited inductions (= phi
                         ///< unless a limit is active) [rad]
  double alpha = 0;      ///< angle of attack phi_out − θ [rad]
  double W = 0;          ///< relative speed √((Vx(1−a))² + (Vy(1+a'))²) [m/s]
  double cl = 0, cd = 0, cm = 0;  ///< polar at alpha
  double ax_ind_vel = 0;   ///< induced velocity along x, −Vx·a (what frozen wake holds, AeroDyn AxInd_op) [m/s]
  double tan_ind_vel = 0;  ///< induced velocity along y, Vy·a' (AeroDyn TnInd_op) [m/s]
  int iterations = 0;      ///< residual evaluations in the root finder (0 for the special cases)
  double slope = 0;        ///< ∂R/∂φ of the secant search's last step (0 without one): a next solve's slope_hint
  int bracket = -1;        ///< which bracket held the root (0-based, AeroDyn's order), −1 for special cases
  bool valid = true;       ///< false only with geometric_fallback when no solution exists
};

/// The root of R(φ) as solveInflow finds it, with the inductions evaluated there, before AeroDyn's
/// outputs (the flow angle and the polar at the limited inductions) are formed from it.
struct InflowRoot {
  double phi = 0;          ///< as BemSolution::phi [rad]
  double a = 0, ap = 0;    ///< as BemSolution::a, ap (0 if not valid, else AeroDyn's limits)
  Induction<double> at{};  ///< inductions(φ): a, a' before the limits, F, k, k', R, the polar at φ − θ
  /// The root's own angle is AeroDyn's output angle: a valid root in the operating rotor's bracket
  /// (Vx, Vy > 0) whose inductions are within AeroDyn's limits. There tan φ = Vx(1−a)/(Vy(1+a')) is
  /// the equation R(φ) = 0 solves, so atan2 of the induced flow returns φ to within the root
  /// tolerance, and at.coef is the polar at the output angle of attack (no Reynolds tables).
  bool flow_at_root = false;
  bool valid = true;   ///< as BemSolution::valid
  int iterations = 0;  ///< as BemSolution::iterations
  double slope = 0;    ///< as BemSolution::slope
  int bracket = -1;    ///< as BemSolution::bracket
};

/// Loads per unit length at a station (see the file comment for signs).
template <class T>
struct SectionLoads {
  T phi;         ///< inflow angle [rad]
  T alpha;       ///< angle of attack [rad]
  T W;           ///< relative speed [m/s]
  T cl, cd, cm;  ///< polar coefficients at alpha [-]
  T cx, cy;      ///< Cx = Cl cos φ + Cd sin φ, Cy = Cl sin φ − Cd cos φ [-]
  T fx;          ///< force along annulus x (normal to the rotor plane, downwind) [N/m]
  T fy;          ///< force along annulus y (= −Cy q c; negative when driving the rotor) [N/m]
  T mz;          ///< pitching moment about annulus z (radial) [N m/m]
};

/// AeroDyn's loss constants B (zTip − z)/(2 z) and B (z − zHub)/(2 zHub) (BEMT_SetParameters).
double tipLossConstant(const BemStation& s);
double hubLossConstant(const BemStation& s);
/// AeroDyn's p%FixedInductions: a loss constant of 0 with that loss on (a = 1, a' = 0 whatever φ).
bool hasFixedInductions(const BemStation& s, const BemOptions& o);

/// `radius` (optional, in T): the distance from the rotor axis [m] the solidity is formed with, so that
/// its derivative reaches the result (a deflecting blade); absent: s.r.
/// Inductions and residual at inflow angle phi [rad] for inputs Vx, Vy [m/s] and theta [rad], as
/// BEMTU_InductionWithResidual with BEM_Mod = 1. Branches (momentum or propeller-brake region, Buhl, special
/// cases) are chosen from the values; formulas are evaluated in T (double or ADChunk).
template <class T>
Induction<T> inductions(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const T& theta,
                        const BemOptions& o, const T* radius = nullptr);
/// Same with θ = s.theta.
template <class T>
Induction<T> inductions(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const BemOptions& o);

/// Ning's residual R(φ) (AeroDyn fzero):
///   momentum region (φ > 0, Vx ≥ 0 or φ < 0, Vx < 0): R = sin φ/(1−a) − cos φ (Vx/Vy)(1−k'),
///   propeller-brake region:                             R = sin φ (1−k) − cos φ (Vx/Vy)(1−k').
template <class T>
T bemResidual(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const T& theta, const BemOptions& o,
              const T* radius = nullptr);
template <class T>
T bemResidual(const BemStation& s, const T& phi, const T& Vx, const T& Vy, const BemOptions& o);

/// Solves R(φ) = 0 at θ = s.theta by Brent's method in AeroDyn's brackets (GetSolveRegionOrdering,
/// FindTestRegion), accepting only valid solutions; special cases as BEMT_UnCoupledSolve: |Vx| < 1e-3 → φ = 0,
/// else |Vy| < 1e-3 → φ = ±π/2 (sign of Vx). Throws ComputeError naming r, Vx, Vy, θ and the brackets tried
/// when no bracket holds a valid root (unless o.geometric_fallback), InputError for an invalid station.
///
/// `phi_hint` (optional) is the root of a neighbouring solve of the same element (the previous Newton
/// iterate of an equilibrium). Inside the first bracket (the operating rotor's), secant steps start
/// from it before the bracket's ends are evaluated, and a valid root they reach inside it is taken
/// (two to four residuals instead of eight); steps that leave the bracket or stall fall back to the
/// bracketed search, which starts from the hint by safeguarded secant steps inside the bracket AeroDyn's
/// search selects. Either way it is the root Brent's search finds wherever the bracket holds one root,
/// equal to it within the tolerances; the brackets are tried in AeroDyn's order. `slope_hint`: ∂R/∂φ near the hint
/// (BemSolution::slope of that solve; 0: unknown) takes the first step, instead of a small step that
/// measures the slope.
BemSolution solveInflow(const BemStation& s, double Vx, double Vy, const BemOptions& o,
                        std::optional<double> phi_hint = std::nullopt, double slope_hint = 0.0);

/// solveInflow's root search alone (same arguments, same root, same errors), without the output
/// flow angle and polar that solveInflow evaluates at the limited inductions.
InflowRoot findInflowRoot(const BemStation& s, double Vx, double Vy, const BemOptions& o,
                          std::optional<double> phi_hint = std::nullopt, double slope_hint = 0.0);

/// Inflow angle as an implicit function of (Vx, Vy, θ): phi0 must solve R at the values of the inputs.
/// Returns phi0 − R(phi0; Vx, Vy, θ) / ∂R/∂φ(phi0) with ∂R/∂φ in double, so the value is phi0 (to the
/// residual) and the derivatives are −R_x/R_φ (implicit-function theorem). In the φ-independent special
/// cases (Induction::fixed) φ does not influence AeroDyn's outputs and phi0 is returned with zero derivatives.
/// `slope` (optional): ∂R/∂φ at phi0 kept by the caller for the AD passes at the same root — 0 on entry:
/// evaluated and stored (infinity for the special cases); otherwise used as it is.
template <class T>
T inflowAngle(const BemStation& s, const T& Vx, const T& Vy, const T& theta, double phi0, const BemOptions& o,
              const T* radius = nullptr, double* slope = nullptr);

/// Loads with AeroDyn's frozen wake (DBEMT_Mod = −1 / FrozenWake): the induced velocities at the operating point,
/// ax_ind_vel = −Vx₀ a₀ and tan_ind_vel = Vy₀ a'₀ (AeroDyn computeFrozenWake, BEMT.f90), are held; at the
/// perturbed inputs a = −ax_ind_vel/Vx, a' = tan_ind_vel/Vy (0 when Vx resp. Vy is 0), so the flow is
/// (Vx + ax_ind_vel, Vy + tan_ind_vel), φ = atan2 of it (0 if both are 0), α = φ − θ.
/// rho [kg/m³]. `o` is unused (kept for a uniform signature).
template <class T>
SectionLoads<T> frozenLoads(const BemStation& s, const T& Vx, const T& Vy, const T& theta, double ax_ind_vel,
                            double tan_ind_vel, double rho, const BemOptions& o);

/// Quasi-steady loads (induction re-solved with the inputs): φ = inflowAngle(...phi0...), inductions at φ
/// (0 if not valid, else limited to [−1, 1.5] and [−1, 1] as AeroDyn's limitInductionFactors), then AeroDyn's
/// output φ = atan2(Vx(1−a), Vy(1+a')), α, W and loads as frozenLoads.
/// `weight` (optional, default 1) scales a and a' after the limits, as AeroDyn's check_turnOffBEMT does at
/// low tip-speed ratios (inductionWeight).
/// `slope`: as for inflowAngle.
template <class T>
SectionLoads<T> quasiSteadyLoads(const BemStation& s, const T& Vx, const T& Vy, const T& theta, double phi0, double rho,
                                 const BemOptions& o, const T* radius = nullptr, const T* weight = nullptr,
                                 double* slope = nullptr);

/// The induced velocities of the quasi-steady BEM solution at (Vx, Vy, θ): AeroDyn's DBEMT input vind_s
/// (BEMT SetInputs_For_DBEMT, eq. 38 of its theory): axial −Vx a, tangential Vy a', with a, a' the inductions at
/// φ = inflowAngle(...phi0...) (its derivatives by the implicit-function theorem), 0 where the solution is not
/// valid, else within AeroDyn's limits (limitInductionFactors; a clamped value has no derivative); before the
/// low-TSR weight, which AeroDyn applies after DBEMT. `fixed`: AeroDyn's p%FixedInductions (a tip or hub loss
/// constant of 0: the tip node, a node at the blade root), where the loads take these inductions, not DBEMT's.
/// `radius`, `slope`: as for inflowAngle. [m/s]
template <class T>
struct InducedVelocity {
  T axial, tangential;
  bool fixed = false;
};
template <class T>
InducedVelocity<T> quasiSteadyInducedVelocity(const BemStation& s, const T& Vx, const T& Vy, const T& theta,
                                              double phi0, const BemOptions& o, const T* radius = nullptr,
                                              double* slope = nullptr);

/// Loads with given induced velocities (ax, tn) [m/s], e.g. DBEMT's states: AeroDyn's
/// calculate_Inductions_from_DBEMT, a = −ax/Vx, a' = tn/Vy (0 where Vx resp. Vy is 0), limited as
/// limitInductionFactors, scaled by the low-TSR `weight` (optional) as check_turnOffBEMT, then the flow
/// (Vx(1−a), Vy(1+a')) and its loads as frozenLoads. With ax, tn constant, unlimited and weight 1, frozenLoads.
template <class T>
SectionLoads<T> inducedVelocityLoads(const BemStation& s, const T& Vx, const T& Vy, const T& theta, const T& ax,
                                     const T& tn, double rho, const T* weight = nullptr);

/// The relative flow (x, y) = (Vx(1−a), Vy(1+a')) of inducedVelocityLoads, for models that form the section
/// loads themselves (the unsteady-airfoil elements, src/dynamics/aero_unsteady.hpp).
template <class T>
std::pair<T, T> inducedFlow(const T& Vx, const T& Vy, const T& ax, const T& tn, const T* weight = nullptr);

/// Loads of a solved element in double at its inductions a, a' (BemSolution::a, ap: AeroDyn's limited values,
/// times the low-TSR weight where it applies): AeroDyn's output φ = atan2(Vx(1−a), Vy(1+a')), α, W and loads as
/// frozenLoads. quasiSteadyLoads<double> at the same root, without re-evaluating the inductions and the
/// implicit-function step (a double evaluation carries no derivative): equal to it within the root's residual
/// tolerance (BemOptions::tolerance).
SectionLoads<double> loadsAtInduction(const BemStation& s, double Vx, double Vy, double theta, double a, double ap,
                                      double rho);

/// loadsAtInduction at a root with InflowRoot::flow_at_root (phi, a, ap, coef: its phi, a, ap, at.coef),
/// from the root's own evaluation: the output angle is the root φ (AeroDyn's atan2 of the induced flow
/// returns it to within the root tolerance) and the polar the root's (at φ − θ), so neither is
/// evaluated again. Equal to loadsAtInduction(s, Vx, Vy, theta, a, ap, rho) to the root tolerance.
SectionLoads<double> loadsAtRoot(const BemStation& s, double Vx, double Vy, double theta, double phi, double a,
                                 double ap, const Coefficients<double>& coef, double rho);

/// AeroDyn's BEM weight at tip-speed ratio λ (BEMT check_turnOffBEMT with BlendCosine): 0 for λ ≤ 1
/// (induction off: near standstill the momentum balance has no meaning), 1 for λ ≥ 2, ½(1 − cos(π(λ − 1)))
/// between.
template <class T>
T inductionWeight(const T& tsr);

}  // namespace whirl::aero
