#include "dymesh/io/json_document.h"

#include <vector>

#include "dymesh/core/scenario.h"
#include "dymesh/io/printable.h"
#include "json_path.h"

namespace dymesh {
namespace {

using Json = nlohmann::json;

using json_path::At;
using json_path::FieldName;
using json_path::Join;

// a DOM builder that knows the JSON path of every token, so that number overflow (1e999) and
// duplicate keys are reported at their field
class PathTrackingBuilder {
 public:
  explicit PathTrackingBuilder(Json* root) : root_(root) {}

  bool null() { return Place(Json(nullptr)) != nullptr; }
  bool boolean(bool v) { return Place(Json(v)) != nullptr; }
  bool number_integer(Json::number_integer_t v) { return Place(Json(v)) != nullptr; }
  bool number_unsigned(Json::number_unsigned_t v) { return Place(Json(v)) != nullptr; }
  bool number_float(Json::number_float_t v, const std::string&) { return Place(Json(v)) != nullptr; }
  bool string(std::string& v) { return Place(Json(v)) != nullptr; }
  bool binary(Json::binary_t& v) { return Place(Json::binary(v)) != nullptr; }
  bool start_object(std::size_t) { return Open(Json::object()); }
  bool start_array(std::size_t) { return Open(Json::array()); }
  bool end_object() { return Close(); }
  bool end_array() { return Close(); }

  bool key(std::string& k) {
    // refuse duplicate keys (the JSON library would keep only the last one)
    Frame& f = frames_.back();
    if (f.value->contains(k)) {
      f.key = k;
      error_field_ = Path(false);
      error_message_ = "duplicate key \"" + k + "\"";
      return false;
    }
    f.key = k;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& token, const nlohmann::json::exception& ex) {
    // number overflow is a non-finite value at a known field; anything else is malformed JSON
    if (ex.id == 406) {
      error_field_ = Path(true);
      error_message_ = "expected a finite number, got " + token;
      return false;
    }
    std::string what = ex.what();
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    error_field_ = "(json)";
    error_message_ = "malformed JSON at byte " + std::to_string(position) + ": " + what;
    return false;
  }

  const std::string& error_field() const { return error_field_; }
  const std::string& error_message() const { return error_message_; }

 private:
  struct Frame {
    Json* value;
    std::string key;  // current key (objects)
  };

  // the value goes into the open container (or becomes the root)
  Json* Place(Json&& v) {
    if (frames_.empty()) {
      *root_ = std::move(v);
      return root_;
    }
    Frame& f = frames_.back();
    if (f.value->is_array()) {
      f.value->push_back(std::move(v));
      return &f.value->back();
    }
    Json& slot = (*f.value)[f.key];
    slot = std::move(v);
    return &slot;
  }

  bool Open(Json&& container) {
    Json* placed = Place(std::move(container));
    frames_.push_back(Frame{placed, {}});
    return true;
  }

  bool Close() {
    frames_.pop_back();
    return true;
  }

  // JSON path of the value being read (`next`: an array's next element rather than its last)
  std::string Path(bool next) const {
    std::string path;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.value->is_array()) {
        const bool innermost = i + 1 == frames_.size();
        const std::size_t n = f.value->size();
        path = At(path, innermost && next ? n : (n == 0 ? 0 : n - 1));
      } else {
        path = Join(path, f.key);
      }
    }
    return FieldName(path);
  }

  Json* root_;
  std::vector<Frame> frames_;
  std::string error_field_, error_message_;
};

}  // namespace

Json ParseJsonDocument(const std::string& text, const std::string& file) {
  // the JSON library ends the text at a NUL byte: "{...}\0garbage" would read as the object alone
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw InputError(file, "(json)", "malformed JSON at byte " + std::to_string(nul) +
                                         ": a NUL byte; expected JSON text, and nothing after the document");
  Json root;
  PathTrackingBuilder builder(&root);
  const bool ok = Json::sax_parse(text, &builder);
  if (!ok) throw InputError(file, Printable(builder.error_field()), Printable(builder.error_message()));
  return root;
}

}  // namespace dymesh
