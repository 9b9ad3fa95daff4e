#pragma once
#include <string>
#include <vector>

#include "dymesh/core/scenario.h"

/// Scenario files: JSON in US or SI units, converted to SI and validated at load.
namespace dymesh {

/// Why `path` cannot be read as an input file ("file not found", "a directory, not a file", "a FIFO
/// (named pipe), not a file", a device, a socket), or "" for a regular file. Never opens it (a FIFO
/// would block).
std::string NotARegularFile(const std::string& path);

/// The files `scenario` reads: the scenario file itself, and each body's vehicle file and mesh file.
std::vector<std::string> InputFiles(const Scenario& scenario);

/// Reads and validates a scenario file; mesh paths are resolved against the file's folder.
/// Throws InputError naming the file, the field and what was expected.
Scenario LoadScenario(const std::string& path);

/// Parses scenario JSON text (`file` is used in messages and to resolve relative paths).
Scenario ParseScenario(const std::string& json_text, const std::string& file);

/// Warns of the specified search direction where it cannot serve: with two or more deformable bodies
/// (specified_direction_shared: one body-frame direction serves every body as slave, so where two
/// bodies push back along different lines one sinks into the other), and for a deformable body it does
/// not push back against its initial approach to another body (specified_direction_away: its nodes
/// look past it). A scenario file's parse and a world built from arrays both ask it.
void WarnOfTheSpecifiedDirection(Scenario* scenario);

}  // namespace dymesh
