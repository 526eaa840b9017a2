// Runs a generated Gnuplot script: the images appear whole or not at all.
#include "src/writers/gnuplot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "src/base/text.hpp"

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

}  // namespace

std::vector<std::string> renderGnuplot(const std::string& folder, const std::string& gnuplot, const std::string& stem,
                                       const std::string& shown_folder) {
  const fs::path dir(folder), shown(shown_folder.empty() ? folder : shown_folder);
  const std::string program = findProgram(gnuplot);
  if (program.empty()) {
    std::cerr << "whirl: note: " << gnuplot << " not found on PATH; render with: cd " << shown.string()
              << " && gnuplot " << stem << ".gp" << std::endl;
    return {};
  }
  const std::string tag = ".tmp" + std::to_string(::getpid());
  const std::string png_name = stem + ".png", svg_name = stem + ".svg", script = stem + ".gp";
  const std::string png = png_name + tag, svg = svg_name + tag;
  const int rc = runIn(dir.string(), {program, "-e", "png_out='" + png + "'; svg_out='" + svg + "'", script});
  std::vector<std::string> written;
  std::error_code ec;
  if (rc == 0 && nonEmptyFile(dir / png) && nonEmptyFile(dir / svg)) {
    for (const auto& [tmp, name] : {std::pair{png, png_name}, std::pair{svg, svg_name}}) {
      fs::rename(dir / tmp, dir / name, ec);
      if (ec) break;
      written.push_back((dir / name).string());
    }
  }
  if (rc != 0 || written.size() != 2) {
    std::cerr << "whirl: warning: " << (shown / script).string() << ": " << program
              << (rc == 0 ? " did not write both images" : " failed (exit status " + std::to_string(rc) + ")") << "; "
              << png_name << " and " << svg_name << " are not up to date. The tables are complete." << std::endl;
  }
  fs::remove(dir / png, ec);
  fs::remove(dir / svg, ec);
  return written;
}

std::string gnuplotQuoted(const std::string& s) {
  std::string q = "'";
  for (char c : withoutControlCharacters(s)) {
    if (c == '\'') q += '\'';
    q += c;
  }
  return q + "'";
}

std::string gnuplotComment(const std::string& s) {
  std::string t = withoutControlCharacters(s);
  while (!t.empty() && (t.back() == '\\' || t.back() == ' ')) t.pop_back();
  return t;
}

}  // namespace whirl
