// Every bad input gives one InputError line "file:line: key: reason": missing file, YAML syntax,
// unknown keys in any map, wrong types, non-finite numbers, negative mass, inertia that is not a
// mass distribution, beam columns of different lengths, unknown names, CSV errors, and errors of
// the core (finalize, buildBeamBody) re-thrown with the case file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "case_file_test_util.hpp"
#include "src/dynamics/outputs.hpp"
#include "src/dynamics/workspace.hpp"

namespace whirl {
namespace {

using ::testing::HasSubstr;
using testing::inputErrorOf;
using testing::lineOf;
using testing::replaced;
using testing::smallTurbineCase;

class CaseErrors : public ::testing::Test {
 protected:
  // The base case with `from` replaced by `to`; the error must name the file, the line where `to`
  // starts (or `line` when given) and contain `what`.
  void expect(const std::string& from, const std::string& to, const std::string& what, int line = 0) {
    const std::string text = replaced(smallTurbineCase(), from, to);
    expectText(text, line > 0 ? line : lineOf(text, to), what);
  }
  void expectText(const std::string& text, int line, const std::string& what) {
    const std::string path = tmp.write("bad.yaml", text);
    const std::string msg = inputErrorOf([&] { readCase(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":" + std::to_string(line) + ": ")) << "line " << line;
    EXPECT_THAT(msg, HasSubstr(what));
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line";
  }
  testing::TempCaseDir tmp;
};

TEST_F(CaseErrors, BaseCaseIsValid) { EXPECT_EQ(readCase(tmp.write("ok.yaml", smallTurbineCase())).ndof(), 2); }

TEST_F(CaseErrors, MissingFile) {
  const std::string path = (tmp.dir / "nope.yaml").string();
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }), HasSubstr(path + ": cannot open the case file"));
}

TEST_F(CaseErrors, YamlSyntax) {
  expect("uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}", "uniform: {m: 5000, EIy: [1.0e11, EIz: 1.0e11}",
         "YAML syntax error");
  expect("    type: rigid\n    parent: tower", "    type: rigid\n   parent: tower", "YAML syntax error",
         lineOf(smallTurbineCase(), "    parent: tower"));
}

// Beyond 100 g (limits::kMaxGravity) a case is an input error, as a scalar g or as a vector.
TEST_F(CaseErrors, GravityMagnitudeIsBounded) {
  expect("gravity: 9.81", "gravity: [0, 0, 1.0e9]", "gravity: magnitude 1e+09 m/s² is above the limit of 1000 m/s²");
  expect("gravity: 9.81", "gravity: 1001", "gravity: magnitude 1001 m/s² is above the limit of 1000 m/s²");
  EXPECT_NO_THROW(
      readCase(tmp.write("g.yaml", replaced(smallTurbineCase(), "gravity: 9.81", "gravity: [0, 600, 800]"))));
}

TEST_F(CaseErrors, UnknownKeysInEveryMap) {
  expect("gravity: 9.81", "gravty: 9.81", "gravty: unknown key 'gravty' (allowed: name, description, gravity, inputs");
  expect("  - {name: thrust, value: 1.0e5}", "  - {name: thrust, valeu: 1.0e5}", "inputs.thrust.valeu: unknown key");
  expect("    mass: 2.4e5", "    mas: 2.4e5",
         "bodies.nacelle.mas: unknown key 'mas' (allowed: name, type, parent, at,"
         " offset, rotation, joint, points, mass, cog, inertia)");
  expect("    length: 80", "    length: 80\n    mass: 3", "bodies.tower.mass: unknown key 'mass'",
         lineOf(smallTurbineCase(), "    length: 80") + 1);
  expect("{m: 5000, EIy: 1.0e11, EIz: 1.0e11}", "{m: 5000, EIy: 1.0e11, EIz: 1.0e11, Gkt: 1}",
         "bodies.tower.uniform.Gkt: unknown key 'Gkt' (allowed: m, EIy, EIz, GKt, jG)");
  expect("direction: z}", "directon: z}", "bodies.tower.shapes.tower FA 1.directon: unknown key");
  expect("{name: top, x: 80}", "{name: top, x: 80, y: 0}",
         "bodies.tower.points.top.y: unknown key 'y' (allowed: name, x, fraction)");
  expect("{name: hub, position: [-5, 0, 2]}", "{name: hub, pos: [-5, 0, 2]}",
         "unknown key 'pos' (allowed: name, position)");
  expect("axis: [1, 0, 0]", "axes: [1, 0, 0]",
         "bodies.rotor.joint.axes: unknown key 'axes' (allowed: type, axis, dof)");
  expect("{y_deg: 90}", "{y_degs: 90}", "unknown key 'y_degs' (allowed: x, y, z, x_deg, y_deg, z_deg)");
  expect("rate_rpm: 12.1}", "rate_rmp: 12.1}",
         "dofs.azimuth.rate_rmp: unknown key 'rate_rmp' (allowed: value, value_deg,");
  expect("force: [1, 0, 0]", "forse: [1, 0, 0]",
         "unknown key 'forse' (allowed: type, body, point, force, moment, frame, input)");
  expect("inertia: [1.0e6, 2.0e6, 2.0e6]", "inertia: {xx: 1, yx: 2}",
         "unknown key 'yx' (allowed: xx, yy, zz, xy, xz, yz)");
  expect("    mass: 2.4e5", "    mass: 2.4e5\n    mass: 2.5e5", "bodies.nacelle.mass: key 'mass' given twice",
         lineOf(smallTurbineCase(), "    mass: 2.4e5") + 1);
}

TEST_F(CaseErrors, WrongTypes) {
  expect("mass: 2.4e5", "mass: heavy", "bodies.nacelle.mass: expected a number, got 'heavy'");
  expect("mass: 2.4e5", "mass: \"2.4e5\"", "expected a number, got the quoted text");
  expect("length: 80", "length: [80]", "bodies.tower.length: expected a number, got a list");
  expect("type: revolute,", "type: hinge,", "unknown joint type 'hinge' (allowed: fixed, revolute, prismatic, free)");
  expect("type: beam", "type: flexible", "unknown body type 'flexible' (allowed: rigid, beam, fem_beam, fe_blade)");
  expect("rotating: true", "rotating: yes please", "dofs.azimuth.rotating: expected true or false");
  expect("force: [1, 0, 0]", "force: [1, 0]", "expected 3 numbers [x, y, z], got 2");
  expect("  - name: tower\n", "  - tower\n  - name: tower\n", "bodies[0]: expected a map of keys, got 'tower'");
}

TEST_F(CaseErrors, NonFiniteNumbers) {
  expect("mass: 2.4e5", "mass: .nan", "bodies.nacelle.mass: expected a finite number, got .nan");
  expect("EIy: 1.0e11", "EIy: .inf", "bodies.tower.uniform.EIy: expected a finite number, got .inf");
  expect("force: [1, 0, 0]", "force: [1, -.inf, 0]", "loads[0].force[1]: expected a finite number");
}

TEST_F(CaseErrors, NegativeMassAndBadInertia) {
  expect("mass: 2.4e5", "mass: -2.4e5", "bodies.nacelle.mass: negative mass");
  expect("{m: 5000,", "{m: -5000,", "bodies.tower.uniform.m: must not be negative");
  expect("inertia: [1.0e6, 2.0e6, 2.0e6]", "inertia: [1.0e6, -1.0e6, 5.0e6]",
         "bodies.nacelle.inertia: the inertia tensor is not positive semi-definite");
  expect("inertia: [1.0e6, 2.0e6, 2.0e6]", "inertia: [[1, 0, 0], [0.5, 1, 0], [0, 0, 1]]", "not symmetric");
  expect("rotation: {y_deg: 90}", "rotation: [[1, 0, 0], [0, 1, 0], [0, 0.1, 1]]",
         "bodies.nacelle.rotation: the rotation matrix is not orthonormal");
}

TEST_F(CaseErrors, BeamColumnsOfDifferentLengths) {
  expect("uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}",
         "properties:\n      x: [0, 40, 80]\n      m: [5000, 5000, 5000]\n      EIy: [1.0e11, 1.0e11]\n"
         "      EIz: [1.0e11, 1.0e11, 1.0e11]",
         "bodies.tower.properties.EIy: has 2 values, x has 3", lineOf(smallTurbineCase(), "uniform:") + 3);
  expect("uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}",
         "properties: {x: [0, 40, 70], m: [1, 1, 1], EIy: [1, 1, 1], EIz: [1, 1, 1]}",
         "bodies.tower.properties.x: stations must run from 0 to the length");
  expect("uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}", "properties: {x: [0, 80], m: [1, 1], EIy: [1, 1]}",
         "bodies.tower.properties: missing column 'EIz'");
}

TEST_F(CaseErrors, CsvProblemsNameTheCsvFileAndLine) {
  tmp.write("props.csv", "x, m, EIy, EIz\n0, 5000, 1e11, 1e11\n80, heavy, 1e11, 1e11\n");
  const std::string csv = (tmp.dir / "props.csv").string();
  const std::string text = replaced(smallTurbineCase(), "uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}",
                                    "properties: {file: props.csv}");
  const std::string path = tmp.write("bad.yaml", text);
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }), HasSubstr(csv + ":3: m: expected a finite number, got 'heavy'"));
  tmp.write("props.csv", "x, m, EIy, EIz, mass\n0, 5000, 1e11, 1e11, 1\n80, 5000, 1e11, 1e11, 1\n");
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }),
              HasSubstr(csv + ":1: mass: unknown column (allowed: x, fraction, m,"));
  tmp.write("props.csv", "x, m, EIy, EIz\n0, 5000, 1e11, 1e11\n80, -1, 1e11, 1e11\n");
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }), HasSubstr(csv + ":3: m: must not be negative"));
  std::filesystem::remove(tmp.dir / "props.csv");
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }),
              HasSubstr(path + ":" + std::to_string(lineOf(text, "properties:")) +
                        ": bodies.tower.properties.file: cannot open"));
}

TEST_F(CaseErrors, UnknownNames) {
  expect("parent: tower", "parent: towr",
         "bodies.nacelle.parent: no body named 'towr' (bodies: tower, nacelle, rotor)");
  expect("at: top", "at: tip", "bodies.nacelle.at: body 'tower' has no point named 'tip' (points: top)");
  expect("  azimuth: {", "  azimut: {", "dofs.azimut: no DOF named 'azimut' (DOFs: tower FA 1, azimuth)");
  expect("input: thrust}", "input: thrst}", "loads[0].input: no input named 'thrst' (inputs: thrust)");
  expect("{type: point, body: nacelle,", "{type: point, body: hub,", "loads[0].body: no body named 'hub'");
  expect("point: hub, force", "point: top, force", "loads[0].point: body 'nacelle' has no point named 'top'");
  expect("  - {type: point,", "  - {type: dof, dof: azimut, value: 1}\n  - {type: point,",
         "loads[0].dof: no DOF named 'azimut'");
  expect("  - name: rotor\n", "  - name: nacelle\n", "bodies.nacelle.name: body name 'nacelle' is already used at line",
         lineOf(smallTurbineCase(), "  - name: rotor"));
  expect("dof: azimuth}", "dof: tower FA 1}", "DOF name 'tower FA 1' is already used at line");
}

TEST_F(CaseErrors, UnitsAndJointsThatDoNotFit) {
  expect("  azimuth: {rotating: true, rate_rpm: 12.1}", "  tower FA 1: {value_deg: 1}",
         "dofs.tower FA 1.value_deg: DOF 'tower FA 1' is a displacement [m], not an angle");
  expect("  - {type: point,", "  - {type: body_matrices, body: rotor}\n  - {type: point,",
         "loads[0].body: body 'rotor' has no free joint");
  expect("{name: top, x: 80}", "{name: top, x: 81}", "bodies.tower.points.top.x: the point must lie on the beam");
  expect("{type: revolute, axis: [1, 0, 0],", "{type: revolute, axis: [0, 0, 0],", "the joint axis must not be zero");
}

// `type: mooring_line` (cases/oc3_hywind/mooring_only.yaml): its body, its numbers and a line that cannot
// reach its anchor, each with the place in the case file.
TEST_F(CaseErrors, MooringLines) {
  const std::string yaml = R"(name: moored
bodies:
  - {name: platform, type: rigid, mass: 1.0e6, inertia: [1.0e9, 1.0e9, 1.0e9],
     joint: {type: free, dofs: [surge, sway, heave, roll, pitch, yaw]}}
loads:
  - {type: mooring_line, body: platform, fairlead: [5, 0, -70], anchor: [850, 0, -320], length: 900,
     weight: 700, EA: 4.0e8}
)";
  EXPECT_EQ(readCase(tmp.write("ok.yaml", yaml)).mooring.size(), 1u);
  expectText(replaced(yaml, "length: 900", "length: 300"), 6, "loads[0]: ");
  expectText(replaced(yaml, "weight: 700", "weight: -1"), 6,
             "weight: the weight in water per length [N/m] must be positive");
  expectText(replaced(yaml, "EA: 4.0e8}", "EA: 4.0e8, colour: red}"), 7, "loads[0].colour: unknown key");
  expectText(replaced(yaml, "body: platform,", "body: hull,"), 6, "hull");
}

TEST_F(CaseErrors, CoreErrorsAreRethrownWithTheCaseFile) {
  // A parent loop is found by finalize(); two identical shapes by finalize()'s elastic mass check.
  const std::string loop = replaced(replaced(smallTurbineCase(), "    rotation: {y_deg: -90}\n",
                                             "    rotation: {y_deg: -90}\n    parent: rotor\n    at: tip\n"),
                                    "mass: 1.1e5", "mass: 1.1e5\n    points: [{name: tip, position: [0, 0, 0]}]");
  const std::string path = tmp.write("loop.yaml", loop);
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }), HasSubstr(path + ": body '"));
  EXPECT_THAT(inputErrorOf([&] { readCase(path); }), HasSubstr("the parent chain forms a loop"));
  const std::string twin = replaced(smallTurbineCase(),
                                    "      - {name: tower FA 1, type: one_minus_cos, direction: z}\n",
                                    "      - {name: tower FA 1, type: one_minus_cos, direction: z}\n"
                                    "      - {name: tower FA 2, type: one_minus_cos, direction: z}\n");
  const std::string p2 = tmp.write("twin.yaml", twin);
  EXPECT_THAT(inputErrorOf([&] { readCase(p2); }),
              HasSubstr(p2 + ": body 'tower': elastic mass matrix is not positive definite"));
}

TEST_F(CaseErrors, ShapesThatOverflowAreRefusedAtTheirLine) {
  // cosh(β x/L) overflows for a high mode of eq. 32: refused before it gives NaN integrals.
  expect("{name: tower FA 1, type: one_minus_cos, direction: z}",
         "{name: tower FA 1, type: clamped_topmass, direction: z, mode: 400, tip_mass_ratio: 1}",
         "bodies.tower.shapes.tower FA 1: the shape is not finite");
}

// `shapes: {from: fem}`: unknown keys, bad values and FE failures name the key and line.
TEST_F(CaseErrors, FemShapes) {
  const std::string fa = "      - {name: tower FA 1, type: one_minus_cos, direction: z}";
  auto fem = [&](const std::string& settings, const std::string& mode) {
    return "      from: fem\n" + settings + "      modes:\n        - " + mode;
  };
  const std::string ok = "{name: tower FA 1, direction: z, mode: 1}";
  // Lines: 12 `from: fem`, 13 the setting (or `modes:`), then `modes:` and its entry.
  expect(fa, fem("      tip_mas: {mass: 1}\n", ok), "shapes.tip_mas: unknown key 'tip_mas'", 13);
  expect(fa, fem("      from_file: x\n", ok), "unknown key 'from_file'", 13);
  expect(fa, fem("", "{name: tower FA 1, direction: x, mode: 1}"), "direction: expected y or z", 14);
  expect(fa, fem("", "{name: tower FA 1, direction: z, mode: 0}"), "mode: the mode number must be from 1 to 50", 14);
  expect(fa, fem("      tip_mass: {mass: -5}\n", ok), "tip_mass.mass: negative mass", 13);
  expect(fa, fem("      elements: 0\n", ok), "elements: the number of elements must be from 1 to 200", 13);
  // The dense FE eigenproblem is O(elements³): 686 elements took 62 s (a fuzz finding), refused here.
  expect(fa, fem("      elements: 686\n", ok), "elements: the number of elements must be from 1 to 200", 13);
  expect(fa, fem("      rotation_axis: x\n", ok), "rotation_axis: expected y, z or [x, y, z], got 'x'", 13);
  expect(fa, "      from: beamdyn\n      modes: []", "unknown shape source 'beamdyn' (allowed: fem)", 12);
  expect(fa, "      from: fem\n      modes: []", "list at least one mode", 13);
  // 2 elements hold 4 bending modes per direction: mode 5 fails in the FE, re-thrown at the shapes.
  const std::string text = replaced(smallTurbineCase(), fa,
                                    fem("      elements: 2\n", "{name: tower FA 1, direction: z, mode: 5}"));
  expectText(text, lineOf(text, "      from: fem"), "only");
}

// `integration: {n:}` is bounded per method at its key: 3210 Gauss points took over two minutes under
// the sanitizers (a fuzz finding, when their nodes came from a dense eigenproblem).
TEST_F(CaseErrors, IntegrationPointCountsAreBounded) {
  const std::string at = "    uniform: {m: 5000, EIy: 1.0e11, EIz: 1.0e11}";
  auto with = [&](const std::string& integration) { return at + "\n    integration: " + integration; };
  auto refused = [&](const std::string& integration, const std::string& what) {
    const std::string text = with(integration);
    expect(at, text, what, lineOf(replaced(smallTurbineCase(), at, text), "integration:"));
  };
  refused("{method: gauss, n: 3210}", "integration.n: must be between 1 and 500 with method gauss");
  refused("{n: 501}", "must be between 1 and 500 with method gauss");
  refused("{n: 10001, method: trapezoid}", "must be between 1 and 10000 with method trapezoid");
  refused("{method: midpoint, n: 0}", "must be between 1 and 10000 with method midpoint");
  EXPECT_EQ(readCase(tmp.write("gauss.yaml", replaced(smallTurbineCase(), at, with("{method: gauss, n: 500}")))).ndof(),
            2);
  EXPECT_EQ(
      readCase(tmp.write("trap.yaml", replaced(smallTurbineCase(), at, with("{method: trapezoid, n: 10000}")))).ndof(),
      2);
}

// `type: angular`: a body frame's angular velocity about ground axes (default order: rate, unit rad/s). The
// rotor of the small turbine turns at 12.1 rpm about ground x.
TEST_F(CaseErrors, AngularOutputsAreABodyFramesAngularVelocity) {
  const std::string out =
      "outputs:\n  - {name: spin, type: angular, body: rotor, direction: [1, 0, 0], frame: ground}\n";
  const Model m = readCase(tmp.write("ok.yaml", smallTurbineCase() + out));
  const Output& o = m.outputs[*m.findOutput("spin")];
  EXPECT_EQ(o.kind, OutputKind::Angular);
  EXPECT_EQ(o.order, 1);
  EXPECT_EQ(o.unit, "rad/s");
  Workspace<double> ws(m);
  VecX q = VecX::Zero(m.ndof()), qd = VecX::Zero(m.ndof()), y(m.noutput());
  qd(*m.findDof("azimuth")) = 12.1 * std::numbers::pi / 30;
  evaluateOutputs(m, ws, q, qd, VecX::Zero(m.ndof()).eval(), y);
  EXPECT_NEAR(y(*m.findOutput("spin")), 12.1 * std::numbers::pi / 30, 1e-12);
  const std::string base = smallTurbineCase() + out;
  const int line = lineOf(base, "  - {name: spin");
  expectText(replaced(base, "frame: ground}", "frame: ground, order: 0}"), line,
             "an angular output is a rate (1) or an acceleration (2)");
  expectText(replaced(base, "frame: ground}", "frame: ground, point: hub}"), line, "point");
  expectText(replaced(base, "type: angular", "type: angle"), line, "allowed: dof, point, angular, moment");
}

TEST_F(CaseErrors, FemShapesValidCaseReads) {
  const std::string fa = "      - {name: tower FA 1, type: one_minus_cos, direction: z}";
  const std::string text = replaced(smallTurbineCase(), fa,
                                    "      from: fem\n      axial_gravity: 9.81\n      modes:\n"
                                    "        - {name: tower FA 1, direction: z, mode: 1}\n"
                                    "        - {name: tower SS 1, direction: y, mode: 1}");
  EXPECT_EQ(readCase(tmp.write("fem.yaml", text)).ndof(), 3);
}

}  // namespace
}  // namespace whirl
