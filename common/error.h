// Error types: InputError is bad user input (exit code 2), anything else is an internal failure.
#pragma once

#include <stdexcept>
#include <string>

namespace voxgi {

// `text` as one printable line: control characters and bytes that are not valid UTF-8 become
// \xNN, and anything past `limit` bytes becomes "...". File names, fields and library messages
// carry bytes from the input; echoed raw they could end the line, move the cursor or mangle the
// terminal.
std::string printable(const std::string& text, size_t limit = 512);

// Bad input: the message is one line naming the file and the field, e.g.
// "scenes/a.json: grid.resolution: must be a power of two, got 100".
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& reason)
      : std::runtime_error(printable(file) + ": " + (field.empty() ? "" : printable(field) + ": ") +
                           printable(reason)) {}
};

// Exit codes of the voxgi command (docs/architecture.md, "Command line").
enum ExitCode : int { kExitOk = 0, kExitInternal = 1, kExitBadInput = 2 };

}  // namespace voxgi
