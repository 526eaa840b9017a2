// writeCampbell: all Campbell files of one diagram, written atomically, then rendered by Gnuplot.
#include "modal/campbell_output.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "src/io/atomic_file.hpp"
#include "src/model/error.hpp"

namespace whirl {

namespace {

namespace fs = std::filesystem;

/// Full path of `program` on PATH (or itself when it holds a '/'); empty when not found.
std::string findProgram(const std::string& program) {
  if (program.empty()) return "";
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0 ? program : "";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
  }
  return "";
}

/// Runs `argv` with `dir` as working directory; returns its exit status (−1: could not start or
/// was killed by a signal, 127: could not be executed).
int runIn(const std::string& dir, const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool nonEmptyFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && fs::file_size(p, ec) > 0 && !ec;
}

/// Renders campbell.png and campbell.svg into temporary names, then renames them into place, so a
/// failing Gnuplot leaves no half image. Returns the images written; warns on stderr on failure.
std::vector<std::string> render(const fs::path& dir, const std::string& gnuplot) {
  const std::string program = findProgram(gnuplot);
  if (program.empty()) {
    std::cerr << "whirl: note: " << gnuplot << " not found on PATH; render with: cd " << dir.string()
              << " && gnuplot campbell.gp" << std::endl;
    return {};
  }
  const std::string tag = ".tmp" + std::to_string(::getpid());
  const std::string png = "campbell.png" + tag, svg = "campbell.svg" + tag;
  const int rc = runIn(dir.string(), {program, "-e", "png_out='" + png + "'; svg_out='" + svg + "'", "campbell.gp"});
  std::vector<std::string> written;
  std::error_code ec;
  if (rc == 0 && nonEmptyFile(dir / png) && nonEmptyFile(dir / svg)) {
    for (const auto& [tmp, name] : {std::pair{png, "campbell.png"}, std::pair{svg, "campbell.svg"}}) {
      fs::rename(dir / tmp, dir / name, ec);
      if (ec) break;
      written.push_back((dir / name).string());
    }
  }
  if (rc != 0 || written.size() != 2) {
    std::cerr << "whirl: warning: " << (dir / "campbell.gp").string() << ": " << program
              << (rc == 0 ? " did not write both images" : " failed (exit status " + std::to_string(rc) + ")")
              << "; campbell.png and campbell.svg are not up to date. The tables are complete." << std::endl;
  }
  fs::remove(dir / png, ec);
  fs::remove(dir / svg, ec);
  return written;
}

}  // namespace

std::vector<std::string> writeCampbell(const CampbellDiagram& d, const std::string& dir, const CampbellPlotOptions& opt) {
  checkCampbell(d, opt);
  const fs::path folder = dir.empty() ? fs::path(".") : fs::path(dir);
  const std::vector<std::pair<std::string, std::string>> files{{"campbell.csv", campbellCsv(d)},
                                                               {"campbell_modes.json", campbellModesJson(d)},
                                                               {"campbell.dat", campbellGnuplotData(d)},
                                                               {"campbell.gp", campbellGnuplotScript(d, opt)}};
  ensureWritableFolder(folder.string());
  std::vector<std::string> written;
  try {
    for (const auto& [name, text] : files) {
      writeFileAtomic((folder / name).string(), text);
      written.push_back((folder / name).string());
    }
  } catch (const InputError&) {
    for (const auto& w : written) std::remove(w.c_str());  // all four tables or none
    throw;
  }
  if (opt.render) {
    for (auto& image : render(folder, opt.gnuplot)) written.push_back(std::move(image));
  }
  return written;
}

}  // namespace whirl
