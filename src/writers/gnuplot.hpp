#pragma once
/// \file
/// Generated Gnuplot scripts: strings and comments that cannot become commands, and rendering a
/// script's PNG and SVG into place.
#include <string>
#include <vector>

namespace whirl {

/// A single-quoted Gnuplot string: Gnuplot 5 reads it verbatim (no backslash escapes, no `…`
/// command substitution, which double-quoted strings do run; no @macro expansion) up to the next
/// lone ', and '' stands for one quote. A newline would end the command and let the next line run
/// as one (`!cmd` is a shell command): control characters become spaces. With noenhanced terminals
/// no character has a meaning in the rendered text either.
std::string gnuplotQuoted(const std::string& s);

/// Text for a `#` comment: one line, and no trailing backslash (Gnuplot continues a comment ending
/// in \ onto the next line, which would swallow that line).
std::string gnuplotComment(const std::string& s);

/// Runs `gnuplot` (a program name on PATH, or a path) on `<stem>.gp` in `folder`, which writes the
/// files named by the variables png_out and svg_out; renders into temporary names and renames them
/// to `<stem>.png` and `<stem>.svg`, so a failing Gnuplot leaves no half image. Returns the images
/// written; a note on stderr when Gnuplot is missing, a warning when it fails, both naming
/// `shown_folder` (default `folder`): the output folder when `folder` is an OutputSet's staging folder.
std::vector<std::string> renderGnuplot(const std::string& folder, const std::string& gnuplot, const std::string& stem,
                                       const std::string& shown_folder = "");

}  // namespace whirl
