#pragma once
/// \file
/// The one place every reader of an input file gets its bytes (YAML cases, OpenFAST files, CSV
/// tables, `.lin` files, WAMIT and MAP++/MoorDyn files): only a regular file is read (a FIFO would
/// block forever, a device never end), and only one no larger than limits::kMaxInputFileBytes,
/// refused from its size before a byte is read (issue 48, item 3).
#include <sstream>
#include <string>

namespace whirl::io {

/// Reads the whole file `path` into `text`. Returns false, with errno set, when the file cannot be
/// opened or is a folder (the caller says so in its own words: "cannot open file", "is a folder").
/// \throws InputError "path: is a FIFO, not a regular file: whirl reads input only from files" for a
///   FIFO, socket or device, and "path: is N MB, more than the 128 MB an input file may have …"
///   when its size exceeds limits::kMaxInputFileBytes.
bool readInputFile(const std::string& path, std::string& text);

/// "file:line: more than 1000000 rows, the bound of a table (…)" for a table's row `line` past
/// limits::kMaxTableRows.
std::string tooManyRows(const std::string& file, int line);

/// readInputFile() into a stream for readers that go line by line; false when it cannot be opened.
bool openInputFile(const std::string& path, std::istringstream& in);

}  // namespace whirl::io
