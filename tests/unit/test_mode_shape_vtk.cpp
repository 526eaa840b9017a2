// VTK animations of a mode (src/writers/mode_shape_vtk.hpp), checked against the rules of VTK's XML file
// formats (Kitware, "VTK File Formats", XML: a VTKFile element of type "PolyData" with one Piece whose
// NumberOfPoints and NumberOfLines match its arrays: Points 3 per point, point data per point, cell data
// per line; Lines' `offsets` the end of each cell in `connectivity`, increasing, the last equal to the
// connectivity's length; connectivity entries point indices; a "Collection" (.pvd) of DataSet entries
// with a timestep and a file) by a small XML parser here, and the drawn motion against the mode.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>

#include "linearize/operating_point.hpp"
#include "linearize/periodic.hpp"
#include "modal/mode_shapes.hpp"
#include "modal/rotor_modes.hpp"
#include "src/turbine/elastodyn_model.hpp"
#include "src/writers/campbell_output.hpp"
#include "src/writers/mode_shape_vtk.hpp"
#include "test_util.hpp"
#include "tests/unit/openfast_test_util.hpp"

namespace whirl {
namespace {

struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<Element> children;
  const Element* child(const std::string& n) const {
    for (const Element& c : children)
      if (c.name == n) return &c;
    return nullptr;
  }
  std::vector<const Element*> all(const std::string& n) const {
    std::vector<const Element*> v;
    for (const Element& c : children)
      if (c.name == n) v.push_back(&c);
    return v;
  }
};

// A well-formedness parser for the subset VTK writes: an XML declaration, elements with quoted
// attributes, text, self-closing tags. Fails the test (and returns an empty element) on a mismatched or
// unclosed tag, a duplicate attribute, a '<' or '&' in text, or anything after the root.
class XmlParser {
 public:
  explicit XmlParser(std::string s) : s_(std::move(s)) {}
  Element parse() {
    skipSpace();
    if (s_.compare(i_, 5, "<?xml") == 0) i_ = s_.find("?>", i_) + 2;
    skipSpace();
    Element root = element();
    skipSpace();
    EXPECT_EQ(i_, s_.size()) << "content after the root element";
    return root;
  }

 private:
  std::string s_;
  std::size_t i_ = 0;
  void skipSpace() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::string name() {
    const std::size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == ':')) ++i_;
    EXPECT_GT(i_, start) << "a name at " << start;
    return s_.substr(start, i_ - start);
  }
  Element element() {
    Element e;
    if (i_ >= s_.size() || s_[i_] != '<') {
      ADD_FAILURE() << "an element at " << i_;
      i_ = s_.size();
      return e;
    }
    ++i_;
    e.name = name();
    for (;;) {
      skipSpace();
      if (i_ >= s_.size()) {
        ADD_FAILURE() << "unclosed tag " << e.name;
        return e;
      }
      if (s_.compare(i_, 2, "/>") == 0) {
        i_ += 2;
        return e;
      }
      if (s_[i_] == '>') break;
      const std::string key = name();
      EXPECT_EQ(s_[i_], '=') << key;
      ++i_;
      EXPECT_EQ(s_[i_], '"') << key;
      const std::size_t end = s_.find('"', i_ + 1);
      EXPECT_TRUE(e.attributes.emplace(key, s_.substr(i_ + 1, end - i_ - 1)).second) << "duplicate " << key;
      i_ = end + 1;
    }
    ++i_;
    for (;;) {
      const std::size_t lt = s_.find('<', i_);
      if (lt == std::string::npos) {
        ADD_FAILURE() << "unclosed element " << e.name;
        i_ = s_.size();
        return e;
      }
      e.text += s_.substr(i_, lt - i_);
      i_ = lt;
      if (s_.compare(i_, 2, "</") == 0) {
        i_ += 2;
        EXPECT_EQ(name(), e.name) << "mismatched closing tag";
        skipSpace();
        EXPECT_EQ(s_[i_], '>');
        ++i_;
        EXPECT_EQ(e.text.find('&'), std::string::npos);
        return e;
      }
      e.children.push_back(element());
    }
  }
};

std::vector<double> values(const Element& array) {
  std::istringstream in(array.text);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  EXPECT_TRUE(in.eof()) << array.attributes.at("Name") << ": not all numbers";
  return v;
}

const Element& namedArray(const Element& parent, const std::string& name) {
  for (const Element* a : parent.all("DataArray"))
    if (a->attributes.count("Name") && a->attributes.at("Name") == name) return *a;
  ADD_FAILURE() << "no DataArray " << name << " in " << parent.name;
  static const Element none;
  return none;
}

// The PolyData checks of the header; returns the piece's points (3 per point) and its cells (point lists).
struct PolyData {
  std::vector<double> points, displacement;
  std::vector<std::vector<long>> cells;
};

PolyData checkPolyData(const std::string& text) {
  const Element root = XmlParser(text).parse();
  EXPECT_EQ(root.name, "VTKFile");
  EXPECT_EQ(root.attributes.at("type"), "PolyData");
  EXPECT_EQ(root.attributes.at("byte_order"), "LittleEndian");
  const Element* poly = root.child("PolyData");
  const Element* piece = poly ? poly->child("Piece") : nullptr;
  if (!piece) {
    ADD_FAILURE() << "no PolyData/Piece";
    return {};
  }
  const std::size_t np = std::stoul(piece->attributes.at("NumberOfPoints"));
  const std::size_t nl = std::stoul(piece->attributes.at("NumberOfLines"));
  PolyData out;
  out.points = values(*piece->child("Points")->child("DataArray"));
  EXPECT_EQ(piece->child("Points")->child("DataArray")->attributes.at("NumberOfComponents"), "3");
  EXPECT_EQ(out.points.size(), 3 * np);
  out.displacement = values(namedArray(*piece->child("PointData"), "displacement"));
  EXPECT_EQ(out.displacement.size(), 3 * np);
  EXPECT_EQ(values(namedArray(*piece->child("PointData"), "amplitude")).size(), np);
  EXPECT_EQ(values(namedArray(*piece->child("CellData"), "body")).size(), nl);
  const std::vector<double> conn = values(namedArray(*piece->child("Lines"), "connectivity"));
  const std::vector<double> offsets = values(namedArray(*piece->child("Lines"), "offsets"));
  EXPECT_EQ(offsets.size(), nl);
  double previous = 0;
  for (double o : offsets) {
    EXPECT_GE(o - previous, 2) << "a polyline of fewer than 2 points";
    out.cells.emplace_back();
    for (auto k = static_cast<std::size_t>(previous); k < static_cast<std::size_t>(o) && k < conn.size(); ++k)
      out.cells.back().push_back(static_cast<long>(conn[k]));
    previous = o;
  }
  EXPECT_EQ(previous, static_cast<double>(conn.size()));
  for (double c : conn) {
    EXPECT_GE(c, 0);
    EXPECT_LT(c, static_cast<double>(np));
  }
  return out;
}

// A small turbine: tower (3 nodes, ElastoDyn's frame: x up, z = ground X), nacelle and hub (one node each),
// three blades of two nodes. The tower top moves fore-aft by 1 at phase 0, blade b's tip flaps by 0.5
// at phase +120° (b − 1) (backward whirl).
ModeMotion turbine() {
  ModeMotion m;
  BodyMotion tower;
  tower.body = "tower";
  tower.nodes = {"node 1", "node 2", "node 3"};
  tower.x = VecX::LinSpaced(3, 0, 80);
  tower.position = Mat3X::Zero(3, 3);
  tower.position.row(2) = VecX::LinSpaced(3, 0, 80).transpose();
  tower.R << 0, 0, 1, 0, -1, 0, 1, 0, 0;
  tower.u = Eigen::MatrixXcd::Zero(3, 6);
  tower.u(1, 2) = 0.3, tower.u(2, 2) = 1.0;
  m.bodies.push_back(tower);
  for (const auto& [name, x] : {std::pair<std::string, double>{"nacelle", 0.0}, {"hub", -5.0}}) {
    BodyMotion b;
    b.body = name;
    b.nodes = {"origin"};
    b.x = VecX::Zero(1);
    b.position = Mat3X::Zero(3, 1);
    b.position.col(0) << x, 0, 80;
    b.u = Eigen::MatrixXcd::Zero(1, 6);
    b.u(0, 0) = 1.0;  // with the tower top: fore-aft (R = I: ground X)
    m.bodies.push_back(b);
  }
  for (int k = 0; k < 3; ++k) {
    BodyMotion b;
    b.body = "blade " + std::to_string(k + 1);
    b.blade = k;
    b.nodes = {"node 1", "node 2"};
    b.x = VecX::LinSpaced(2, 1.5, 61.5);
    const double psi = 2 * std::numbers::pi * k / 3;
    b.position = Mat3X::Zero(3, 2);
    for (int n = 0; n < 2; ++n) b.position.col(n) << -5, -b.x(n) * std::sin(psi), 80 + b.x(n) * std::cos(psi);
    b.R = Mat3::Identity();
    b.u = Eigen::MatrixXcd::Zero(2, 6);
    b.u(1, 0) = std::polar(0.5, 2 * std::numbers::pi * k / 3);  // flap: ground X
    m.bodies.push_back(b);
  }
  return m;
}

TEST(ModeShapeVtk, FramesAreValidPolyDataAndDrawTheMotion) {
  const ModeMotion m = turbine();
  VtkAnimationOptions opt;
  opt.frames = 8;
  const auto files = modeShapeVtk(m, "mode_x", 0.5, 0.4, opt);
  ASSERT_EQ(files.size(), 9u);
  EXPECT_EQ(files[0].first, "mode_x.pvd");
  // Bounding box of the nodes: x −5 … 0, y ±61.5 sin 120°, z 0 … 80 + 61.5.
  const double size = Vec3(5, 2 * 61.5 * std::sin(2 * std::numbers::pi / 3), 80 + 61.5).norm();
  const double scale = 0.1 * size;
  for (int k = 0; k < opt.frames; ++k) {
    EXPECT_EQ(files[static_cast<std::size_t>(k) + 1].first, "mode_x_0" + std::to_string(k) + ".vtp");
    const PolyData pd = checkPolyData(files[static_cast<std::size_t>(k) + 1].second);
    // Tower; tower top → nacelle → hub; three blades from the hub centre.
    ASSERT_EQ(pd.cells.size(), 5u);
    EXPECT_EQ(pd.cells[0].size(), 3u);
    EXPECT_EQ(pd.cells[1].size(), 3u);
    for (int b = 0; b < 3; ++b) EXPECT_EQ(pd.cells[2 + static_cast<std::size_t>(b)].size(), 3u);
    const double phi = 2 * std::numbers::pi * k / opt.frames;
    const auto point = [&](long i) { return Vec3(pd.points[3 * i], pd.points[3 * i + 1], pd.points[3 * i + 2]); };
    // Tower top: fore-aft (ground X) s cos φ about (0, 0, 80).
    EXPECT_NEAR((point(pd.cells[0][2]) - Vec3(scale * std::cos(phi), 0, 80)).norm(), 0, 1e-12) << k;
    // The hub chain starts at the tower top; blades start at the hub centre, moving with the hub.
    EXPECT_NEAR((point(pd.cells[1][0]) - point(pd.cells[0][2])).norm(), 0, 1e-12);
    EXPECT_NEAR((point(pd.cells[2][0]) - Vec3(-5 + scale * std::cos(phi), 0, 80)).norm(), 0, 1e-12);
    // Blade b's tip flaps 0.5 s cos(φ + 120° b).
    for (int b = 0; b < 3; ++b) {
      const long tip = pd.cells[2 + static_cast<std::size_t>(b)].back();
      EXPECT_NEAR(pd.displacement[3 * static_cast<std::size_t>(tip)],
                  0.5 * scale * std::cos(phi + 2 * std::numbers::pi * b / 3), 1e-12)
          << "frame " << k << ", blade " << b + 1;
    }
  }
  // The collection: one DataSet per frame, in time order over one damped period (1/0.4 s).
  const Element pvd = XmlParser(files[0].second).parse();
  EXPECT_EQ(pvd.attributes.at("type"), "Collection");
  const auto sets = pvd.child("Collection")->all("DataSet");
  ASSERT_EQ(sets.size(), 8u);
  for (std::size_t k = 0; k < sets.size(); ++k) {
    EXPECT_EQ(sets[k]->attributes.at("file"), files[k + 1].first);
    EXPECT_NEAR(std::stod(sets[k]->attributes.at("timestep")), k / 8.0 / 0.4, 1e-12);
  }
}

TEST(ModeShapeVtk, AnEmptyMotionWritesNothing) {
  EXPECT_TRUE(modeShapeVtk(ModeMotion{}, "x", 1, 1).empty());
  EXPECT_EQ(vtkFileStem("flap 1 BW (2)"), "flap_1_BW_2");
  EXPECT_EQ(vtkFileStem("--"), "mode");
}

// The NREL 5MW at 12 rpm (cases/nrel5mw/Main_Onshore.fst, 12 azimuths), its first backward-whirl flap
// mode: the tower (11 nodes), the chain tower top → nacelle → generator → hub, three blades of 11 nodes
// hung on the hub centre; the drawn displacements scaled by 0.1 × the model's size: the motion's largest
// component amplitude is 1 (modal/mode_shapes.hpp), so the largest drawn displacement over the frames
// lies between that scale × cos(π/16) (16 phase steps) and the scale × the largest node amplitude |u|.
TEST(ModeShapeVtk, Nrel5mwFlapWhirlIsDrawnAsTowerShaftAndThreeBlades) {
  const Model model = readElastoDynModel((test::nrel5mwDir() / "Main_Onshore.fst").string(), {"RotSpeed=12"});
  PeriodicOptions popt;
  popt.azimuths = 12;
  const PeriodicLinearization lin = linearizePeriodic(model, initialPoint(model), popt);
  RotorModes r = rotorModes(model, lin);
  addModeMotions(model, lin, r.num_blades, r.coordinates, r.modes);
  const Mode* flap = nullptr;
  for (const Mode& m : r.modes)
    if (m.name == "flap 1 BW") flap = &m;
  ASSERT_NE(flap, nullptr);
  const auto files = modeShapeVtk(flap->motion, "flap", flap->freq_hz, flap->damped_freq_hz);
  ASSERT_EQ(files.size(), 17u);
  double size = 0;
  {
    Vec3 lo = Vec3::Constant(1e300), hi = -lo;
    for (const BodyMotion& b : flap->motion.bodies)
      for (Eigen::Index k = 0; k < b.position.cols(); ++k)
        lo = lo.cwiseMin(b.position.col(k)), hi = hi.cwiseMax(b.position.col(k));
    size = (hi - lo).norm();
  }
  EXPECT_GT(size, 120);  // 87.6 m hub height + 63 m rotor radius
  double amplitude = 0;
  for (const BodyMotion& b : flap->motion.bodies)
    for (Eigen::Index k = 0; k < b.u.rows(); ++k) amplitude = std::max(amplitude, b.u.row(k).head<3>().norm());
  EXPECT_GE(amplitude, 1.0);
  double largest = 0;
  for (std::size_t f = 1; f < files.size(); ++f) {
    const PolyData pd = checkPolyData(files[f].second);
    ASSERT_EQ(pd.cells.size(), 5u);
    EXPECT_EQ(pd.cells[0].size(), 11u);                                      // tower nodes
    EXPECT_EQ(pd.cells[1].size(), 4u);                                       // tower top, nacelle, generator, hub
    for (std::size_t b = 2; b < 5; ++b) EXPECT_EQ(pd.cells[b].size(), 12u);  // hub centre + 11 blade nodes
    for (std::size_t i = 0; i + 2 < pd.displacement.size(); i += 3)
      largest = std::max(largest, Vec3(pd.displacement[i], pd.displacement[i + 1], pd.displacement[i + 2]).norm());
  }
  EXPECT_LE(largest, 0.1 * size * amplitude * (1 + 1e-12));
  EXPECT_GE(largest, 0.1 * size * std::cos(std::numbers::pi / 16));
}

// `campbell --format vtk` (writeCampbell): one animation per line and point with a mode, its .pvd's
// entries pointing at files written beside it.
TEST(ModeShapeVtk, CampbellWritesOneAnimationPerLineAndPoint) {
  CampbellDiagram d;
  for (int p = 0; p < 2; ++p) {
    CampbellPoint pt;
    pt.rpm = 6 + 3 * p;
    Mode md;
    md.freq_hz = 0.3;
    md.damped_freq_hz = 0.3;
    md.motion = turbine();
    pt.modes = {md, md};
    d.points.push_back(pt);
  }
  d.lines = {{"tower FA 1", {0, 0}}, {"flap 1 BW", {1, -1}}};
  test::TempDir tmp;
  const std::string dir = (tmp.path / "out").string();
  CampbellPlotOptions opt;
  opt.render = false;
  opt.formats = {"vtk"};
  writeCampbell(d, dir, opt);
  int pvds = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".pvd") continue;
    ++pvds;
    const Element pvd = XmlParser(test::slurp(e.path().string())).parse();
    for (const Element* set : pvd.child("Collection")->all("DataSet")) {
      const std::string frame = dir + "/" + set->attributes.at("file");
      ASSERT_TRUE(std::filesystem::exists(frame)) << frame;
      checkPolyData(test::slurp(frame));
    }
  }
  EXPECT_EQ(pvds, 3);
  EXPECT_TRUE(std::filesystem::exists(dir + "/mode_flap_1_BW_p0.pvd"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/mode_flap_1_BW_p1.pvd"));
}

}  // namespace
}  // namespace whirl
