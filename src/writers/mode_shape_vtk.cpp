// A mode's motion as a .pvd collection of .vtp polylines (src/writers/mode_shape_vtk.hpp).
#include "src/writers/mode_shape_vtk.hpp"

#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "src/io/text/csv.hpp"

namespace whirl {
namespace {

struct NodeRef {
  std::size_t body;
  Eigen::Index node;
};

// The polylines of the turbine, each a list of nodes (header's rules).
std::vector<std::vector<NodeRef>> polylines(const ModeMotion& m) {
  std::vector<std::vector<NodeRef>> lines;
  std::vector<NodeRef> run;            // the current run of one-node bodies
  std::optional<NodeRef> before, hub;  // the last node of the previous body; the end of the last run
  const auto closeRun = [&] {
    if (run.size() >= 2) lines.push_back(run);
    if (!run.empty()) hub = run.back();
    run.clear();
  };
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Eigen::Index n = m.bodies[b].position.cols();
    if (n == 0 || m.bodies[b].u.rows() != n) continue;
    if (n == 1) {
      if (run.empty() && before) run.push_back(*before);
      run.push_back({b, 0});
    } else {
      closeRun();
      std::vector<NodeRef> line;
      if (m.bodies[b].blade >= 0 && hub) line.push_back(*hub);
      for (Eigen::Index k = 0; k < n; ++k) line.push_back({b, k});
      lines.push_back(line);
    }
    before = NodeRef{b, n - 1};
  }
  closeRun();
  return lines;
}

Vec3 position(const ModeMotion& m, NodeRef r) { return m.bodies[r.body].position.col(r.node); }

// Ground translation amplitude of a node.
Eigen::Vector3cd groundAmplitude(const ModeMotion& m, NodeRef r) {
  const BodyMotion& b = m.bodies[r.body];
  return b.R.cast<std::complex<double>>() * b.u.row(r.node).head<3>().transpose();
}

std::string dataArray(const std::string& attributes, const std::string& values) {
  return "        <DataArray " + attributes + " format=\"ascii\">\n          " + values + "\n        </DataArray>\n";
}

std::string numbers(const std::vector<double>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? " " : "") + formatNumber(v[i]);
  return s;
}

std::string integers(const std::vector<long>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? " " : "") + std::to_string(v[i]);
  return s;
}

std::string vtpFrame(const ModeMotion& m, const std::vector<std::vector<NodeRef>>& lines, double scale, double phase) {
  const std::complex<double> rot = std::polar(1.0, phase);
  std::vector<double> points, displacement, amplitude;
  std::vector<long> connectivity, offsets, body;
  for (const auto& line : lines) {
    for (const NodeRef& r : line) {
      const Eigen::Vector3cd a = groundAmplitude(m, r);
      const Vec3 d = scale * (a * rot).real();
      const Vec3 p = position(m, r) + d;
      points.insert(points.end(), {p.x(), p.y(), p.z()});
      displacement.insert(displacement.end(), {d.x(), d.y(), d.z()});
      amplitude.push_back(a.norm());
      connectivity.push_back(static_cast<long>(connectivity.size()));
    }
    offsets.push_back(static_cast<long>(connectivity.size()));
    body.push_back(static_cast<long>(line.back().body));
  }
  std::string s =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <PolyData>\n";
  s += fmt::format(
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"0\" NumberOfLines=\"{}\" NumberOfStrips=\"0\" "
      "NumberOfPolys=\"0\">\n",
      connectivity.size(), lines.size());
  s += "      <PointData Vectors=\"displacement\" Scalars=\"amplitude\">\n";
  s += dataArray("type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\"", numbers(displacement));
  s += dataArray("type=\"Float64\" Name=\"amplitude\"", numbers(amplitude));
  s += "      </PointData>\n      <CellData Scalars=\"body\">\n";
  s += dataArray("type=\"Int64\" Name=\"body\"", integers(body));
  s += "      </CellData>\n      <Points>\n";
  s += dataArray("type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"", numbers(points));
  s += "      </Points>\n      <Lines>\n";
  s += dataArray("type=\"Int64\" Name=\"connectivity\"", integers(connectivity));
  s += dataArray("type=\"Int64\" Name=\"offsets\"", integers(offsets));
  s += "      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return s;
}

// Diagonal of the bounding box of the undeformed nodes [m].
double modelSize(const ModeMotion& m) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const BodyMotion& b : m.bodies)
    for (Eigen::Index k = 0; k < b.position.cols(); ++k) {
      lo = lo.cwiseMin(b.position.col(k));
      hi = hi.cwiseMax(b.position.col(k));
    }
  return std::isfinite(lo.x()) ? (hi - lo).norm() : 0.0;
}

}  // namespace

std::string vtkFileStem(const std::string& name) {
  std::string s;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) s += c;
    else if (!s.empty() && s.back() != '_') s += '_';
  }
  while (!s.empty() && s.back() == '_') s.pop_back();
  return s.empty() ? "mode" : s;
}

std::vector<std::pair<std::string, std::string>> modeShapeVtk(const ModeMotion& motion, const std::string& stem,
                                                              double freq_hz, double damped_freq_hz,
                                                              const VtkAnimationOptions& opt) {
  std::vector<std::pair<std::string, std::string>> files;
  const auto lines = polylines(motion);
  if (lines.empty() || opt.frames < 1) return files;
  const double size = modelSize(motion);
  const double scale = opt.scale_fraction * (size > 0 ? size : 1.0);
  const double f = damped_freq_hz > 0 ? damped_freq_hz : freq_hz;
  std::string pvd =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  files.emplace_back(stem + ".pvd", "");
  for (int k = 0; k < opt.frames; ++k) {
    const double cycle = static_cast<double>(k) / opt.frames;
    const std::string name = fmt::format("{}_{:02d}.vtp", stem, k);
    pvd += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                       formatNumber(f > 0 ? cycle / f : cycle), name);
    files.emplace_back(name, vtpFrame(motion, lines, scale, 2 * std::numbers::pi * cycle));
  }
  files.front().second = pvd + "  </Collection>\n</VTKFile>\n";
  return files;
}

}  // namespace whirl
