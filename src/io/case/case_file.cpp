// readCase: load the YAML, apply the overrides, read each section, finalize.
#include "src/io/case/case_file.hpp"

#include <yaml-cpp/eventhandler.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "src/base/error.hpp"
#include "src/base/limits.hpp"
#include "src/base/text.hpp"
#include "src/io/case/case_reader.hpp"
#include "src/io/text/input_file.hpp"

namespace whirl {
namespace {

// The 1-based line of a yaml-cpp mark, 0 when yaml-cpp has none.
int markLine(const YAML::Mark& mark) { return mark.is_null() ? 0 : mark.line + 1; }

// Whether a YAML document has content (anything but an empty document), and where it starts.
class DocumentContent : public YAML::EventHandler {
 public:
  bool found = false;
  YAML::Mark mark = YAML::Mark::null_mark();
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { note(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t, const std::string&) override { note(m); }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    note(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    note(m);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& m) {
    if (!found) mark = m;
    found = true;
  }
};

// Refuses a second document with content (after a `---` line), which YAML::Load skips. Only the
// first two documents are parsed: yaml-cpp 0.7's parser can report documents without end on some
// malformed text (YAML::LoadAll on 142 bytes took 23 GB, fuzz_cli).
void refuseSecondDocument(const std::string& text, const std::string& label) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentContent first, second;
  if (parser.HandleNextDocument(first) && parser.HandleNextDocument(second) && second.found)
    throw InputError(
        where(label, markLine(second.mark), "", "a second YAML document (after a '---' line): a case file holds one"));
}

// `label` names the text in messages (the file, or "<dict>" for a case built in Python). yaml-cpp's
// what() starts "yaml-cpp: error at line …": only its message and line reach the user.
YAML::Node parse(const std::string& text, const std::string& label) {
  try {
    YAML::Node doc = YAML::Load(text);
    refuseSecondDocument(text, label);
    return doc;
  } catch (const YAML::ParserException& e) {
    throw InputError(where(label, markLine(e.mark), "", "YAML syntax error: " + e.msg));
  } catch (const YAML::Exception& e) {
    throw InputError(where(label, markLine(e.mark), "", "cannot read the YAML: " + e.msg));
  }
}

YAML::Node load(const std::string& path) {
  if (std::filesystem::is_directory(path)) throw InputError(where(path, 0, "", "is a folder, not a case file"));
  std::istringstream in;
  if (!io::openInputFile(path, in)) throw InputError(where(path, 0, "", "cannot open the case file"));
  return parse(in.str(), path);
}

// Scalar g → [0, 0, −g] or a vector [gx, gy, gz].
Vec3 readGravity(const CaseNode& g) {
  if (!g.isScalar() && !g.isList()) g.fail("expected g [m/s²] or a vector [gx, gy, gz]");
  const Vec3 v = g.isScalar() ? Vec3(0, 0, -g.number()) : g.vec3();
  if (v.norm() > limits::kMaxGravity)
    g.fail(fmt::format("magnitude {:g} m/s² is above the limit of {:g} m/s² (100 g)", v.norm(), limits::kMaxGravity));
  return v;
}

// The case in `doc`; `path` names it in messages, `folder` holds the files it names.
Model readCaseDocument(YAML::Node doc, const std::string& path, const std::string& folder,
                       const std::vector<CaseOverride>& overrides, std::vector<fem::FlexibleBeam>* beams,
                       bool allow_outside_files) {
  CaseSource source;
  source.file = path;
  source.allow_outside_files = allow_outside_files;
  source.folder = folder;
  applyOverrides(doc, overrides, source);
  const CaseNode top(doc, source);
  if (!top.isMap())
    top.fail("a case file is a map of keys (name, gravity, bodies, ...), this one is empty, a list or a single value");
  top.allowKeys(
      {"name", "description", "gravity", "inputs", "bodies", "dofs", "loads", "outputs", "wind", "aero", "generator"});

  CaseBuild build;
  Model& m = build.model();
  m.name = top.text("name", std::filesystem::path(path).stem().string());
  if (!top.has("name")) requirePrintable(m.name, path, 0, "name (the case file's name)");
  if (const auto d = top.find("description")) d->freeText();
  if (const auto g = top.find("gravity")) m.gravity = readGravity(*g);
  if (const auto in = top.find("inputs")) readInputs(*in, build);
  readBodies(top.at("bodies"), build);
  if (const auto d = top.find("dofs")) readDofSettings(*d, build);
  if (const auto l = top.find("loads")) readLoads(*l, build);
  if (const auto in = top.find("inputs")) readInputTargets(*in, build);
  assignRoles(build);
  if (const auto o = top.find("outputs")) readOutputs(*o, build);
  readAerodynamics(top, build);
  if (const auto g = top.find("generator")) readGenerator(*g, build);
  // Body indices of build.beams are those before finalize() sorts the bodies.
  if (beams)
    for (const CaseBuild::Beam& b : build.beams)  // an fe_blade's shapes are its FE modes already
      if (!b.finite_element) beams->push_back({m.bodies[b.body].name, b.fem, b.shapes});
  Model model;
  try {
    model = std::move(build.builder).finish();
  } catch (const InputError& e) {
    rethrowAt(Where{path, 0, "", ""}, e);
  }
  addFemGeometricStiffness(model, build.fem);
  return model;
}

// Runs `read`; a yaml-cpp exception that escapes the readers (they ask the node's type before every
// access, so none should) becomes an InputError at its line: no library text reaches the user.
template <class Read>
Model guarded(const std::string& label, Read&& read) {
  try {
    return read();
  } catch (const YAML::Exception& e) {
    throw InputError(where(label, markLine(e.mark), "", "a value of an unexpected YAML type here"));
  }
}

}  // namespace

Model readCase(const std::string& path, const std::vector<CaseOverride>& overrides,
               std::vector<fem::FlexibleBeam>* beams, bool allow_outside_files) {
  return guarded(path, [&] {
    return readCaseDocument(load(path), path, std::filesystem::path(path).parent_path().string(), overrides, beams,
                            allow_outside_files);
  });
}

Model readCaseText(const std::string& text, const std::string& label, const std::string& folder,
                   const std::vector<CaseOverride>& overrides, bool allow_outside_files) {
  return guarded(label, [&] {
    return readCaseDocument(parse(text, label), label, folder, overrides, nullptr, allow_outside_files);
  });
}

}  // namespace whirl
