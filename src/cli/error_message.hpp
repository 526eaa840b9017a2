#pragma once
/// \file
/// The one line `whirl: error: <message>` says for an exception that ends a command. InputError and
/// ComputeError carry whirl's own messages (`file:line: key: reason`); any other exception is a
/// library's (the standard library's std::bad_alloc, nlohmann's `[json.exception…]`) whose text means
/// nothing to a user and is replaced by what happened and what to do (issue 48, item 5).
#include <exception>
#include <string>

namespace whirl::cli {

/// The message for `e`, one line, control characters and non-UTF-8 bytes escaped.
std::string errorMessage(const std::exception& e);

}  // namespace whirl::cli
