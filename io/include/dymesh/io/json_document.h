#pragma once
#include <nlohmann/json.hpp>

#include <string>

/// A whole JSON document read strictly, for every input file (scenarios, ensemble specs).
namespace dymesh {

/// Parses `text`; refusals are InputError naming `file`, the field's JSON path and what was wrong: a
/// duplicate key (the JSON library would keep only the last), a number out of range (1e999), or
/// malformed JSON (with its byte offset).
nlohmann::json ParseJsonDocument(const std::string& text, const std::string& file);

}  // namespace dymesh
