#pragma once
// A small XML well-formedness check for the report's tests: tags nest and match, attributes are
// quoted and unique per element, entities are known. Enough for what the engine writes (no CDATA,
// no processing instructions besides a doctype). Returns "" when well formed, else what is wrong.
#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace dymesh::testing {

inline std::string XmlWellFormedError(const std::string& text) {
  std::vector<std::string> open;
  std::size_t i = 0, n = text.size();
  auto where = [&](std::size_t at) { return " at byte " + std::to_string(at); };
  // an entity starting at text[at] == '&'
  auto entity_ok = [&](std::size_t at) {
    const std::size_t end = text.find(';', at);
    if (end == std::string::npos || end - at > 10) return false;
    const std::string name = text.substr(at + 1, end - at - 1);
    if (name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos") return true;
    return name.size() > 1 && name[0] == '#';
  };
  auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' || c == '.'; };
  while (i < n) {
    // text up to the next tag
    if (text[i] != '<') {
      if (text[i] == '&' && !entity_ok(i)) return "bad entity" + where(i);
      ++i;
      continue;
    }
    // comments and the doctype
    if (text.compare(i, 4, "<!--") == 0) {
      const std::size_t end = text.find("-->", i);
      if (end == std::string::npos) return "unclosed comment" + where(i);
      i = end + 3;
      continue;
    }
    if (text.compare(i, 2, "<!") == 0) {
      const std::size_t end = text.find('>', i);
      if (end == std::string::npos) return "unclosed declaration" + where(i);
      i = end + 1;
      continue;
    }
    // a closing tag must match the innermost open element
    const bool closing = i + 1 < n && text[i + 1] == '/';
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_start = j;
    while (j < n && name_char(text[j])) ++j;
    const std::string name = text.substr(name_start, j - name_start);
    if (name.empty()) return "tag without a name" + where(i);
    if (closing) {
      while (j < n && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j >= n || text[j] != '>') return "bad closing tag </" + name + where(i);
      if (open.empty() || open.back() != name)
        return "</" + name + "> closes <" + (open.empty() ? std::string("nothing") : open.back()) + ">" + where(i);
      open.pop_back();
      i = j + 1;
      continue;
    }
    // attributes: name="value" or name='value', each once
    std::set<std::string> seen;
    for (;;) {
      while (j < n && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j >= n) return "unclosed tag <" + name + where(i);
      if (text[j] == '>' || text.compare(j, 2, "/>") == 0) break;
      const std::size_t a = j;
      while (j < n && name_char(text[j])) ++j;
      const std::string attribute = text.substr(a, j - a);
      if (attribute.empty() || j >= n || text[j] != '=') return "bad attribute in <" + name + ">" + where(a);
      if (!seen.insert(attribute).second) return "duplicate attribute " + attribute + " in <" + name + ">" + where(a);
      const char quote = j + 1 < n ? text[j + 1] : 0;
      if (quote != '"' && quote != '\'') return "unquoted attribute " + attribute + where(a);
      const std::size_t end = text.find(quote, j + 2);
      if (end == std::string::npos) return "unclosed attribute " + attribute + where(a);
      for (std::size_t k = j + 2; k < end; ++k) {
        if (text[k] == '<') return "'<' in attribute " + attribute + where(k);
        if (text[k] == '&' && !entity_ok(k)) return "bad entity in attribute " + attribute + where(k);
      }
      j = end + 1;
    }
    const bool empty = text[j] == '/';
    if (!empty) open.push_back(name);
    i = j + (empty ? 2 : 1);
  }
  if (!open.empty()) return "unclosed <" + open.back() + "> at the end";
  return {};
}

}  // namespace dymesh::testing
